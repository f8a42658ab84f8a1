#pragma once
// A random porosity field, so that a 2D or 3D bed is not perfectly uniform and can localise into
// pipes (issue 7). n(x) = n0 + sigma g(x), where g is a stationary Gaussian random field of zero
// mean, unit variance and squared-exponential correlation
//     E[g(x) g(x + r)] = exp(-|r|^2 / (2 l^2))          (l: correlation length, m),
// drawn by the randomization (random Fourier mode) method: g(x) = sqrt(2/M) sum_m cos(k_m.x + phi_m)
// with wave vectors k_m ~ N(0, I / l^2) (the covariance's spectral density) and phases phi_m
// uniform in [0, 2 pi). M = kModes.
//
// Reproducible from the seed on every platform: the modes come from std::mt19937_64 (its sequence
// is fixed by the C++ standard) through a Box-Muller transform written here, because the
// standard's normal and uniform distributions may differ between library implementations.
#include <cstdint>
#include <vector>

namespace qs {

class RandomPorosityField {
public:
    static constexpr int kModes = 256;

    /// dimension 1..3; correlationLength > 0 (m).
    RandomPorosityField(int dimension, double correlationLength, std::uint64_t seed);

    /// g(x): zero mean, unit variance. x: `dimension` coordinates (m).
    double unitField(const double* x) const;

private:
    int dimension_;
    std::vector<double> wave_;   ///< [mode][axis], 1/m
    std::vector<double> phase_;  ///< [mode], rad
};

}  // namespace qs
