// The free water's surface in 2D (issue 7). One pore pressure per cell cannot see where in a cell
// the water is; these tests fail when the surface's treatment lets that show.
//   - A sloshing mode of the top cells must not grow. Seeded with v_z = a cos(pi x / h) in the
//     water's top two cell rows (up beside the walls, down beside the middle node column: the
//     pattern each cell-centre divergence cancels), it stays at its seed. With a nodal liquid
//     mass that followed the points within the surface cells it grew 150 times in 3 s here
//     (points sinking towards a node made it heavier, and the cell's pressure did not hold the
//     extra weight), and it stopped a 2D batch settling at 11.3 s (e-fold in about 0.2 s there).
//   - One stray point above a half-filled cell leaves the pore pressure below as it was: decided
//     by any liquid above, the half-filled cell counted as full, the water gained the weight of
//     its missing half (15 Pa on average, 26 Pa at worst, in the sand below, where 1.0 Pa is left
//     now).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "VerificationCase.hpp"
#include "io/Checkpoint.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/RunSize.hpp"
#include "solver/DoublePointSolver.hpp"

using namespace qs;
using namespace qs::test;

namespace {

/// The geostatic column in 2D plane strain, two cells across, with `cells` cells of free water
/// above the sand (the surface inside a cell when it is not whole), at rest on a constant head.
CaseConfig freeWaterColumn(double cells) {
    CaseConfig c = loadVerificationCase("geostatic");
    inGeometry(c, Geometry::Plane2D, 2);
    const double h = c.grid.cellSize;
    c.column.waterLevel = c.sandTop() + cells * h;
    c.column.top = std::ceil(c.column.waterLevel / h - 1e-9) * h + 2 * h;
    c.reservoir.head = c.column.waterLevel;
    return c;
}

}  // namespace

TEST(FreeSurface2D, ASloshingModeOfTheTopCellsDoesNotGrow) {
    const CaseConfig c = freeWaterColumn(3.9);
    auto reservoir = makeReservoirModel(c);
    DoublePointSolver<2> solver(c, *reservoir);
    const double h = c.grid.cellSize, pi = std::acos(-1.0);
    double top = 0;
    for (std::size_t p = 0; p < solver.liquid().size(); ++p) top = std::max(top, solver.liquid().x[p * 2 + 1]);
    auto inTopCells = [&](const double* x) { return x[1] > top - 2 * h; };
    auto pattern = [&](const double* x) { return std::cos(pi * x[0] / h); };
    // the mode's amplitude: the top cells' vertical velocities projected on the pattern
    auto amplitude = [&]() {
        const auto& l = solver.liquid();
        double sv = 0, ss = 0;
        for (std::size_t p = 0; p < l.size(); ++p) {
            if (!inTopCells(&l.x[p * 2])) continue;
            const double s = pattern(&l.x[p * 2]);
            sv += s * l.v[p * 2 + 1];
            ss += s * s;
        }
        return sv / ss;
    };
    const double seed = 1e-7;  // m/s
    CheckpointData data;
    solver.saveState(data);
    std::vector<double> v(solver.liquid().v.begin(), solver.liquid().v.end());
    const auto& l = solver.liquid();
    for (std::size_t p = 0; p < l.size(); ++p)
        if (inTopCells(&l.x[p * 2])) v[p * 2 + 1] += seed * pattern(&l.x[p * 2]);
    data.put("liquid/velocity", v);  // x, v, mass, volume, pressure
    solver.loadState(data);
    const double start = amplitude();
    ASSERT_NEAR(start, seed, 0.05 * seed);
    double worst = 0;
    while (solver.time() < 3.0) {
        solver.step();
        if (solver.stepCount() % 1000 == 0) worst = std::max(worst, std::abs(amplitude()));
    }
    // with the points' mass at the surface it grew to 150 times its seed in these 3 s
    EXPECT_LT(worst, 2 * seed);
    EXPECT_LT(worst, 1.01 * seed);  // guard: neutral, 1.000 times the seed throughout
    std::printf("free-surface sloshing mode: seeded %.2e m/s, largest %.3e m/s over 3 s, %.3e m/s at the end\n",
                start, worst, amplitude());
}

