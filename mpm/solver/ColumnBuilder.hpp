#pragma once
// Builds the initial material points of a column case (physics.md sections 1-2):
//  - solid points, solid_per_cell per axis in every sand cell, m_s = (1 - n0) rho_s V;
//    effective stress by the K0 procedure (sigma'_v from the buoyant weight above, sigma'_h =
//    K0 sigma'_v), or zero; optionally the undrained state under a surcharge;
//  - liquid points, liquid_per_cell per axis in sand cells (m_L = n rho_L V), and in free water
//    (chamber, water above the sand) smaller points of V = n_min V_cell / liquid_per_cell^D along
//    the vertical, so that water entering the sand does not leave sand cells empty;
//  - hydrostatic pore pressure below the initial water level.
#include <functional>
#include <vector>

#include "grid/Grid.hpp"
#include "case/CaseConfig.hpp"
#include "points/LiquidPoints.hpp"
#include "points/SolidPoints.hpp"

namespace qs {

struct SolidMaterial;

/// `keep`, when given, says which points to make (by position): over MPI ranks a rank makes
/// only its block's, in the order one rank makes them (a random field's porosity, its costliest
/// part, is not evaluated for the others' points).
template <int D>
void buildColumn(const CaseConfig& config, const Grid<D>& grid,
                 const std::vector<SolidMaterial>& materials, SolidPoints<D>& solid,
                 LiquidPoints<D>& liquid, const std::function<bool(const Real* x)>& keep = {});

/// Vertical count of free-water liquid points per cell: ceil(liquid_per_cell / n_min).
int freeWaterPointsPerCell(const CaseConfig& config);

}  // namespace qs
