#pragma once
// LiquidPoints<D>: the pore-water material points, as a structure of arrays.
//
// A liquid point has a constant liquid mass m_L and stands for a mixture volume V: inside the sand
// m_L = n rho_L V, in free water m_L = rho_L V. V follows the liquid's own strain,
// V <- V (1 + d eps_L), which keeps that relation as the point moves between sand and free water.
// Pore pressure p is gauge, compression positive. The water's state is a cell's (one pressure
// and gradient, or one cavity, per cell each step, physics.md section 2); each point holds its
// cell's field where it stands, p_c + grad p_c . (x - x_c), so that the state moves with the
// liquid into the next step's cells. That is an extrapolation of the cell's field: a point's
// pressure can sit below the cavitation limit; the cells' water never does.
// Below the cavitation limit the water takes no more tension: what it expands further is a
// cavity (vapour, released air), a volumetric strain of the water the point carries and that a
// compression closes at the limit's pressure before the water is pressed again.
#include <vector>

#include "points/PointSet.hpp"

namespace qs {

enum LiquidFlags : int { kSubmergedLiquid = 0, kFreeSurfaceLiquid = 1 };

template <int D>
struct LiquidPoints {
    std::vector<Real> x;          ///< m, position [point][axis]
    std::vector<Real> v;          ///< m/s, velocity [point][axis]
    std::vector<Real> mass;       ///< kg, liquid mass (constant)
    std::vector<Real> volume;     ///< m3, mixture volume V
    std::vector<Real> pressure;   ///< Pa, pore pressure (gauge, compression positive)
    std::vector<int> state;       ///< LiquidFlags, set each step
    std::vector<Real> cavity;     ///< -, the water's volumetric strain opened at the cavitation limit (>= 0)

    ShapeCache<D> shape;          ///< per-step scratch
    std::vector<Real> weight;     ///< m3, integration weight V* (per step, see the solver)
    Real halfLength = 0;          ///< m, uGIMP particle half-length

    std::size_t size() const { return mass.size(); }

    /// The registry of the liquid points' persistent fields (points/PointSet.hpp). The order is
    /// that of checkpoints written before the registry (liquid_field0 to liquid_field6).
    template <class F>
    void forEachField(F&& f) { fields(*this, f); }
    template <class F>
    void forEachField(F&& f) const { fields(*this, f); }

private:
    template <class Self, class F>
    static void fields(Self& p, F& f) {
        f(p.x, FieldSpec{"position", D});
        f(p.v, FieldSpec{"velocity", D, true, true});
        f(p.mass, FieldSpec{"mass", 1, true});
        f(p.volume, FieldSpec{"volume", 1, true});
        f(p.pressure, FieldSpec{"pore_pressure", 1, true});
        f(p.state, FieldSpec{"state", 1, true});
        f(p.cavity, FieldSpec{"cavity", 1, true, false, "2026-12-04"});
    }
};

}  // namespace qs
