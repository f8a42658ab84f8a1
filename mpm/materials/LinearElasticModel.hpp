#pragma once
// LinearElasticModel: Hooke's law on the effective stress with the tension cut-off (the sand takes
// no tension: after each increment principal stresses above zero are clipped to zero, physics.md
// section 2). No state variables.
#include "materials/ConstitutiveModel.hpp"
#include "materials/LinearElastic.hpp"
#include "materials/StressTensor.hpp"

namespace qs {

class LinearElasticModel final : public ConstitutiveModel {
public:
    LinearElasticModel(Real youngsModulus, Real poissonRatio)
        : elastic_(LinearElastic::fromYoung(youngsModulus, poissonRatio)) {}

    std::string name() const override { return "linear_elastic"; }
    StressReturn update(const StressPoint& point) const override {
        elastic_.update(point.stress, point.strainIncrement);
        return tensionCutoff(point.stress) ? StressReturn::TensionCutoff : StressReturn::Elastic;
    }
    Real oedometricModulus() const override { return elastic_.oedometric(); }

private:
    LinearElastic elastic_;
};

}  // namespace qs
