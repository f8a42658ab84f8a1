#pragma once
// Which nodal velocity components are held, per phase (physics.md section 2, boundaries):
//  - smooth lateral walls: the normal component of both phases (2D/3D);
//  - the filter plane: the solid's vertical component, both ways (the filter also pulls; a one-way
//    support lets the whole bed lift off as a plug near i_c);
//  - the gate plane (chamber bottom): the liquid's vertical component in the flux and closed gate
//    modes (prescribed velocity, or zero); in the pressure mode it carries the gate traction.
//    Through an open gate (pressure or flux) the water enters vertically, as through a perforated
//    plate: its horizontal components are held at zero too. The chamber spreads the water sideways
//    above it. (Left free, the chamber's lowest points drifted sideways between the injection slots
//    in 2D, which then refilled what was not empty: the liquid ledger drifted by 1e-4 of the
//    inflow in 16 s with two gravels side by side; held, it stays within 1e-5.) A closed gate is a
//    smooth wall;
//  - a rigid skeleton: every solid component;
//  - rough walls (column.wall_friction_angle > 0): the grains' tangential components by Coulomb
//    friction, solved with the node (boundary/RoughWalls.hpp).
// Built once; the nodal update reads the flags. Also knows each gate node's share of the area.
#include <vector>

#include "grid/Grid.hpp"
#include "boundary/RoughWalls.hpp"
#include "case/CaseConfig.hpp"

namespace qs {

template <int D>
struct BoundaryMasks {
    std::vector<char> solidFixed;   ///< [node][axis]
    std::vector<char> liquidFixed;  ///< [node][axis]
    std::vector<Index> gateNodes;   ///< the bottom node row (the gate plane)
    std::vector<Index> filterNodes; ///< the node row of the filter plane
    RoughWalls<D> roughWalls;       ///< the lateral walls' friction on the grains (none if smooth)

    void build(const Grid<D>& grid, const CaseConfig& config) {
        const Index nn = grid.numNodes();
        solidFixed.assign(nn * D, 0);
        liquidFixed.assign(nn * D, 0);
        const Index filterRow = static_cast<Index>(std::llround(config.filterLevel() / grid.h()));
        for (Index i = 0; i < nn; ++i) {
            const IVec<D> n = grid.nodeCoords(i);
            for (int d = 0; d < D - 1; ++d) {
                if (n[d] == 0 || n[d] == grid.nodes(d) - 1) {
                    solidFixed[i * D + d] = 1;
                    liquidFixed[i * D + d] = 1;
                }
            }
            if (n[D - 1] == filterRow) {
                solidFixed[i * D + D - 1] = 1;
                filterNodes.push_back(i);
            }
            if (n[D - 1] == 0) {
                gateNodes.push_back(i);
                if (config.gate.mode != GateMode::Pressure) liquidFixed[i * D + D - 1] = 1;
                if (config.gate.mode != GateMode::Closed)
                    for (int d = 0; d < D - 1; ++d) liquidFixed[i * D + d] = 1;
                solidFixed[i * D + D - 1] = 1;
            }
            if (config.initial.rigidSkeleton)
                for (int d = 0; d < D; ++d) solidFixed[i * D + d] = 1;
        }
        roughWalls.build(grid, config);
    }
};

/// m2, the share of a horizontal plane carried by one node of it (Grid::nodeFootprint).
template <int D>
Real nodeFootprint(const Grid<D>& grid, Index node) {
    return grid.nodeFootprint(node);
}

}  // namespace qs