TEST(FreeSurface2D, AStrayPointAboveLeavesThePorePressureBelowAsItWas) {
    const CaseConfig c = freeWaterColumn(0.5);  // the free water half fills its cell
    auto reservoir = makeReservoirModel(c);
    DoublePointSolver<2> solver(c, *reservoir);
    const double h = c.grid.cellSize;
    while (solver.time() < 0.2) solver.step();  // at rest: its water's speeds below 1e-8 m/s
    // lift the highest point beside the wall by one cell, into the empty cell above
    const auto& l = solver.liquid();
    std::size_t stray = 0;
    for (std::size_t p = 1; p < l.size(); ++p)
        if (l.x[p * 2 + 1] > l.x[stray * 2 + 1] + 1e-12 ||
            (std::abs(l.x[p * 2 + 1] - l.x[stray * 2 + 1]) <= 1e-12 && l.x[p * 2] < l.x[stray * 2]))
            stray = p;
    CheckpointData data;
    solver.saveState(data);
    std::vector<double> x(l.x.begin(), l.x.end());
    x[stray * 2 + 1] += h;
    data.put("liquid/position", x);
    solver.loadState(data);
    const double strayMass = l.mass[stray];
    // While the point falls back through the cell above (sqrt(2 h / g) = 44 ms) the pore pressure
    // in the sand stays as it was: at most the lifted point's weight over the column's area (its
    // weight leaves the water while it is in the air) may come and go. A half-filled cell counted
    // as full adds the weight of the half cell's missing water, rho_L g h / 4 = 23 Pa.
    const double waterTop = c.column.waterLevel;
    const auto before = solver.profile();
    double worst = 0, worstDp = 0, meanDp = 0;
    int samples = 0;
    const double t0 = solver.time();
    while (solver.time() < t0 + 0.04) {
        solver.step();
        for (std::size_t p = 0; p < l.size(); ++p)
            if (l.x[p * 2 + 1] < waterTop - 0.5 * h) worst = std::max(worst, std::abs(l.v[p * 2 + 1]));
        if (solver.stepCount() % 20 == 0) {
            const auto rows = solver.profile();
            double dp = 0;
            int n = 0;
            for (std::size_t r = 0; r < rows.size(); ++r)
                if (rows[r].z > c.filterLevel() && rows[r].z < c.sandTop()) {
                    dp += rows[r].porePressure - before[r].porePressure;
                    worstDp = std::max(worstDp, std::abs(rows[r].porePressure - before[r].porePressure));
                    ++n;
                }
            meanDp += dp / n;
            ++samples;
        }
    }
    std::printf("stray point (%.2e kg): largest vertical velocity of the water below its surface cell %.3e m/s, "
                "largest sand-row pressure change %.3f Pa, mean %.3f Pa\n",
                strayMass, worst, worstDp, meanDp / samples);
    const double pointWeight = strayMass * c.gravity / c.grid.crossSectionArea;  // 3.8 Pa
    EXPECT_LT(worstDp, pointWeight);
    EXPECT_LT(std::abs(meanDp / samples), pointWeight);
    // guard: 1.53 Pa achieved with one water state per cell (1.0 Pa while points carried their own
    // pressures; any liquid above counting: 26 Pa, mean 15 Pa)
    EXPECT_LT(worstDp, 2.0);
    // The water below does move: the falling point shares its cell's lower nodes with the water's
    // top cell and drags them (2.9e-3 m/s at most; 1.4e-2 m/s when the cell counted as full)
    EXPECT_LT(worst, 5e-3);
}

