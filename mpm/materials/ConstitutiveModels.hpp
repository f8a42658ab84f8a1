#pragma once
// The constitutive models quicksand knows, made from a case's [materials.NAME] table.
//
//   std::shared_ptr<const ConstitutiveModel> m = makeConstitutiveModel(materialConfig);
//
// A new model is one new file behind materials/ConstitutiveModel.hpp plus one line here (and its
// keys in case/CaseLoader and docs/case-format.md); the solver is not edited.
#include <memory>

#include "case/CaseConfig.hpp"
#include "materials/ConstitutiveModel.hpp"

namespace qs {

std::shared_ptr<const ConstitutiveModel> makeConstitutiveModel(const MaterialConfig& material);

}  // namespace qs
