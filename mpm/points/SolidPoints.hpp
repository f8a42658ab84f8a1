#pragma once
// SolidPoints<D>: the solid material points (the sand skeleton), as a structure of arrays.
//
// Each point carries a constant solid mass m_s = (1 - n0) rho_s V0 and stands for a mixture
// volume V that follows the solid's volumetric strain; its porosity follows from solid mass
// balance, (1 - n_new) = (1 - n_old) / (1 + d eps_vol) (physics.md section 2).
// Effective stress is a full 3D tensor in Voigt order xx, yy, zz, yz, xz, xy (tension positive)
// whatever D is: a 1D column is oedometric, a 2D grid plane strain.
#include <vector>

#include "points/PointSet.hpp"

namespace qs {

enum PointState : int { kSolidState = 0, kFluidisedState = 1 };

template <int D>
struct SolidPoints {
    std::vector<Real> x;          ///< m, position [point][axis]
    std::vector<Real> v;          ///< m/s, velocity [point][axis]
    std::vector<Real> mass;       ///< kg, solid mass (constant)
    std::vector<Real> volume;     ///< m3, mixture volume the point stands for
    std::vector<Real> porosity;   ///< -, n
    std::vector<Real> stress;     ///< Pa, effective stress [point][6], tension positive
    std::vector<int> state;       ///< PointState
    std::vector<int> material;    ///< index into the solver's material table
    std::vector<Real> internal;   ///< constitutive state variables [point][internalCount]
    std::vector<Real> velocityGradient;  ///< 1/s, C = grad v at the point [point][D*D] (APIC)

    ShapeCache<D> shape;          ///< per-step scratch, not part of the state
    std::vector<int> stressReturn;  ///< per-step scratch: the StressReturn of the last update
    int internalCount = 0;        ///< state variables per point (the most any material needs)
    Real halfLength = 0;          ///< m, uGIMP particle half-length (from the initial spacing)

    std::size_t size() const { return mass.size(); }

    /// The index of velocityGradient among forEachField's fields: checkpoints written before it
    /// existed (2026-12-02) have none (solver/SolverCheckpoint.cpp)
    static constexpr int kVelocityGradientField = 9;

    template <class F>
    void forEachField(F&& f) {
        f(x, D); f(v, D); f(mass, 1); f(volume, 1); f(porosity, 1); f(stress, 6);
        f(state, 1); f(material, 1); f(internal, internalCount); f(velocityGradient, D * D);
    }
};

}  // namespace qs
