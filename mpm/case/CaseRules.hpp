#pragma once
// CaseRules: the physics rules that relate several keys of a case, checked on the loaded
// CaseConfig once the schema (case/CaseLoader.cpp) has read the keys concerned and checked each on
// its own (type, range, whether it applies with the choices made elsewhere). Two groups:
//  - the geometry: the grid's width, every layer, the chamber and the grid's top are whole
//    numbers of cells, the chamber at least one; the water starts at or above the sand top, the
//    overflow at or above the water, and the grid's top above both;
//  - the initial state: n_min <= n0 < n_max for every material (n0 >= n_max only for a bed that
//    starts fluidised); an undrained start needs a surcharge; zones side by side start at rest.
//
// The messages name the file, line and dotted key exactly as the schema's do: the loader records
// where every key was written (KeyLocations), and a rule reports at the key it blames (at its
// table's line when that key took its default). loadCase runs both groups, so `quicksand check`,
// `quicksand run` and every other caller of loadCase refuse the same cases.
//
// Rules that need more than the loaded values stay in the schema, which says why beside each:
// those that decide which keys are read at all (zones need grid.dimension = 2 or 3; a fluidised
// start takes no effective stress; gate.flux only with mode = "flux"; [reservoir] needed by a
// pressure gate; [coupling] only with OpenFOAM), bounds that one key sets for another's range
// (dilatancy_angle <= friction_angle, a monitor within column.top, a zone within grid.width),
// unique monitor names (the message quotes the line of the first) and names of materials.
#include "case/CaseConfig.hpp"
#include "case/KeyLocations.hpp"

namespace qs {

/// Throws qs::InputError, placed with `where` (the positions the loader recorded), at the first
/// geometry rule `config` breaks: needs [grid], [[layers]] and [column].
void validateGeometry(const CaseConfig& config, const KeyLocations& where);

/// Throws qs::InputError at the first initial-state rule `config` breaks: needs [materials],
/// [[layers]], [loads] and [initial].
void validateInitialState(const CaseConfig& config, const KeyLocations& where);

}  // namespace qs
