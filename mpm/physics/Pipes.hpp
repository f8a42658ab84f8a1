#pragma once
// Pipes: localised fluidisation, found on the grid's cells (docs/fluidisation.md, "Pipes").
//
// The reference column did not fluidise evenly: it piped. A pipe is what the lab saw, a fluidised
// channel rising from the filter through sand that stays solid beside it. On the grid:
//   - a cell is fluidised, solid, or holds no sand (the liquid-state switch's per-cell state);
//   - a cell is open when it is fluidised or a pocket of water: no sand, at or above the filter,
//     under its column's sand surface and under sand of the bed (sand connected to the grid's
//     lowest sand) in its column: the foot of a pipe that has emptied its base. Free water under
//     sand afloat apart from the bed is not a pocket;
//   - a fluidised region is a set of open cells connected through their faces (4 neighbours in
//     2D, 6 in 3D; cells touching only at an edge or a corner are not connected), at least one of
//     them fluidised (a pocket alone is a cavity under solid sand);
//   - a region is a pipe when
//       1. it rises from the filter: one of its cells is in the base row (the cells on the filter),
//       2. it is localised: the base row still holds solid sand (a region spanning the whole base
//          is a fluidised bed with a front, measured by series.csv's fluidised_front instead),
//       3. it rises: it is at least kMinimumRows cells tall (a flat patch on the filter is not a
//          channel).
// What is measured of each pipe:
//   x, y        m, the centroid of its cells, each cell counted once (in axisymmetry x is a radius,
//               not weighted by it: a region off the axis is a ring, not a pipe)
//   width       m, its mean horizontal extent: cells / rows x h in 2D (in axisymmetry a radial
//               thickness); in 3D the diameter of the circle of its mean cross-section,
//               sqrt(4 cells h^2 / (pi rows))
//   height      m, the top of its highest cell above the filter
//   wall        whether a cell of it lies against a side wall (the axis of an axisymmetric grid
//               is not a wall)
//   flux share  the share of the water crossing the filter plane that enters through its base
//               cells
// and of the whole bed, the share entering through every open base cell (pipe or not).
#include <cstdint>
#include <vector>

#include "core/Types.hpp"

namespace qs {

/// The sand's state in one grid cell.
enum class CellSand : std::int8_t { None = 0, Solid = 1, Fluidised = 2 };

/// The grid's cells as the pipe measurement reads them: lexicographic, axis 0 fastest, the last
/// axis vertical (as Grid<D>): in 2D cells[1] is the vertical axis and cells[2] is not used.
struct SandCells {
    int dimension = 2;               ///< 2 or 3
    Index cells[3] = {1, 1, 1};      ///< cells per axis
    Real h = 0;                      ///< m, cell edge
    Real filterLevel = 0;            ///< m, the filter plane (the base row's lower face)
    Index baseRow = 0;               ///< the row of cells on the filter
    bool axisymmetric = false;       ///< axis 0 is the radius; its low side is the axis, not a wall
    std::vector<CellSand> state;     ///< per cell
    std::vector<Real> porosity;      ///< per cell, the sand's porosity (NaN where no sand)
    std::vector<Real> baseFlux;      ///< m3/s, per column of cells: water crossing the filter plane
    std::vector<Real> surface;       ///< m, per column of cells: the top of its sand (NaN: none; empty: no pockets)

    Index columns() const { return dimension == 3 ? cells[0] * cells[1] : cells[0]; }
    Index rows() const { return cells[dimension - 1]; }
    Index cell(Index column, Index row) const { return row * columns() + column; }
};

struct Pipe {
    Real x = 0, y = 0;       ///< m, centroid of its cells
    Real width = 0;          ///< m
    Real height = 0;         ///< m above the filter
    bool wall = false;       ///< touches a side wall
    Real fluxShare = 0;      ///< -, of the water crossing the filter plane
    Index cellCount = 0;
};

struct PipeSurvey {
    std::vector<Pipe> pipes;        ///< largest flux share first
    Real fluidisedFluxShare = 0;    ///< -, through the base cells of open regions holding fluidised sand
};

/// Shortest pipe, in cells.
constexpr Index kMinimumPipeRows = 2;

/// Finds the pipes of a cell state. Deterministic; allocates (called at output times only).
PipeSurvey findPipes(const SandCells& cells);

}  // namespace qs
