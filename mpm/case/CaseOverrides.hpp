#pragma once
// Applying command-line overrides (case/CaseOverride.hpp) to a parsed case file, and writing the
// case as run. Seen only by the schema (CaseLoader.cpp), like everything that includes toml++.
#include <toml++/toml.h>

#include <string>
#include <vector>

#include "case/CaseOverride.hpp"

namespace qs {

/// Where an override landed in the file, for writing the case as run
struct OverrideSite {
    std::string was;                   ///< the replaced value as written in the file; "" if absent
    toml::source_region value;         ///< the replaced value's place in the file (if it was there)
    toml::source_region table;         ///< the header of the table that holds the key
    bool tableWritten = false;         ///< whether that table has a header in the file
    bool tableIsRoot = false;          ///< the key is a top-level key
    std::string newValue;              ///< how the new value is written (a bare word quoted)
    std::string tablePath;             ///< "materials.sand", "layers[0]" (for an appended table)
    std::string key;                   ///< the last name of the key
};

/// Sets each override in `root` (the parsed case file), in order. Throws qs::InputError naming
/// `fileName` and the override if its key cannot be reached: a path through a value that is not a
/// table, an index past the end of an array of tables.
std::vector<OverrideSite> applyOverrides(toml::table& root, const std::vector<CaseOverride>& overrides,
                                         const std::string& fileName);

/// The case as run, as TOML: the file's text with each override's value put in its place (or
/// added under its table) and marked with the value it replaced, headed by a comment listing the
/// overrides. Checked by reading it back against `root`; should the splice not read back the
/// same (a key inside a multi-line string), toml++'s own writing of `root` is used instead.
std::string effectiveCaseText(const std::string& fileText, const toml::table& root,
                              const std::vector<CaseOverride>& overrides, const std::vector<OverrideSite>& sites,
                              const std::string& fileName);

}  // namespace qs
