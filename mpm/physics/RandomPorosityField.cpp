#include "physics/RandomPorosityField.hpp"

#include <cmath>
#include <random>

#include "core/Constants.hpp"
#include "core/Error.hpp"

namespace qs {

namespace {


/// A uniform deviate in (0, 1] from the top 53 bits: the same on every platform.
double uniformOpen(std::mt19937_64& engine) { return (static_cast<double>(engine() >> 11) + 1.0) * 0x1.0p-53; }

/// A standard normal deviate (Box-Muller, one of the pair).
double standardNormal(std::mt19937_64& engine) {
    const double u1 = uniformOpen(engine), u2 = uniformOpen(engine);
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
}

}  // namespace

RandomPorosityField::RandomPorosityField(int dimension, double correlationLength, std::uint64_t seed)
    : dimension_(dimension) {
    QS_CHECK(dimension >= 1 && dimension <= 3, "RandomPorosityField: dimension " << dimension << " is not 1, 2 or 3");
    QS_CHECK(correlationLength > 0 && std::isfinite(correlationLength),
             "RandomPorosityField: correlation length " << correlationLength << " m must be > 0");
    std::mt19937_64 engine(seed);
    wave_.resize(static_cast<std::size_t>(kModes) * dimension);
    phase_.resize(kModes);
    for (int m = 0; m < kModes; ++m) {
        for (int d = 0; d < dimension; ++d) wave_[m * dimension + d] = standardNormal(engine) / correlationLength;
        phase_[m] = 2.0 * kPi * uniformOpen(engine);
    }
}

double RandomPorosityField::unitField(const double* x) const {
    double sum = 0.0;
    for (int m = 0; m < kModes; ++m) {
        double arg = phase_[m];
        for (int d = 0; d < dimension_; ++d) arg += wave_[m * dimension_ + d] * x[d];
        sum += std::cos(arg);
    }
    return std::sqrt(2.0 / kModes) * sum;
}

}  // namespace qs
