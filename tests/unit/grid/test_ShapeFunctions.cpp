// Shape functions along one axis (grid/ShapeFunctions.hpp): linear hats and uGIMP, whole and cut
// at the end of the region a material fills.
#include <gtest/gtest.h>

#include <cmath>

#include "grid/ShapeFunctions.hpp"

using namespace qs;

namespace {

constexpr double h = 0.01, lp = 0.25 * h;
constexpr Index cells = 10;

struct Sums {
    double N = 0, dN = 0, xN = 0, xdN = 0;
};

Sums sums(const AxisWeights& a) {
    Sums s;
    for (int k = 0; k < kStencil; ++k) {
        const double xi = (a.start + k) * h;
        s.N += a.w[k];
        s.dN += a.dw[k];
        s.xN += xi * a.w[k];
        s.xdN += xi * a.dw[k];
    }
    return s;
}

/// The mean of node k's hat and of its slope over [a, b], by the midpoint rule on 20 000 pieces.
void meanHat(double node, double a, double b, double& N, double& dN) {
    const int n = 20000;
    N = dN = 0;
    for (int j = 0; j < n; ++j) {
        double w, dw;
        linearHat(a + (j + 0.5) * (b - a) / n - node, h, w, dw);
        N += w / n;
        dN += dw / n;
    }
}

}  // namespace

// Away from the region's ends, uGIMP is Bardenhagen & Kober's: a partition of unity whose
// interpolation of x is exact (sum N x_i = x, sum dN x_i = 1).
TEST(ShapeFunctions, InsideTheRegionUgimpIsAConsistentPartitionOfUnity) {
    for (double x : {0.3 * h, 2.1 * h, 4.5 * h, 5.9 * h, 9.7 * h}) {
        const Sums s = sums(axisWeights(x, h, cells, ShapeFunctionKind::Gimp, lp, 0.0, cells * h));
        EXPECT_NEAR(s.N, 1, 1e-14) << x;
        EXPECT_NEAR(s.dN, 0, 1e-10) << x;
        EXPECT_NEAR(s.xN, x, 1e-14) << x;
        EXPECT_NEAR(s.xdN, 1, 1e-12) << x;
    }
}

// Within lp of an end (a wall, the filter for the sand) the domain is cut there: the weights
// still sum to 1 and interpolate the cut domain's centre, and nothing reaches past the end.
// uGIMP's own weights there summed to 1 - (lp - d)^2 / (4 h lp) at a distance d from a wall.
TEST(ShapeFunctions, UgimpCutAtTheRegionsEndsKeepsThePartitionOfUnity) {
    struct Case { double x, lo, hi; };
    for (const Case c : {Case{h / 16, 0, cells * h}, Case{0, 0, cells * h}, Case{cells * h - 0.1 * h, 0, cells * h},
                         Case{3 * h + 0.05 * h, 3 * h, cells * h}, Case{3 * h - 0.1 * h, 3 * h, cells * h}}) {
        const AxisWeights a = axisWeights(c.x, h, cells, ShapeFunctionKind::Gimp, lp, c.lo, c.hi);
        const Sums s = sums(a);
        const double from = std::max(c.x - lp, c.lo), to = std::min(c.x + lp, c.hi);
        EXPECT_NEAR(s.N, 1, 1e-14) << c.x;
        EXPECT_NEAR(s.dN, 0, 1e-10) << c.x;
        EXPECT_NEAR(s.xN, 0.5 * (from + to), 1e-14) << c.x;
        EXPECT_NEAR(s.xdN, 1, 1e-12) << c.x;
        for (int k = 0; k < kStencil; ++k) {
            const double node = (a.start + k) * h;
            double N, dN;
            meanHat(node, from, to, N, dN);
            EXPECT_NEAR(a.w[k], N, 1e-8) << c.x << " node " << k;
            EXPECT_NEAR(a.dw[k], dN, 1e-6 / h) << c.x << " node " << k;
            if (node < c.lo - 1e-12 || node > c.hi + 1e-12) {
                EXPECT_EQ(a.w[k], 0.0) << "beyond the end";
            }
        }
    }
}

// Where the domain is whole, the cut and uGIMP's closed form are the same function (the cut's
// formula is only taken where it is needed, so the two meet at its edge).
TEST(ShapeFunctions, TheCutMeetsUgimpWhereTheDomainIsWhole) {
    for (double x : {lp, 3 * h + lp}) {
        const double lo = x < h ? 0.0 : 3 * h;
        const AxisWeights whole = axisWeights(x, h, cells, ShapeFunctionKind::Gimp, lp, lo, cells * h);
        const AxisWeights cut = axisWeights(x - 1e-9 * h, h, cells, ShapeFunctionKind::Gimp, lp, lo, cells * h);
        for (int k = 0; k < kStencil; ++k) {
            EXPECT_NEAR(whole.w[k], cut.w[k], 1e-8);
            EXPECT_NEAR(whole.dw[k], cut.dw[k], 1e-6 / h);
        }
    }
}

// Linear hats are never cut: a point inside its cell has only its cell's two nodes.
TEST(ShapeFunctions, LinearHatsAreExactAtTheEnds) {
    for (double x : {h / 16, 0.5 * h, 9.9 * h}) {
        const Sums s = sums(axisWeights(x, h, cells, ShapeFunctionKind::Linear, 0, 0.0, cells * h));
        EXPECT_NEAR(s.N, 1, 1e-14);
        EXPECT_NEAR(s.xN, x, 1e-14);
        EXPECT_NEAR(s.xdN, 1, 1e-12);
    }
}
