// A cell holds one state of its water (solver/PorePressure.cpp, cellWaterFromPoints): the points that
// meet in it, some with a cavity and some pressed, mix so that the water's volume is kept. The
// cell's water strain is the mean of its points' strains e = c - p / K_L weighted by their water
// (liquid mass), and its pressure the water at that strain, -K_L e above the cavitation limit.
// Weighted by the points' mixture volumes instead, a point from the free water (V = m / rho) counts
// n times a point in sand (V = m / (n rho)) of the same water: the mixing then makes or loses water.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "case/CaseLoader.hpp"
#include "io/Checkpoint.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/DoublePointSolver.hpp"

using namespace qs;

TEST(CellWater, ACavityAndPressedWaterMeetingInACellKeepTheirVolume) {
    CaseConfig c = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/geostatic");
    const double pMin = -5e4;  // Pa, a limit well apart from zero
    c.liquid.cavitationPressure = pMin;
    auto reservoir = makeReservoirModel(c);
    DoublePointSolver<1> solver(c, *reservoir);
    for (int k = 0; k < 10; ++k) solver.step();

    // the points of a cell in the middle of the sand
    const double h = c.grid.cellSize, K = c.liquid.bulkModulus;
    const int row = static_cast<int>(0.5 * (c.filterLevel() + c.sandTop()) / h);
    const auto& l = solver.liquid();
    std::vector<std::size_t> inCell;
    for (std::size_t p = 0; p < l.size(); ++p)
        if (static_cast<int>(std::floor(l.x[p] / h)) == row) inCell.push_back(p);
    ASSERT_GE(inCell.size(), 2u);

    // One point at the limit holding a cavity, the others pressed; the cavity's point as if it came
    // from the free water (its mixture volume n times that of a sand point of the same water).
    // No gradient, so each point's pressure is its water's at the centre.
    CheckpointData data;
    solver.saveState(data);
    std::vector<double> volume(l.volume.begin(), l.volume.end()), pressure(l.pressure.begin(), l.pressure.end()),
        cavity(l.cavity.begin(), l.cavity.end());
    const double pressed = 3e4, open = 0.5 * pressed / K;  // Pa; the cavity a strain of the water
    for (std::size_t k = 0; k < inCell.size(); ++k) {
        const std::size_t p = inCell[k];
        pressure[p] = k == 0 ? pMin : pressed;
        cavity[p] = k == 0 ? open : 0.0;
    }
    volume[inCell[0]] *= c.material("sand").porosity;
    data.put("liquid/volume", volume);
    data.put("liquid/pore_pressure", pressure);
    data.put("liquid/cavity", cavity);
    data.put("cells/pressure_gradient", std::vector<double>(data.doubles("cells/pressure_gradient").size(), 0.0));
    solver.loadState(data);
    solver.step();  // its forces phase mixes the cell's points into the cell's water

    // the closed form: the mean strain, weighted by water, and the water at it
    double strain = 0, water = 0, strainByVolume = 0, volumes = 0;
    for (std::size_t k = 0; k < inCell.size(); ++k) {
        const std::size_t p = inCell[k];
        const double e = cavity[p] - pressure[p] / K;
        strain += l.mass[p] * e;
        water += l.mass[p];
        strainByVolume += volume[p] * e;
        volumes += volume[p];
    }
    const double expected = std::max(pMin, -K * strain / water);
    const double byVolume = std::max(pMin, -K * strainByVolume / volumes);
    const double got = solver.profile()[row].porePressure;
    std::printf("cell water: %.1f Pa, closed form %.1f Pa (weighted by mixture volume %.1f Pa)\n", got, expected,
                byVolume);
    ASSERT_GT(expected, pMin + 1e3);                        // the cavity closed: the mix is above the limit
    ASSERT_GT(std::abs(byVolume - expected), 1e3);          // the test tells the two weightings apart
    EXPECT_NEAR(got, expected, 1e-9 * pressed);             // round-off only
}
