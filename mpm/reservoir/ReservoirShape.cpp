#include "reservoir/ReservoirShape.hpp"

#include <cmath>

namespace qs {

ReservoirShape ReservoirShape::prismatic(double area) {
    QS_CHECK(area > 0, "a reservoir's plan area must be > 0 m2, got " << area);
    ReservoirShape s;
    s.area_ = area;
    return s;
}

ReservoirShape ReservoirShape::table(const PiecewiseLinear::Points& rows) {
    QS_CHECK(rows.size() >= 2, "a reservoir's area table needs at least two (level, area) rows");
    for (const auto& [h, a] : rows) QS_CHECK(a > 0, "a reservoir's plan area must be > 0 m2, got " << a << " at level " << h);
    ReservoirShape s;
    s.prismatic_ = false;
    s.areaOf_ = PiecewiseLinear(rows);
    s.volumeAt_.assign(rows.size(), 0.0);
    for (std::size_t k = 1; k < rows.size(); ++k)  // trapezoids: A is linear between rows
        s.volumeAt_[k] = s.volumeAt_[k - 1] + 0.5 * (rows[k].second + rows[k - 1].second) * (rows[k].first - rows[k - 1].first);
    return s;
}

double ReservoirShape::volumeBelow(double h) const {
    if (prismatic_) return area_ * h;
    const auto& rows = areaOf_.points();
    if (h <= rows.front().first) return rows.front().second * (h - rows.front().first);
    if (h >= rows.back().first) return volumeAt_.back() + rows.back().second * (h - rows.back().first);
    const std::size_t k = areaOf_.segmentOf(h);
    return volumeAt_[k] + 0.5 * (rows[k].second + areaOf_(h)) * (h - rows[k].first);
}

double ReservoirShape::levelOf(double volume) const {
    if (prismatic_) return volume / area_;
    const auto& rows = areaOf_.points();
    if (volume <= 0) return rows.front().first + volume / rows.front().second;
    if (volume >= volumeAt_.back()) return rows.back().first + (volume - volumeAt_.back()) / rows.back().second;
    std::size_t k = 0;
    while (volumeAt_[k + 1] < volume) ++k;
    // on the segment A = a + s (h - h_k): V - V_k = a d + s d^2 / 2, d = h - h_k; the root
    // written without the cancellation of -a + sqrt(a^2 + 2 s dV) when s is small
    const double a = rows[k].second, slope = (rows[k + 1].second - a) / (rows[k + 1].first - rows[k].first);
    const double dV = volume - volumeAt_[k];
    const double d = 2 * dV / (a + std::sqrt(a * a + 2 * slope * dV));
    return rows[k].first + d;
}

double ReservoirShape::levelAfter(double h, double volumeOut) const {
    // a prismatic reservoir as it always was, to the last bit: h - Q dt / A
    if (prismatic_) return h - volumeOut / area_;
    return levelOf(volumeBelow(h) - volumeOut);
}

}  // namespace qs
