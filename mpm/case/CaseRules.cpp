#include "case/CaseRules.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

#include "case/MessageText.hpp"

namespace qs {

namespace {

/// Relative tolerance of the "whole number of cells" and level comparisons: levels are sums of
/// decimal thicknesses (0.1 + 0.2 is not 0.3 in binary).
constexpr double kGeometryTolerance = 1e-9;

using Table = KeyLocations::Table;

/// True if a >= b up to the relative geometry tolerance.
bool atLeast(double a, double b) {
    return a >= b - kGeometryTolerance * std::max({1e-300, std::abs(a), std::abs(b)});
}
/// True if a > b by more than the relative geometry tolerance.
bool above(double a, double b) {
    return a > b + kGeometryTolerance * std::max({1e-300, std::abs(a), std::abs(b)});
}

/// Throws unless `length` is a whole number (>= 1) of cells of size h: the grid's lines must fall
/// on the filter, on every layer's boundary and on the grid's top.
void requireWholeCells(const Table& s, std::string_view key, double length, double h) {
    const double cells = length / h;
    const double n = std::round(cells);
    if (n >= 1.0 && std::abs(cells - n) <= kGeometryTolerance * cells) return;
    const double fewer = std::floor(cells) * h, more = std::ceil(cells) * h;
    s.fail(key, number(length) + " m is not a whole number of cells: with grid.cell_size = " + number(h) +
                    " m it spans " + number(cells) + " cells; use a multiple of the cell size, e.g. " +
                    (fewer > 0.0 ? number(fewer) + " m or " : "") + number(more) + " m");
}

void checkGridWidth(const CaseConfig& c, const KeyLocations& where) {
    if (c.grid.dimension >= 2) requireWholeCells(where.table("grid"), "width", c.grid.width, c.grid.cellSize);
}

void checkLayerThicknesses(const CaseConfig& c, const KeyLocations& where) {
    for (std::size_t i = 0; i < c.layers.size(); ++i)
        requireWholeCells(where.table("layers[" + std::to_string(i) + "]"), "thickness", c.layers[i].thickness,
                          c.grid.cellSize);
}

/// Bottom to top: gate (z = 0), chamber, filter, layers, sand top <= water <= overflow < top.
void checkColumnLevels(const CaseConfig& c, const KeyLocations& where) {
    const Table s = where.table("column");
    const ColumnConfig& col = c.column;
    const double h = c.grid.cellSize;
    if (!atLeast(col.chamberHeight, h))
        s.fail("chamber_height", "chamber_height = " + number(col.chamberHeight) +
                                     " m is less than one cell (grid.cell_size = " + number(h) +
                                     " m): the chamber needs at least one cell");
    requireWholeCells(s, "chamber_height", col.chamberHeight, h);

    const double sandTop = c.sandTop();
    const std::string sandTopText = "the sand top at " + number(sandTop) + " m (chamber_height " +
                                    number(col.chamberHeight) + " m + layers " +
                                    number(sandTop - col.chamberHeight) + " m)";
    if (!atLeast(col.waterLevel, sandTop))
        s.fail("water_level", "water_level = " + number(col.waterLevel) + " m is below " + sandTopText +
                                  "; the bed must start submerged: use water_level >= " + number(sandTop) +
                                  " m, or omit it (default: the sand top)");
    // The overflow holds the water's surface at its level, a node row: the water's top cells
    // count as full there (solver/PointsToGrid.cpp), so the water must stand at the overflow from
    // the start, and the level must fall on the grid's lines
    if (col.overflowLevel && (!atLeast(*col.overflowLevel, col.waterLevel) || above(*col.overflowLevel, col.waterLevel)))
        s.fail("overflow_level", "overflow_level = " + number(*col.overflowLevel) + " m differs from water_level = " +
                                     number(col.waterLevel) + " m" +
                                     (s.has("water_level") ? "" : " (the default: sand top)") +
                                     "; the overflow holds the water's surface at its level, so the column starts "
                                     "full to it: expected overflow_level = water_level");
    if (col.overflowLevel) requireWholeCells(s, "overflow_level", *col.overflowLevel, h);
    if (!above(col.top, col.waterLevel))
        s.fail("top", "top = " + number(col.top) + " m is not above water_level = " + number(col.waterLevel) +
                          " m; the grid must reach above the free surface");
    if (col.overflowLevel && !above(col.top, *col.overflowLevel))
        s.fail("top", "top = " + number(col.top) + " m is not above overflow_level = " +
                          number(*col.overflowLevel) + " m; the grid must reach above the overflow");
    requireWholeCells(s, "top", col.top, h);
}

/// n0 < n_max: at n_max the sand switches to the liquid state, where only a bed meant to start
/// fluidised may begin. n_min <= n0: n_min is the densest packing (docs/case-format.md), which a
/// bed cannot start beyond.
void checkPorosityBounds(const CaseConfig& c, const KeyLocations& where) {
    for (const MaterialConfig& m : c.materials) {
        const Table s = where.table("materials." + m.name);
        if (!(m.maxPorosity > m.porosity) && c.initial.state != InitialState::Fluidised) {
            const bool given = s.has("max_porosity");
            s.fail(given ? "max_porosity" : "porosity",
                   "n0 = " + number(m.porosity) + " >= n_max = " + number(m.maxPorosity) +
                       (given ? "" : " (the default)") +
                       ": porosity must be below max_porosity, or the sand starts in the liquid "
                       "state; lower porosity, set max_porosity in (porosity, 1), or start a "
                       "fluidised bed with initial.state = \"fluidised\"");
        }
        if (m.minPorosity > m.porosity) {
            const bool given = s.has("min_porosity");
            s.fail(given ? "min_porosity" : "porosity",
                   "n_min = " + number(m.minPorosity) + (given ? "" : " (the default)") + " > n0 = " +
                       number(m.porosity) + ": min_porosity must be in (0, porosity]; set min_porosity <= porosity");
        }
    }
}

/// The starts the initial state is built for: an undrained response needs a load to respond to.
void checkStartingState(const CaseConfig& c, const KeyLocations& where) {
    const Table s = where.table("initial");
    const InitialConfig& i = c.initial;
    if (i.undrainedSurcharge && !(c.loads.surcharge > 0.0))
        s.fail("undrained_surcharge", "undrained_surcharge = true needs a surcharge, but loads.surcharge is " +
                                          number(c.loads.surcharge) +
                                          " Pa; set loads.surcharge > 0 or remove this key");
    // Zones side by side start from a state built column by column: right at rest under
    // hydrostatic water, not yet for the starts that need one flux per zone from a shared
    // chamber and top (a seepage or fluidised start) or one undrained response
    const bool zones = std::any_of(c.layers.begin(), c.layers.end(),
                                   [](const LayerConfig& l) { return !l.zones.empty(); });
    if (zones) {
        const std::string why = "the layers have [[layers.zones]], whose initial state is built only at rest "
                                "so far (a start that needs one flux or undrained response per zone is not)";
        if (i.filterVelocity != 0.0) s.fail("filter_velocity", "filter_velocity must be 0 here: " + why);
        if (i.undrainedSurcharge) s.fail("undrained_surcharge", "undrained_surcharge must be false here: " + why);
        if (i.state == InitialState::Fluidised) s.fail("state", "state must be \"solid\" here: " + why);
    }
}

/// The overflow holds the water's surface at its level (solver/PointsToGrid.cpp): a reservoir
/// whose head starts below it would drain the column below the overflow, where that no longer
/// holds. (During a run the solver stops, saying so, if the water falls half a cell below it.)
void checkHeadAgainstOverflow(const CaseConfig& c, const KeyLocations& where) {
    if (!c.column.overflowLevel || c.gate.mode != GateMode::Pressure) return;
    if (!atLeast(c.reservoir.head, *c.column.overflowLevel))
        where.table("reservoir").fail("head", "head = " + number(c.reservoir.head) + " m is below the overflow level " +
                                                   "column.overflow_level = " + number(*c.column.overflowLevel) +
                                                   " m: the column would drain below the overflow, which holds the "
                                                   "water's surface at its level; expected head >= overflow_level");
}

/// Axisymmetric grids integrate over the rings with the rule the points do, m points across a
/// cell (grid/Grid.hpp): one rule for both phases, and for linear shape functions (uGIMP spreads
/// each point over its own domain, another rule)
void checkAxisymmetricRules(const CaseConfig& c, const KeyLocations& where) {
    if (c.grid.geometry != GridGeometry::Axisymmetric) return;
    const Table s = where.table("grid");
    if (c.grid.shapeFunctions != ShapeFunctionKind::Linear)
        s.fail("geometry", "geometry = \"axisymmetric\" needs shape_functions = \"linear\": its rings are integrated "
                           "the way linear points integrate them (grid/Grid.hpp), which uGIMP does not");
    if (c.points.solidPerCell != c.points.liquidPerCell)
        s.fail("geometry", "geometry = \"axisymmetric\" needs as many liquid as solid points per cell and axis "
                           "(points.solid_per_cell = " + std::to_string(c.points.solidPerCell) +
                               ", points.liquid_per_cell = " + std::to_string(c.points.liquidPerCell) +
                               "): the grid integrates over the rings with the points' rule, one for both phases");
}

}  // namespace

void validateGeometry(const CaseConfig& config, const KeyLocations& where) {
    checkGridWidth(config, where);
    checkLayerThicknesses(config, where);
    checkColumnLevels(config, where);
}

void validateInitialState(const CaseConfig& config, const KeyLocations& where) {
    checkPorosityBounds(config, where);
    checkStartingState(config, where);
    checkHeadAgainstOverflow(config, where);
    checkAxisymmetricRules(config, where);
}

}  // namespace qs