namespace {

/// What is left, after `steps` steps, of velocities seeded in the free water of a column at rest:
/// a random velocity of `noise` m/s per point (what the grid cannot see, a few points per node
/// moving opposite ways) and a vortex of `swirl` m/s filling the free water (a flow the grid
/// resolves, its stream function psi = sin(pi x / W) sin(pi (z - z0) / (z1 - z0)), free of
/// divergence and of flow through the walls). The vortex is measured by its projection on the
/// seeded field, the noise as the rms of what the projection leaves (docs/piping.md, "The free
/// water over a boil").
struct SeededFreeWater {
    double noise;  ///< rms of the residual over its seeded rms
    double swirl;  ///< the vortex's amplitude over its seeded amplitude (0 when not seeded)
};

SeededFreeWater freeWaterAfter(double picShare, double noise, double swirl, int steps, int across = 2,
                               double cells = 3.0, double dampingTime = 0.0, double courant = 0.0,
                               double* stepSize = nullptr) {
    CaseConfig c = freeWaterColumn(cells);
    inGeometry(c, Geometry::Plane2D, across);
    c.liquid.picShare = picShare;
    c.liquid.picDampingTime = dampingTime;
    if (courant > 0) c.time.courant = courant;
    // outputs every 2 h / c: 5 steps at courant 0.4, 10 at 0.2, so that the step fitted to them
    // (solver/TimeLattice.hpp) is the stable one at both and the halved one is exactly half
    c.time.outputInterval = 2 * stableTimeStep(c) / c.time.courant;
    auto reservoir = makeReservoirModel(c);
    DoublePointSolver<2> solver(c, *reservoir);
    if (stepSize) *stepSize = solver.dt();
    const double z0 = c.sandTop() + c.grid.cellSize;  // a cell clear of the sand's nodes
    const double z1 = c.column.waterLevel, width = c.grid.width, pi = std::acos(-1.0);
    const auto& l = solver.liquid();
    auto free = [&](std::size_t p) { return l.x[p * 2 + 1] > z0 && l.x[p * 2 + 1] < z1; };
    auto vortex = [&](std::size_t p, int axis) {  // (d psi / dz, -d psi / dx), psi scaled by W / pi
        const double a = pi * l.x[p * 2] / width, b = pi * (l.x[p * 2 + 1] - z0) / (z1 - z0);
        return axis == 0 ? std::sin(a) * std::cos(b) * width / (z1 - z0) : -std::cos(a) * std::sin(b);
    };
    auto measure = [&](double& amplitude, double& residual) {
        double sv = 0, ss = 0;
        for (std::size_t p = 0; p < l.size(); ++p)
            if (free(p))
                for (int d = 0; d < 2; ++d) { sv += l.v[p * 2 + d] * vortex(p, d); ss += vortex(p, d) * vortex(p, d); }
        amplitude = sv / ss;
        double r = 0;
        int n = 0;
        for (std::size_t p = 0; p < l.size(); ++p)
            if (free(p)) {
                for (int d = 0; d < 2; ++d) r += std::pow(l.v[p * 2 + d] - amplitude * vortex(p, d), 2);
                ++n;
            }
        residual = std::sqrt(r / n);
    };
    CheckpointData data;
    solver.saveState(data);
    std::vector<double> v(l.v.begin(), l.v.end());
    std::uint32_t state = 12345;  // a fixed linear congruential sequence: the same on every machine
    auto next = [&]() { state = state * 1664525u + 1013904223u; return state / 4294967296.0 - 0.5; };
    for (std::size_t p = 0; p < l.size(); ++p)
        if (free(p))
            for (int d = 0; d < 2; ++d) v[p * 2 + d] += 2 * noise * next() + swirl * vortex(p, d);
    data.put("liquid/velocity", v);  // the liquid points' velocities
    solver.loadState(data);
    double a0 = 0, r0 = 0, a = 0, r = 0;
    measure(a0, r0);
    for (int k = 0; k < steps; ++k) solver.step();
    measure(a, r);
    return {r / r0, swirl > 0 ? a / a0 : 0.0};
}

}  // namespace

// liquid.pic_share: the free water has nothing at the grid's scale to dissipate the velocities of
// points the grid cannot see, and FLIP keeps them; in piping2D they grew over a boil into a
// stirring at the sand's surface. A share alpha of the grid's velocity each step takes the part
// the grid cannot see down as (1 - alpha)^steps. Seeded at random in a free water at rest, FLIP
// keeps most of it; with alpha = 0.01, 300 steps take it to (0.99)^300 = 0.049 of its seed (what
// the grid does see of a random seed is small: a few points per node, opposite ways).
TEST(FreeSurface2D, PicShareDampsThePointVelocitiesTheGridCannotSee) {
    const double seed = 1e-6;  // m/s: far too small to move the water's points measurably
    const double flip = freeWaterAfter(0.0, seed, 0.0, 300).noise;
    const double blended = freeWaterAfter(0.01, seed, 0.0, 300).noise;
    const double closed = std::pow(0.99, 300);
    EXPECT_GT(flip, 0.5);  // FLIP keeps it (0.964 achieved)
    // the blend takes it down as the closed form: within 10 % (0.050 against 0.049 achieved)
    EXPECT_LT(std::abs(blended / closed - 1), 0.10);
    EXPECT_LT(std::abs(blended / closed - 1), 0.05);  // guard
    std::printf("free water's random point velocities after 300 steps: FLIP %.3f of the seed, pic_share 0.01 %.3f "
                "((0.99)^300 = %.3f)\n", flip, blended, closed);
}

