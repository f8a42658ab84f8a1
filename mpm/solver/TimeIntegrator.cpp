// The time schemes behind the TimeIntegrator seam, chosen by case.toml's time.scheme.
#include "solver/TimeIntegrator.hpp"

#include "solver/ExplicitIntegrator.hpp"
#include "solver/SemiImplicitIntegrator.hpp"

namespace qs {

template <int D>
std::unique_ptr<TimeIntegrator<D>> makeTimeIntegrator(const StepContext<D>& context) {
    if (context.config.time.scheme == TimeScheme::SemiImplicit)
        return std::make_unique<SemiImplicitIntegrator<D>>(context);
    return std::make_unique<ExplicitIntegrator<D>>(context);
}

template std::unique_ptr<TimeIntegrator<1>> makeTimeIntegrator(const StepContext<1>&);
template std::unique_ptr<TimeIntegrator<2>> makeTimeIntegrator(const StepContext<2>&);
template std::unique_ptr<TimeIntegrator<3>> makeTimeIntegrator(const StepContext<3>&);

}  // namespace qs
