// RandomPorosityField: reproducible from its seed; one realization over a large domain has the
// field's statistics (mean 0, variance 1, correlation exp(-r^2 / 2 l^2)).
#include "physics/RandomPorosityField.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

struct Statistics {
    double mean = 0, variance = 0, correlationAtL = 0, correlationAt3L = 0;
};

/// Statistics of one 2D realization on a 60 l x 60 l square sampled every l/5.
Statistics sample2D(const qs::RandomPorosityField& g, double l) {
    const int n = 300, lag = 5;  // lag * spacing = l
    const double spacing = l / 5;
    std::vector<double> v(static_cast<std::size_t>(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x[2] = {i * spacing, j * spacing};
            v[j * n + i] = g.unitField(x);
        }
    Statistics s;
    for (double a : v) s.mean += a;
    s.mean /= v.size();
    for (double a : v) s.variance += (a - s.mean) * (a - s.mean);
    s.variance /= v.size();
    auto correlation = [&](int k) {
        double c = 0;
        int count = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i + k < n; ++i, ++count)  // along x and along z alike
                c += (v[j * n + i] - s.mean) * (v[j * n + i + k] - s.mean) +
                     (v[i * n + j] - s.mean) * (v[(i + k) * n + j] - s.mean);
        return c / (2.0 * count * s.variance);
    };
    s.correlationAtL = correlation(lag);
    s.correlationAt3L = correlation(3 * lag);
    return s;
}

TEST(RandomPorosityField, TheSameSeedGivesTheSameFieldAndAnotherSeedAnother) {
    const qs::RandomPorosityField a(2, 0.01, 7), b(2, 0.01, 7), c(2, 0.01, 8);
    int differ = 0;
    for (int k = 0; k < 50; ++k) {
        const double x[2] = {0.003 * k, 0.0017 * k};
        EXPECT_EQ(a.unitField(x), b.unitField(x));  // bit for bit
        if (std::abs(a.unitField(x) - c.unitField(x)) > 1e-3) ++differ;
    }
    EXPECT_GT(differ, 45);
}

TEST(RandomPorosityField, OneRealizationHasUnitVarianceAndGaussianCorrelation) {
    const double l = 0.02;
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        const Statistics s = sample2D(qs::RandomPorosityField(2, l, seed), l);
        // closed forms: mean 0, variance 1, rho(l) = exp(-1/2) = 0.6065, rho(3 l) = exp(-9/2) = 0.0111.
        // A realization of 256 modes over 60 l misses them by O(1/sqrt(256)); measured for seeds
        // 1..3: |mean| <= 0.049, |var - 1| <= 0.052, |rho(l) - 0.6065| <= 0.019, |rho(3 l) - 0.0111| <= 0.061.
        // A correlation length 10 % off would put rho(l) 0.055 away.
        EXPECT_NEAR(s.mean, 0.0, 0.07) << "seed " << seed;
        EXPECT_NEAR(s.variance, 1.0, 0.08) << "seed " << seed;
        EXPECT_NEAR(s.correlationAtL, std::exp(-0.5), 0.04) << "seed " << seed;
        EXPECT_NEAR(s.correlationAt3L, std::exp(-4.5), 0.08) << "seed " << seed;
    }
}

TEST(RandomPorosityField, TheCorrelationLengthScalesTheField) {
    // g with length l at x is g with length 2 l at 2 x: the length is a pure scale
    const qs::RandomPorosityField a(3, 0.01, 5), b(3, 0.02, 5);
    for (int k = 0; k < 20; ++k) {
        const double x[3] = {0.001 * k, 0.002 * k, 0.0005 * k};
        const double x2[3] = {2 * x[0], 2 * x[1], 2 * x[2]};
        EXPECT_NEAR(a.unitField(x), b.unitField(x2), 1e-12);
    }
}

}  // namespace
