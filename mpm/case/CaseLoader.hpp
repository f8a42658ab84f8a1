#pragma once
// CaseLoader: reads a case directory's case.toml into a validated CaseConfig.
//
// Usage:
//   qs::CaseConfig config = qs::loadCase("cases/deltaresColumn");   // reads .../case.toml
//   // config is complete: every default filled in, every range and cross-check passed.
//
// Loading has two steps. The schema (CaseLoader.cpp) reads each table and checks each key on its
// own: its type, its range, whether it applies with the choices made elsewhere; the keys, units,
// defaults and ranges are those of docs/case-format.md, and the accepted keys of each table are
// declared once there and drive the unknown-key check ("Did you mean ..."). The rules that relate
// several keys (case/CaseRules.hpp: whole cells, levels, porosity bounds, ...) are checked on the
// loaded values, once the keys they relate are read. The TOML toolkit under the schema is
// case/TomlSection.hpp; only these files see TOML (toml++).
//
// Every problem is reported as qs::InputError naming the file, the line of the offending node
// (for a missing key, the line of the table that should hold it), the full dotted key
// (e.g. "materials.sand.porosity", "layers[1].thickness"), the bad value and what is expected.
// Loading stops at the first problem.
#include <string>
#include <vector>

#include "case/CaseConfig.hpp"

namespace qs {

/// Reads CASE_DIR/case.toml, validates it completely and returns the config. Throws qs::InputError
/// naming file, line, full dotted key (e.g. "materials.sand.porosity") and expected value.
/// config.caseDirectory is set to `caseDirectory` as given.
/// With `overrides` (--set KEY=VALUE) applied to the file before validation: an override is
/// checked exactly like the key in the file, and an error it causes names it (case/CaseOverride.hpp).
CaseConfig loadCase(const std::string& caseDirectory, const std::vector<CaseOverride>& overrides = {});

/// Same, from a TOML string (for tests); `fileName` is used in messages. Relative paths in the
/// case (reservoir.openfoam_case) are resolved against `caseDirectory`.
CaseConfig parseCase(const std::string& tomlText, const std::string& fileName,
                     const std::string& caseDirectory = ".", const std::vector<CaseOverride>& overrides = {});

}  // namespace qs
