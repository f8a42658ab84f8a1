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

    /// The registry of the solid points' persistent fields (points/PointSet.hpp): names, in the
    /// checkpoint and fields.h5, and components. The order is that of checkpoints written before
    /// the registry, whose entries were numbered solid_field0 to solid_field9.
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
        f(p.porosity, FieldSpec{"porosity", 1, true});
        f(p.stress, FieldSpec{"effective_stress", 6, true});
        f(p.state, FieldSpec{"state", 1, true});
        f(p.material, FieldSpec{"material", 1});
        // Mohr-Coulomb: equivalent plastic strain, plastic volumetric strain
        f(p.internal, FieldSpec{"state_variables", p.internalCount, p.internalCount > 0});
        // APIC's C; an older checkpoint's points start with C = 0, a PIC transfer for their first step
        f(p.velocityGradient, FieldSpec{"velocity_gradient", D * D, false, false, "2026-12-02"});
    }
};

}  // namespace qs
