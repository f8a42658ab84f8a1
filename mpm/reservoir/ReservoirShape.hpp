#pragma once
// ReservoirShape: the plan area of an upstream reservoir as a function of its level, A(h), and
// the level balance it gives, A(h) dh/dt = -Q. A prismatic reservoir (one area) or a table of
// (level, area), linear between its rows and prismatic beyond them (reservoir.area_table,
// docs/case-format.md): a cone, a tank with a narrower standpipe on top, a sloping lake bank.
//
// The level moves by volume, not by dh = -Q dt / A(h): the volume held between the lowest
// table level and h, V(h) = integral A dh (quadratic on each segment), loses Q dt, and the new
// level is V's inverse. So the water that crossed the gate leaves the reservoir exactly,
// whatever the step, even where the area changes within one step.
//
//   ReservoirShape cone = ReservoirShape::table({{0.2, 1e-4}, {0.4, 4e-4}});
//   double h = cone.levelAfter(0.35, Q * dt);   // the level after Q dt has left
#include "core/PiecewiseLinear.hpp"

namespace qs {

class ReservoirShape {
public:
    /// One plan area, m2 (> 0)
    static ReservoirShape prismatic(double area);
    /// Rows of (level m above the gate plane, plan area m2 > 0), levels strictly increasing
    static ReservoirShape table(const PiecewiseLinear::Points& rows);

    /// m2, the plan area at level h (m)
    double area(double h) const { return prismatic_ ? area_ : areaOf_(h); }
    /// m3, the volume between the table's lowest level (0 for a prismatic one) and h; negative below
    double volumeBelow(double h) const;
    /// m, the level that holds volume V (m3), volumeBelow's inverse
    double levelOf(double volume) const;
    /// m, the level after `volumeOut` (m3; negative: inflow) has left from level h
    double levelAfter(double h, double volumeOut) const;
    bool isPrismatic() const { return prismatic_; }
    /// m, where the reservoir is empty: its table's first level (0, the gate plane, if prismatic)
    double lowestLevel() const { return prismatic_ ? 0.0 : areaOf_.points().front().first; }

private:
    bool prismatic_ = true;
    double area_ = 0;
    PiecewiseLinear areaOf_;
    std::vector<double> volumeAt_;  ///< m3, volumeBelow at each table level
};

}  // namespace qs
