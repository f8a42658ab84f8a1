#pragma once
// Runs a shipped verification case (cases/verification/NAME) in memory and keeps what a test
// compares with the closed form: the series at every output time and the cell-row profiles.
#include <functional>
#include <string>
#include <vector>

#include "io/CaseLoader.hpp"
#include "solver/Run.hpp"

namespace qs::test {

struct CaseRun {
    CaseConfig config;
    RunSummary summary;
    std::vector<ColumnState> series;
    std::vector<std::vector<CellRow>> profiles;  ///< one per output time
};

inline CaseConfig loadVerificationCase(const std::string& name) {
    return loadCase(std::string(QUICKSAND_SOURCE_DIR) + "/cases/verification/" + name);
}

/// Runs the case; `edit` may change the loaded config first (e.g. break the physics on purpose).
inline CaseRun runVerificationCase(const std::string& name,
                                   const std::function<void(CaseConfig&)>& edit = {}) {
    CaseRun run;
    run.config = loadVerificationCase(name);
    if (edit) edit(run.config);
    RunOptions options;
    options.quiet = true;
    options.writeFiles = false;
    options.onOutput = [&](const ColumnState& s, const std::vector<CellRow>& rows) {
        run.series.push_back(s);
        run.profiles.push_back(rows);
    };
    run.summary = runCase(run.config, options);
    return run;
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