// liquid.pic_damping_time: the same blend given as a time T, alpha = 1 - exp(-dt / T) each step,
// so that it damps as much per second whatever the step: a semi-implicit step 6.5 times the
// explicit one took pic_share = 0.01 as a damping time of 13 ms instead of 2 ms. Two runs of
// the same simulated time, one at half the step (courant 0.2 against 0.4) and twice the steps,
// both towards exp(-t / T).
TEST(FreeSurface2D, PicDampingTimeDampsAsMuchPerSecondWhateverTheStep) {
    const double seed = 1e-6;  // m/s
    double dt = 0, dtHalf = 0;
    freeWaterAfter(0.0, seed, 0.0, 0, 2, 3.0, 0.0, 0.4, &dt);
    const double T = 100 * dt;  // pic_share 0.01 at the coarser step
    const double coarse = freeWaterAfter(0.0, seed, 0.0, 300, 2, 3.0, T, 0.4, &dt).noise;
    const double fine = freeWaterAfter(0.0, seed, 0.0, 600, 2, 3.0, T, 0.2, &dtHalf).noise;
    const double closed = std::exp(-300 * dt / T);
    ASSERT_NEAR(dtHalf / dt, 0.5, 1e-12);
    std::printf("pic_damping_time %.3g s: noise left after %.3g s at dt %.3g s %.4f, at dt / 2 %.4f "
                "(exp(-t / T) = %.4f)\n", T, 300 * dt, dt, coarse, fine, closed);
    EXPECT_LT(std::abs(coarse / closed - 1), 0.10);
    EXPECT_LT(std::abs(fine / closed - 1), 0.10);
    // per step, pic_share = 0.01 at both steps would leave 0.049 and 0.0024: here the two agree
    EXPECT_LT(std::abs(fine / coarse - 1), 0.05);
    // guards near what is achieved (0.0500 and 0.0499 against 0.0498)
    EXPECT_LT(std::abs(coarse / closed - 1), 0.02);
    EXPECT_LT(std::abs(fine / coarse - 1), 0.01);
}

// The blend must take the grid's velocity, not zero: at rest the two are the same, so here the
// free water turns as a vortex under the same random noise. A blend towards zero would leave
// (0.99)^300 = 0.049 of the vortex; FLIP keeps it all. The blend keeps what the grid sees of it:
// each step it takes a share alpha towards the grid's own velocity, and the grid (linear hats)
// carries a fraction lambda of a mode a few cells across, so the vortex decays as
// (1 - alpha (1 - lambda))^steps. Twelve cells across (6 at the vortex's half wavelength)
// lambda ~ 0.96 and 0.88 is kept (FLIP 0.997); six cells across kept 0.63 (lambda ~ 0.85): PIC's known damping of
// what the grid barely resolves, which is why the blend is small and off by default.
TEST(FreeSurface2D, PicShareKeepsTheFlowTheGridSees) {
    const double noise = 1e-6, swirl = 1e-6;  // m/s
    const auto flip = freeWaterAfter(0.0, noise, swirl, 300, 12, 12.0);
    const auto blended = freeWaterAfter(0.01, noise, swirl, 300, 12, 12.0);
    const double closed = std::pow(0.99, 300);
    std::printf("vortex kept after 300 steps: FLIP %.3f, pic_share 0.01 %.3f (towards zero: %.3f); noise and the "
                "vortex's unresolved part left: FLIP %.3f, blend %.3f\n",
                flip.swirl, blended.swirl, closed, flip.noise, blended.noise);
    EXPECT_GT(flip.swirl, 0.95);
    EXPECT_GT(blended.swirl, 0.5);  // ten times what a blend towards zero leaves
    EXPECT_GT(blended.swirl, 0.85);  // guard near what is achieved
    EXPECT_GT(flip.noise, 0.9);
    EXPECT_LT(blended.noise, 0.5 * flip.noise);
    EXPECT_LT(blended.noise, 0.15);  // guard: 0.108 achieved (0.978 FLIP)
}
