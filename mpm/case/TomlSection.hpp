#pragma once
// Reading TOML with checks: the toolkit under the case schema (case/CaseLoader.cpp). It knows TOML
// and how to report a problem in it, and nothing of quicksand's keys:
//  - TableKeys: the keys one table accepts. Any other key is an error that suggests the nearest
//    accepted key ("Did you mean 'porosity'?") or names the table where it belongs.
//  - Section: one table being read, named by its dotted path, with typed look-ups: a number in a
//    Range, an integer, a boolean, a string, one of a list of Options. Each throws qs::InputError
//    naming the file, the line of the offending value (for a missing key, the line of its table),
//    the full dotted key, the value found and what is expected.
//  - Every table and key a Section meets is recorded in a KeyLocations, so that rules checked on
//    the values after reading (case/CaseRules) place their messages the same way.
//
//   KeyLocations where("case.toml");
//   const Section root(parsedFile, kRootKeys, kAllTables, where);
//   const Section grid = root.subsection("grid", kGridKeys, /*required=*/true);
//   const double h = grid.requiredNumber("cell_size", positive("m"), "edge of a grid cell");
//
// Only the schema and this toolkit include toml++.
#include <toml++/toml.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "case/KeyLocations.hpp"
#include "case/MessageText.hpp"
#include "case/Range.hpp"

namespace qs {

/// The accepted keys of one table; `title` is how messages name the table ("[grid]",
/// "[[layers]]", "the top level").
struct TableKeys {
    const char* title;
    const char* const* first;
    const char* const* last;
    bool contains(std::string_view key) const {
        return std::any_of(first, last, [&](const char* k) { return key == k; });
    }
};

template <std::size_t N>
constexpr TableKeys tableKeys(const char* title, const char* const (&keys)[N]) {
    return {title, keys, keys + N};
}

/// Every table of a file format: where the unknown-key check looks for a misplaced key's table.
using TableCatalogue = std::vector<const TableKeys*>;

/// The strings a choice accepts and the value each stands for.
template <class E>
using Options = std::vector<std::pair<std::string, E>>;

/// How `value` is written in the file, in quotes ("\"pressure\""); "?" if it has no name.
template <class E>
std::string nameOf(const Options<E>& options, E value) {
    for (const auto& o : options)
        if (o.second == value) return inQuotes(o.first);
    return "?";
}

/// "a string \"abc\"", "an integer 5", ...: how a value the user wrote is named in messages.
std::string describe(const toml::node& node);

/// The 1-based line of a node (0 if toml++ does not know it).
int lineOfNode(const toml::node& node);

class Section {
public:
    /// The top level of a parsed file. `format` lists every table of the file's format; `where`
    /// names the file in messages and records every table and key read. Both, and the parsed
    /// file, must outlive this Section and those made from it. Checks for unknown keys at once,
    /// as every Section does.
    Section(const toml::table& root, const TableKeys& keys, const TableCatalogue& format, KeyLocations& where);

    const std::string& path() const { return path_; }
    int line() const { return line_; }
    std::string keyPath(std::string_view key) const;
    /// The value under `key`, or null; `key` must be one of the table's accepted keys.
    const toml::node* find(std::string_view key) const;
    bool has(std::string_view key) const { return find(key) != nullptr; }
    /// The line of `key`'s value, or the table's line if it is absent.
    int lineOf(std::string_view key) const;

    /// Reports a problem with `key` (at its line if given, else at the table's line).
    [[noreturn]] void fail(std::string_view key, const std::string& what) const;
    [[noreturn]] void missing(std::string_view key, const std::string& expected) const;
    /// A key that is valid in this table but has no meaning with the choices made elsewhere.
    void forbid(std::string_view key, const std::string& why) const;

    std::optional<double> optionalNumber(std::string_view key, const Range& range,
                                         const std::string& hint = "") const;
    double optionalNumber(std::string_view key, double fallback, const Range& range,
                          const std::string& hint = "") const {
        return optionalNumber(key, range, hint).value_or(fallback);
    }
    double requiredNumber(std::string_view key, const Range& range, const std::string& hint = "") const;
    int integer(std::string_view key, int fallback, const Range& range) const;
    bool boolean(std::string_view key, bool fallback) const;
    std::optional<std::string> optionalString(std::string_view key, bool allowEmpty = false) const;
    std::string string(std::string_view key, const std::string& fallback, bool allowEmpty = false) const {
        return optionalString(key, allowEmpty).value_or(fallback);
    }
    std::string requiredString(std::string_view key, const std::string& expected) const;

    /// A string naming one of `options`; unknown strings list the allowed ones.
    template <class E>
    E choice(std::string_view key, E fallback, const Options<E>& options) const {
        if (!has(key)) return fallback;
        return requiredChoice(key, options);
    }
    template <class E>
    E requiredChoice(std::string_view key, const Options<E>& options) const {
        std::vector<std::string> names;
        for (const auto& o : options) names.push_back(o.first);
        return options[requiredChoiceIndex(key, names)].second;
    }

    /// The sub-table under `key` (an absent one, whose reads all give their defaults, if it is
    /// not there and not required).
    Section subsection(std::string_view key, const TableKeys& keys, bool required) const;
    /// A table the schema found itself under this one (e.g. each of a table of named tables).
    Section child(const toml::table& table, std::string path, const TableKeys& keys, int fallbackLine) const;

    /// The array of tables under `key` ([[key]] entries), each checked to be a table; null if
    /// absent and not required.
    const toml::array* arrayOfTables(std::string_view key, bool required) const;
    /// Entry `index` of the array of tables under `key`, named "key[index]" (after arrayOfTables).
    Section entry(std::string_view key, std::size_t index, const TableKeys& keys) const;

    /// "[grid]", "[layers[0]]", "the top level".
    std::string tableName() const { return path_.empty() ? "the top level" : "[" + path_ + "]"; }

private:
    /// `table` may be null (an optional table that is absent): every read then gives its default
    /// and a required key is reported missing at `fallbackLine`.
    Section(const TableCatalogue& format, KeyLocations& where, const toml::table* table, std::string path,
            const TableKeys& keys, int fallbackLine);
    /// Throws at the first key the table does not accept.
    void checkKeys() const;
    /// Which of `names` the string under `key` is (else the error lists them).
    std::size_t requiredChoiceIndex(std::string_view key, const std::vector<std::string>& names) const;

    const TableCatalogue* format_;
    KeyLocations* where_;
    const toml::table* table_;
    std::string path_;
    const TableKeys* keys_;
    int line_;
};

}  // namespace qs
