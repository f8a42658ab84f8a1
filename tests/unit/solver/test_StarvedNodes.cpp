// A solid point just past a node plane, beside a cell without sand: the node it has crossed to
// holds only the point's own sliver of solid (N ~ its distance from the plane), while the point's
// effective stress still pushes on that node with the full slope 1/h. The node's velocity is
// then that force over the sliver's mass, and with linear hats the point's velocity gradient
// takes it with the full slope too. Found in the coupled Deltares column at t = 51.88 s: a lone
// point 2.4e-8 cells above node row 10 read v = -563 m/s at the node above, a strain of -1.21
// in one step and a porosity of 3.98 (the run stopped with a numerical failure).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "io/CaseLoader.hpp"
#include "io/Checkpoint.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/DoublePointSolver.hpp"

using namespace qs;

namespace {

/// The geostatic column with two cells of water over the sand, and a copy of its top solid point
/// (its stress, porosity and state) put `offset` cells above the sand's surface node, into the
/// cell above, which holds no other sand. The surface node then reads the bed's porosity (the
/// copy's grains fill the half cell above it), so the copy is a skeleton that carries stress.
struct ColumnWithAPointPastTheSurface {
    CaseConfig config;
    std::unique_ptr<ReservoirModel> reservoir;
    std::unique_ptr<DoublePointSolver<1>> solver;
    double stressBefore = 0, porosityBefore = 0, z = 0;

    explicit ColumnWithAPointPastTheSurface(double offset) {
        config = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/geostatic");
        const double h = config.grid.cellSize;
        config.column.waterLevel = config.sandTop() + 2 * h;
        config.column.top = config.sandTop() + 4 * h;
        config.reservoir.head = config.column.waterLevel;
        reservoir = makeReservoirModel(config);
        solver = std::make_unique<DoublePointSolver<1>>(config, *reservoir);
        CheckpointData data;
        solver->saveState(data);
        const std::vector<double> x = data.doubles("solid_field0");
        const std::size_t points = x.size();
        const std::size_t top = std::max_element(x.begin(), x.end()) - x.begin();
        // every field of the solid points (SolidPoints::forEachField): the copy appended
        for (int k = 0; k < 10; ++k) {
            const std::string name = "solid_field" + std::to_string(k);
            if (k == 6 || k == 7) {  // state, material
                std::vector<std::int64_t> f = data.integers(name);
                f.push_back(f[top]);
                data.put(name, f);
                continue;
            }
            std::vector<double> f = data.doubles(name);
            const std::size_t components = f.size() / points;
            for (std::size_t c = 0; c < components; ++c) f.push_back(f[top * components + c]);
            data.put(name, f);
        }
        z = (std::round(config.sandTop() / h) + offset) * h;
        std::vector<double> moved = data.doubles("solid_field0");
        moved.back() = z;
        data.put("solid_field0", moved);
        stressBefore = data.doubles("solid_field5")[top * 6 + 2];  // Voigt zz
        porosityBefore = data.doubles("solid_field4")[top];
        solver->loadState(data);
    }
    /// The copy after the steps: still the highest point.
    std::size_t top() const {
        const auto& x = solver->solid().x;
        return std::max_element(x.begin(), x.end()) - x.begin();
    }
};

}  // namespace

TEST(StarvedNodes, AStressedPointJustPastANodePlaneDoesNotTakeTheSliverNodesStrain) {
    // the point sits 1e-6 cells above the sand's surface node; the node above holds 1e-6 of its mass
    ColumnWithAPointPastTheSurface column(1e-6);
    // the test needs a point that pushes on its nodes: the top point of the K0 column carries
    // the buoyant weight of a quarter cell, 23 Pa
    ASSERT_LT(column.stressBefore, -10.0);
    ASSERT_EQ(column.solver->solid().state[column.top()], kSolidState);
    column.solver->step();
    std::size_t p = column.top();
    const auto& s = column.solver->solid();
    // Taking the node above's velocity (its own stress over 1e-6 of its mass, about 30 m/s), the
    // point's gradient was 3059 /s, it stretched by 6 % in that one step (n 0.380 -> 0.416) and
    // its stress vanished at the tension cut-off. Read as a node of the starved share's mass, it
    // unloads at 0.04 /s: n moves by 5e-7, the stress by 1 Pa (E_oed 1.35e6 Pa)
    EXPECT_NEAR(s.porosity[p], column.porosityBefore, 1e-5);
    EXPECT_LT(std::abs(s.velocityGradient[p]), 0.1) << "1/s, APIC's C of the point";
    EXPECT_LT(s.stress[p * 6 + 2], 0.5 * column.stressBefore) << "Pa: it keeps most of its stress";
    // and over 500 steps, as it settles back onto the bed, it stays a skeleton at n0 (without the
    // scaling: n 0.419, gradients up to 179 /s)
    double worst = 0, fastest = 0;
    for (int k = 0; k < 500; ++k) {
        column.solver->step();
        p = column.top();
        worst = std::max(worst, std::abs(s.porosity[p] - column.porosityBefore));
        fastest = std::max(fastest, std::abs(s.velocityGradient[p]));
    }
    EXPECT_LT(worst, 1e-4);
    EXPECT_LT(fastest, 1.0) << "1/s";
}

TEST(StarvedNodes, APointWellInsideItsCellStillStrainsWithBothNodes) {
    // a tenth of a cell past the plane the node above holds 0.1 of the point's mass, against
    // S = m_p (h / h)^2 from the point's one slope: more than the starved share, C^2 / 2 = 0.08 at
    // C = 0.4, so the point's gradient reads the node above in full, as before: 0.026 /s in this
    // step. Scaled by w it would be (0.9 w + 0.1) 0.026 /s, below 0.02 /s for w < 0.78, which a
    // starved share above 0.13 (more than C = 0.5 allows) would give.
    ColumnWithAPointPastTheSurface column(0.1);
    ASSERT_LT(column.stressBefore, -10.0);
    column.solver->step();
    const std::size_t p = column.top();
    EXPECT_GT(std::abs(column.solver->solid().velocityGradient[p]), 0.02)
        << "1/s: the stress acts on the node above and the point's gradient sees it";
}
