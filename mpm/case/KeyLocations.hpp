#pragma once
// KeyLocations: where each table and key of an input file was written. The reader records them
// as it goes (case/TomlSection); they outlive the parsed file, so that a rule checked on the values
// afterwards (case/CaseRules) reports its problem at the same file, line and dotted key as a check
// made while reading would.
//
//   const KeyLocations::Table column = where.table("column");
//   if (!(c.column.top > c.column.waterLevel)) column.fail("top", "top = ... is not above ...");
//       // -> case.toml:16: key 'column.top': top = ... is not above ...
//
// Where a problem is placed: at the key's line if it was written; else (its default was taken)
// at the line of its table; an absent table is placed where the reader would report it missing.
#include <map>
#include <string>
#include <string_view>
#include <utility>

namespace qs {

class KeyLocations {
public:
    explicit KeyLocations(std::string file) : file_(std::move(file)) {}
    const std::string& file() const { return file_; }

    /// Records a table by its dotted path ("" is the top level; "materials.sand", "layers[1]").
    void addTable(const std::string& path, int line);
    /// Records a key written in the table at `path` (line 0: position unknown).
    void addKey(const std::string& path, std::string_view key, int line);

    /// One recorded table, as a check on the loaded values sees it.
    class Table {
    public:
        const std::string& path() const { return path_; }
        int line() const { return line_; }
        /// True if the key was written in the file (false: its default was taken).
        bool has(std::string_view key) const;
        /// The key's line, or the table's if the key was not written.
        int lineOf(std::string_view key) const;
        /// The full dotted key: "column.top", "layers[1].thickness", "gravity".
        std::string keyPath(std::string_view key) const;
        /// Throws qs::InputError naming the file, lineOf(key), keyPath(key) and `what`.
        [[noreturn]] void fail(std::string_view key, const std::string& what) const;

    private:
        friend class KeyLocations;
        Table(const KeyLocations& all, std::string path, int line)
            : all_(&all), path_(std::move(path)), line_(line) {}
        const KeyLocations* all_;
        std::string path_;
        int line_;
    };

    /// The table at `path`, which must have been recorded.
    Table table(const std::string& path) const;

private:
    std::string file_;
    std::map<std::string, int> tableLines_;
    std::map<std::pair<std::string, std::string>, int> keyLines_;  ///< by (table path, key)
};

}  // namespace qs
