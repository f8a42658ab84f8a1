#pragma once
// PiecewiseLinear: a function given by a table of points (x_k, y_k), x strictly increasing,
// linear between them and constant beyond the first and the last. A head schedule h(t) and a
// reservoir's plan area by level A(h) are both written this way in case.toml.
//
//   PiecewiseLinear head({{0, 0.30}, {60, 0.30}, {61, 0.32}});
//   head(30.0);  // 0.30
//   head(60.5);  // 0.31
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/Error.hpp"

namespace qs {

class PiecewiseLinear {
public:
    using Points = std::vector<std::pair<double, double>>;

    PiecewiseLinear() = default;
    explicit PiecewiseLinear(Points points) : points_(std::move(points)) {
        QS_CHECK(!points_.empty(), "a table needs at least one (x, y) point");
        for (std::size_t k = 1; k < points_.size(); ++k)
            QS_CHECK(points_[k].first > points_[k - 1].first,
                     "a table's x values must increase strictly; row " << k << " has x = " << points_[k].first
                                                                       << " after " << points_[k - 1].first);
    }

    bool empty() const { return points_.empty(); }
    const Points& points() const { return points_; }

    double operator()(double x) const {
        if (x <= points_.front().first) return points_.front().second;
        if (x >= points_.back().first) return points_.back().second;
        const std::size_t k = segmentOf(x);
        const auto& [x0, y0] = points_[k];
        const auto& [x1, y1] = points_[k + 1];
        return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
    }

    /// The segment [x_k, x_{k+1}] holding x, for x inside the table
    std::size_t segmentOf(double x) const {
        const auto it = std::upper_bound(points_.begin(), points_.end(), x,
                                         [](double v, const std::pair<double, double>& p) { return v < p.first; });
        return std::min<std::size_t>(std::max<std::ptrdiff_t>(it - points_.begin() - 1, 0), points_.size() - 2);
    }

private:
    Points points_;
};

}  // namespace qs
