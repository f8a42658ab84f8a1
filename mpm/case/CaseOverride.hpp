#pragma once
// Overrides of a case's keys from the command line: `quicksand run CASE --set reservoir.area=0.02`.
//
// An override replaces (or adds) one value in the parsed case.toml before the schema reads it, so
// it is validated exactly like the key written in the file; a problem with it is reported as
// "CASE/case.toml, --set KEY=VALUE: key 'KEY': ..." (CaseLoader.cpp).
//
// KEY is the dotted key of the error messages and docs/case-format.md:
//   time.end, reservoir.area            a key of a table
//   materials.sand.porosity             a key of a named table
//   layers[1].thickness                 a key of an array of tables (0-based, must exist)
//   initial.porosity_field.seed         a key of a sub-table (made if the file has none)
// VALUE is a TOML value (50, 1.5e-10, true, "lumped", [1, 2], { mode = "constant", value = 1e-10 });
// a bare word that is not one (lumped, smooth_pipe) is taken as a string.
//
//   std::vector<CaseOverride> o = {parseOverride("time.end=50")};
//   CaseConfig c = loadCase("cases/deltaresColumn", o);
//   // c.effectiveCase: the case as run, each overridden key marked
#include <string>

namespace qs {

struct CaseOverride {
    std::string key;    ///< dotted, as in the messages: "layers[1].thickness"
    std::string value;  ///< as written after '='
    /// "--set KEY=VALUE", how messages name it
    std::string text() const { return "--set " + key + "=" + value; }
};

/// Splits "KEY=VALUE". Throws qs::Error naming the argument if there is no '=' or no key.
CaseOverride parseOverride(const std::string& argument);

}  // namespace qs
