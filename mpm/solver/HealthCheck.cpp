// After every step: is the state still a solution? A non-finite value, a point faster than a
// cell per step (the explicit step can no longer follow it), a porosity outside (0, 1), or a
// point pressed against the grid's edge stops the run where it starts, with what, where and
// when, and what to try. One parallel OR per point set; the details are looked for only once
// something is wrong.
#include <cmath>
#include <sstream>

#include "solver/DoublePointSolver.hpp"
#include "solver/Parallel.hpp"

namespace qs {

namespace {

template <int D>
bool finiteAll(const Real* a, int n) {
    for (int k = 0; k < n; ++k)
        if (!std::isfinite(a[k])) return false;
    return true;
}

}  // namespace

template <int D>
void DoublePointSolver<D>::checkHealth() const {
    const Real fastest = grid_.h() / dt_;  // m/s: one cell per step
    const Real top = grid_.cells(D - 1) * grid_.h();
    auto speed = [&](const Real* v) {
        Real s = 0;
        for (int d = 0; d < D; ++d) s = std::max(s, std::abs(v[d]));
        return s;
    };
    auto solidProblem = [&](Index p) -> const char* {
        if (!finiteAll<D>(&solid_.x[p * D], D) || !finiteAll<D>(&solid_.v[p * D], D) ||
            !finiteAll<D>(&solid_.stress[p * 6], 6) || !std::isfinite(solid_.porosity[p]) ||
            !finiteAll<D>(&solid_.velocityGradient[p * D * D], D * D))
            return "a non-finite position, velocity, velocity gradient, stress or porosity";
        if (speed(&solid_.v[p * D]) >= fastest) return "a velocity of more than a cell per step";
        if (!(solid_.porosity[p] > 0 && solid_.porosity[p] < 1)) return "a porosity outside (0, 1)";
        if (solid_.x[p * D + D - 1] >= top) return "reached the top of the grid";
        return nullptr;
    };
    auto liquidProblem = [&](Index p) -> const char* {
        if (!finiteAll<D>(&liquid_.x[p * D], D) || !finiteAll<D>(&liquid_.v[p * D], D) ||
            !std::isfinite(liquid_.pressure[p]))
            return "a non-finite position, velocity or pressure";
        if (speed(&liquid_.v[p * D]) >= fastest) return "a velocity of more than a cell per step";
        return nullptr;
    };
    const Index ns = static_cast<Index>(solid_.size()), nl = static_cast<Index>(liquid_.size());
    const bool solidBad = anyOf(ns, [&](Index p) { return solidProblem(p) != nullptr; });
    const bool liquidBad = anyOf(nl, [&](Index p) { return liquidProblem(p) != nullptr; });
    const bool gateBad = !std::isfinite(gateFlux_);
    if (!solidBad && !liquidBad && !gateBad) return;

    std::ostringstream s;
    s << "numerical failure at t = " << time_ << " s (step " << steps_ << "): ";
    auto where = [&](const char* set, Index p, const Real* x, const Real* v) {
        s << set << " point " << p << " at elevation " << x[D - 1] << " m (cell " << grid_.cellOf(x)
          << "), velocity " << speed(v) << " m/s (a cell per step is " << fastest << " m/s), has ";
    };
    if (gateBad) {
        s << "the gate flux is not finite";
    } else if (solidBad) {
        Index p = 0;
        while (!solidProblem(p)) ++p;
        where("solid", p, &solid_.x[p * D], &solid_.v[p * D]);
        s << solidProblem(p) << " (porosity " << solid_.porosity[p] << ")";
    } else {
        Index p = 0;
        while (!liquidProblem(p)) ++p;
        where("liquid", p, &liquid_.x[p * D], &liquid_.v[p * D]);
        s << liquidProblem(p) << " (pressure " << liquid_.pressure[p] << " Pa)";
    }
    s << ". Try a smaller time.courant (now " << config_.time.courant
      << "); with a coupled reservoir, coupling.scheme = \"implicit\"; check the head and the gate";
    throw Error(s.str());
}

template void DoublePointSolver<1>::checkHealth() const;
template void DoublePointSolver<2>::checkHealth() const;
template void DoublePointSolver<3>::checkHealth() const;

}  // namespace qs
