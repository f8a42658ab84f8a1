#include "materials/ConstitutiveModels.hpp"

#include "core/Error.hpp"
#include "materials/LinearElasticModel.hpp"
#include "materials/MohrCoulomb.hpp"

namespace qs {

std::shared_ptr<const ConstitutiveModel> makeConstitutiveModel(const MaterialConfig& m) {
    switch (m.model) {
        case ConstitutiveModelKind::LinearElastic:
            return std::make_shared<LinearElasticModel>(m.youngsModulus, m.poissonRatio);
        case ConstitutiveModelKind::MohrCoulomb:
            return std::make_shared<MohrCoulomb>(m.youngsModulus, m.poissonRatio, m.frictionAngle,
                                                 m.dilatancyAngle, m.cohesion, m.tensileStrength);
    }
    throw Error("materials." + m.name + ".model: unknown constitutive model");
}

}  // namespace qs
