#pragma once
// Runs a shipped verification case (cases/verification/NAME) in memory and keeps what a test
// compares with the closed form: the series at every output time and the cell-row profiles.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/Constants.hpp"
#include "case/CaseLoader.hpp"
#include "solver/Run.hpp"

namespace qs::test {

struct CaseRun {
    CaseConfig config;
    RunSummary summary;
    std::vector<ColumnState> series;
    std::vector<std::vector<CellRow>> profiles;  ///< one per output time
    std::vector<SandCells> cells;                ///< 2D/3D: the cells' sand state per output time
    std::vector<PipeSurvey> pipes;               ///< 2D/3D: the pipes found in them
};

/// The scheme this test binary runs every case with: "explicit" or "semi_implicit"
/// (verification/scheme/*.cpp, one per binary).
const char* defaultTestScheme();

/// The time scheme the suite runs with: the binary's (ctest runs the suite once per scheme,
/// tests/CMakeLists.txt: every problem holds for both with the same tolerances), unless the
/// environment's QUICKSAND_TEST_SCHEME names one.
inline std::string testScheme() {
    const char* scheme = std::getenv("QUICKSAND_TEST_SCHEME");
    return scheme && *scheme ? scheme : defaultTestScheme();
}

/// CI's 45 minutes (docs/verification.md, "Both time schemes"): a long multi-D repeat of a
/// problem whose physics the explicit binary checks in 1D and in a shorter multi-D test runs with
/// the semi-implicit step only; the explicit binary reports it skipped, saying so.
#define QS_SEMI_IMPLICIT_ONLY()                                                                  \
    if (::qs::test::testScheme() == "explicit")                                                  \
    GTEST_SKIP() << "a long multi-D repeat: runs with the semi-implicit step only (CI's 45 minutes; " \
                    "docs/verification.md, \"Both time schemes\")"

inline void applyTestScheme(CaseConfig& c) {
    const std::string s = testScheme();
    if (s == "semi_implicit") c.time.scheme = TimeScheme::SemiImplicit;
    else if (s == "explicit") c.time.scheme = TimeScheme::Explicit;
    else throw std::runtime_error("QUICKSAND_TEST_SCHEME = '" + s + "': expected explicit or semi_implicit");
    // the problem's water stays the case's under both schemes (docs/verification.md, "Both time
    // schemes"): the semi-implicit scheme's own default, real water, is not the problem's
    c.liquid.bulkModulusGiven = true;
}

inline CaseConfig loadVerificationCase(const std::string& name) {
    CaseConfig c = loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/" + name);
    applyTestScheme(c);
    return c;
}

/// Runs a loaded case in memory, keeping every output, until `seen` holds for what was kept so
/// far (checked after each output): a test that measures when something first happens stops
/// watching there, and what the run does afterwards (a pipe blowing out over the rim) neither
/// costs time nor ends it.
inline CaseRun runConfigWhile(const CaseConfig& config, const std::function<bool(const CaseRun&)>& seen) {
    struct Seen {};
    CaseRun run;
    run.config = config;
    RunOptions options;
    options.quiet = true;
    options.writeFiles = false;
    options.onPipes = [&](double, const SandCells& cells, const PipeSurvey& survey) {
        run.cells.push_back(cells);
        run.pipes.push_back(survey);
    };
    options.onOutput = [&](const ColumnState& s, const std::vector<CellRow>& rows) {  // after onPipes
        run.series.push_back(s);
        run.profiles.push_back(rows);
        if (seen && seen(run)) throw Seen{};
    };
    try {
        run.summary = runCase(run.config, options);
    } catch (const Seen&) {
    }
    return run;
}

/// As runConfigWhile, watching the cells' sand state (2D/3D) at each output.
inline CaseRun runConfigUntil(const CaseConfig& config, const std::function<bool(const SandCells&)>& seen) {
    if (!seen) return runConfigWhile(config, {});
    return runConfigWhile(config, [&](const CaseRun& run) { return !run.cells.empty() && seen(run.cells.back()); });
}

/// Runs a loaded case in memory to its end, keeping every output.
inline CaseRun runConfig(const CaseConfig& config) { return runConfigUntil(config, {}); }

/// Runs the case; `edit` may change the loaded config first (e.g. break the physics on purpose).
inline CaseRun runVerificationCase(const std::string& name,
                                   const std::function<void(CaseConfig&)>& edit = {}) {
    CaseConfig config = loadVerificationCase(name);
    if (edit) edit(config);
    return runConfig(config);
}

/// Rows holding sand (solid points) and lying fully inside the sand column.
inline std::vector<CellRow> sandRows(const std::vector<CellRow>& rows) {
    std::vector<CellRow> out;
    for (const auto& r : rows)
        if (r.solidCount > 0) out.push_back(r);
    return out;
}

/// Least-squares line y = a + b z through (z, f(row)); returns {a, b}.
template <class F>
std::pair<double, double> fitLine(const std::vector<CellRow>& rows, F f) {
    double sz = 0, sy = 0, szz = 0, szy = 0;
    const double n = static_cast<double>(rows.size());
    for (const auto& r : rows) {
        const double y = f(r);
        sz += r.z; sy += y; szz += r.z * r.z; szy += r.z * y;
    }
    const double b = (n * szy - sz * sy) / (n * szz - sz * sz);
    return {(sy - b * sz) / n, b};
}

/// Least-squares line f(state) = a + b t over the outputs with t0 <= t <= t1, with its r^2.
struct LineFit { double intercept = 0, slope = 0, r2 = 0; int points = 0; };
template <class F>
LineFit fitOverTime(const std::vector<ColumnState>& series, double t0, double t1, F f) {
    double st = 0, sy = 0, stt = 0, sty = 0, syy = 0;
    LineFit fit;
    for (const auto& s : series) {
        if (s.time < t0 || s.time > t1) continue;
        const double y = f(s);
        st += s.time; sy += y; stt += s.time * s.time; sty += s.time * y; syy += y * y;
        ++fit.points;
    }
    const double n = fit.points;
    if (n < 3) return fit;
    fit.slope = (n * sty - st * sy) / (n * stt - st * st);
    fit.intercept = (sy - fit.slope * st) / n;
    const double ssTot = syy - sy * sy / n;
    const double ssRes = syy - fit.intercept * sy - fit.slope * sty;
    fit.r2 = ssTot > 0 ? 1 - ssRes / ssTot : 0;
    return fit;
}

/// The geometries every 1D verification problem is repeated in (issue 7): a 2D plane-strain
/// column, an axisymmetric cylinder and a 3D square column, each `across` cells wide (in
/// axisymmetry: in radius). The column stays laterally uniform, so the 1D closed form holds
/// unchanged; the 2D and 3D columns then reproduce the 1D run (and show no lateral mode), the
/// axisymmetric one weighs every ring by its radius. Lateral physics proper is tested by the
/// laterally non-uniform columns of test_LateralPhysics.cpp and by test_Axisymmetry.cpp.
enum class Geometry { Plane2D, Axisymmetric, ThreeD };

inline std::string geometryName(const ::testing::TestParamInfo<Geometry>& info) {
    switch (info.param) {
        case Geometry::Plane2D: return "Plane2D";
        case Geometry::Axisymmetric: return "Axisymmetric";
        case Geometry::ThreeD: return "ThreeD";
    }
    return "unknown";
}

inline const auto kGeometries = ::testing::Values(Geometry::Plane2D, Geometry::Axisymmetric, Geometry::ThreeD);

/// Turns a 1D case into the same column in geometry g, `across` cells wide.
inline void inGeometry(CaseConfig& c, Geometry g, int across = 2) {
    c.grid.width = across * c.grid.cellSize;
    switch (g) {
        case Geometry::Plane2D:
            c.grid.dimension = 2;  // the cross-section stays: area / width is the thickness
            break;
        case Geometry::Axisymmetric:
            c.grid.dimension = 2;
            c.grid.geometry = GridGeometry::Axisymmetric;
            c.grid.crossSectionArea = kPi * c.grid.width * c.grid.width;
            break;
        case Geometry::ThreeD:
            c.grid.dimension = 3;
            c.grid.crossSectionArea = c.grid.width * c.grid.width;
            break;
    }
}

/// The column on cells `factor` times larger where its layers allow it. The chamber keeps at least
/// two cells (one let the sideways flow under the filter reach the gate's lowest points): where it
/// grows, everything above it rises with it, the water, the overflow, the monitors and the
/// reservoir's head, so that every closed form (relative to the filter and the overflow) holds
/// unchanged. The water level, the overflow and the grid's top are rounded up to whole cells (the
/// water above the sand only). Returns whether it coarsened.
inline bool coarsen(CaseConfig& c, int factor) {
    const double h = c.grid.cellSize * factor;
    auto whole = [h](double length) { return std::abs(length / h - std::round(length / h)) < 1e-9 * (length / h + 1); };
    for (const auto& l : c.layers)
        if (!whole(l.thickness)) return false;
    auto up = [h](double z) { return std::ceil(z / h - 1e-9) * h; };
    const double rise = std::max(up(c.column.chamberHeight), 2 * h) - c.column.chamberHeight;
    c.grid.cellSize = h;
    c.column.chamberHeight += rise;
    const double water = up(c.column.waterLevel + rise);
    c.reservoir.head += water - c.column.waterLevel;  // the same head over the water (the overflow)
    if (c.column.overflowLevel) c.column.overflowLevel = water;
    c.column.waterLevel = water;
    c.column.top = up(c.column.top + rise);
    if (c.column.top <= water + 1e-9 * h) c.column.top = water + h;
    for (auto& m : c.monitors) m.elevation += rise;
    return true;
}

/// Whether the case runs on its shipped grid (the guards near what is achieved hold there only).
inline bool onShippedGrid(const CaseConfig& c) {
    const CaseConfig shipped = loadCase(c.caseDirectory);
    return std::abs(shipped.grid.cellSize - c.grid.cellSize) <= 1e-12 * shipped.grid.cellSize;
}

/// The geometry of a parametrized verification test: `across` cells wide, and in 3D on cells
/// twice as large where the levels allow (a 2 x 2 column of 3D points costs about 16 times the 1D
/// run of the same column; the 1D tolerances hold on the coarser cells).
inline void inTestGeometry(CaseConfig& c, Geometry g, int across = 2) {
    if (g == Geometry::ThreeD) coarsen(c, 2);
    inGeometry(c, g, across);
}

/// Mean of f(state) over the outputs with t >= t0.
template <class F>
double meanAfter(const std::vector<ColumnState>& series, double t0, F f) {
    double s = 0;
    int n = 0;
    for (const auto& st : series)
        if (st.time >= t0) { s += f(st); ++n; }
    return n > 0 ? s / n : 0.0;
}

}  // namespace qs::test
