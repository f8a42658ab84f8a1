// The Coulomb friction of boundary/RoughWalls.hpp at one wall node, by hand: dry grains (no water,
// no drag) of 2 kg, dt = 0.01 s, mu = 0.5. The reaction that holds a tangential component is
// R = -M_S v* / dt (and, wet, the drag of the water on the held grains); within mu N the grains
// stick, beyond it they slip with mu N against the slip.
#include <gtest/gtest.h>

#include "boundary/RoughWalls.hpp"

using namespace qs;

namespace {
constexpr Real kMass = 2, kDt = 0.01;

template <int D>
RoughWalls<D> oneNode(std::initializer_list<int> sides) {
    RoughWalls<D> w;
    w.friction = 0.5;
    w.side.assign(sides.begin(), sides.end());
    w.atWall.assign(1, 1);
    return w;
}

template <int D>
void solveDry(const RoughWalls<D>& w, const Real (&push)[D], const Real (&vS1)[D], NodeComponent (&c)[D],
              PhaseVelocities (&v)[D]) {
    const Real vL1[D] = {};
    for (int a = 0; a < D; ++a) {
        c[a] = NodeComponent{};
        c[a].massS = kMass;
        c[a].solidHeld = w.side[a] != 0;  // the wall holds its normal
    }
    w.solve(0, kDt, push, c, vS1, vL1, v);
}
}  // namespace

TEST(RoughWalls, GrainsStickWithinTheFrictionAndSlipBeyondIt) {
    const RoughWalls<2> w = oneNode<2>({-1, 0});  // the wall at x's lower end
    const Real push[2] = {-10, 0};                 // pressed onto it with 10 N: mu N = 5 N
    NodeComponent c[2];
    PhaseVelocities v[2];
    solveDry(w, push, {0, -0.02}, c, v);  // holding it takes 4 N: it sticks
    EXPECT_EQ(v[1].solid, 0.0);
    EXPECT_TRUE(c[1].solidHeld);  // and the semi-implicit step sees it held
    solveDry(w, push, {0, -0.05}, c, v);  // 10 N: it slips, 5 N of friction against it
    EXPECT_NEAR(v[1].solid, -0.05 + kDt * 5 / kMass, 1e-15);
    EXPECT_FALSE(c[1].solidHeld);
}

TEST(RoughWalls, GrainsPullingAwayFromTheWallFeelNoFriction) {
    const RoughWalls<2> w = oneNode<2>({1, 0});  // the wall at x's upper end
    NodeComponent c[2];
    PhaseVelocities v[2];
    solveDry(w, {-10, 0}, {0, -0.02}, c, v);  // pushed away from it
    EXPECT_NEAR(v[1].solid, -0.02, 1e-15);
    solveDry(w, {10, 0}, {0, -0.02}, c, v);   // pressed onto it
    EXPECT_EQ(v[1].solid, 0.0);
}

TEST(RoughWalls, ACornerAddsBothWallsPushes) {
    const RoughWalls<3> w = oneNode<3>({-1, -1, 0});
    NodeComponent c[3];
    PhaseVelocities v[3];
    solveDry(w, {-6, -4, 0}, {0, 0, -0.05}, c, v);  // N = 10, mu N = 5 against a 10 N hold
    EXPECT_NEAR(v[2].solid, -0.05 + kDt * 5 / kMass, 1e-15);
}

TEST(RoughWalls, TheFrictionIsIsotropicInTheWallsPlane) {
    const RoughWalls<3> w = oneNode<3>({-1, 0, 0});
    NodeComponent c[3];
    PhaseVelocities v[3];
    // the hold R = -M v* / dt = (-6, 8) N, 10 N against mu N = 5: the slip keeps its direction,
    // at half its speed, and never reverses
    solveDry(w, {-10, 0, 0}, {0, 0.03, -0.04}, c, v);
    EXPECT_NEAR(v[1].solid, 0.015, 1e-15);
    EXPECT_NEAR(v[2].solid, -0.02, 1e-15);
}

TEST(RoughWalls, TheWaterStreamingPastHeldGrainsIsPartOfWhatTheWallHolds) {
    // grains at rest on the wall, water streaming up past them: with the grains held the water's
    // velocity is M_L v_L* / (M_L + dt Q) = 0.05 m/s, its drag on them Q v_L = 5 N upward, which
    // the wall's reaction R = -5 N must hold. Within mu N = 6 N they stick; at mu N = 4 N they
    // are carried up with 4 N of friction against them.
    RoughWalls<2> w = oneNode<2>({-1, 0});
    auto wet = [](NodeComponent (&c)[2]) {
        for (int a = 0; a < 2; ++a) {
            c[a] = NodeComponent{};
            c[a].massS = kMass;
            c[a].massL = 1;
            c[a].drag = 100;
            c[a].solidHeld = a == 0;
        }
    };
    const Real vS1[2] = {0, 0}, vL1[2] = {0, 0.1};
    NodeComponent c[2];
    PhaseVelocities v[2];
    wet(c);
    auto held = w.solve(0, kDt, {-12, 0}, c, vS1, vL1, v);  // N = 12: mu N = 6 N
    EXPECT_TRUE(held.stuck);
    EXPECT_NEAR(held.reaction[1], -5, 1e-12);
    EXPECT_EQ(v[1].solid, 0.0);
    EXPECT_NEAR(v[1].liquid, 0.05, 1e-15);
    wet(c);
    auto carried = w.solve(0, kDt, {-8, 0}, c, vS1, vL1, v);  // mu N = 4 N
    EXPECT_FALSE(carried.stuck);
    NodeComponent free = c[1];
    const PhaseVelocities expected = solveComponent(free, kDt, vS1[1] - kDt * 4 / kMass, vL1[1]);
    EXPECT_NEAR(v[1].solid, expected.solid, 1e-15);
    EXPECT_GT(v[1].solid, 0.0);          // up, with the water
    EXPECT_LT(v[1].solid, v[1].liquid);  // and slower than it
}

TEST(RoughWalls, TheAxisIsALineOfSymmetryNotAWall) {
    // 3 x 4 cells: in plane strain both x walls are rough; in axisymmetry only r = R, not the axis
    CaseConfig config;
    config.column.wallFrictionAngle = 30;
    for (const bool axisymmetric : {false, true}) {
        const Grid<2> grid(IVec<2>{3, 4}, 0.01, 0.001, axisymmetric);
        RoughWalls<2> w;
        w.build(grid, config);
        EXPECT_NEAR(w.friction, std::tan(kPi / 6), 1e-15);
        for (Index i = 0; i < grid.numNodes(); ++i) {
            const IVec<2> n = grid.nodeCoords(i);
            const bool outer = n[0] == 3, axisSide = n[0] == 0;
            EXPECT_EQ(w.rough(i), outer || (axisSide && !axisymmetric)) << "node " << n[0] << ", " << n[1];
            EXPECT_EQ(w.side[i * 2 + 0], outer ? 1 : (axisSide && !axisymmetric ? -1 : 0));
            EXPECT_EQ(w.side[i * 2 + 1], 0);  // the floor is the filter's, not a rough wall
        }
    }
    config.column.wallFrictionAngle = 0;  // smooth: nothing is built, nothing is rough
    RoughWalls<2> smooth;
    smooth.build(Grid<2>(IVec<2>{3, 4}, 0.01, 0.001), config);
    EXPECT_FALSE(smooth.rough(0));
}
