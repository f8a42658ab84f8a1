#pragma once
// Range: the interval a number in an input file must lie in, with its unit. The same object
// checks the value and writes the expectation into the message ("in (0, 1)", "> 0 m", ">= 0 s"),
// so the two cannot disagree.
#include <limits>
#include <string>

namespace qs {

struct Range {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool loOpen = false;
    bool hiOpen = false;
    std::string unit;  ///< "m", "Pa s", ... or empty for dimensionless

    bool contains(double v) const { return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi); }
    /// "in [0, 0.5)", "> 0 m", "<= 0 Pa", "any finite number"
    std::string describe() const;
};

/// (0, inf)
Range positive(std::string unit);
/// [0, inf)
Range nonNegative(std::string unit);
/// (-inf, inf): any finite number
Range anyValue(std::string unit);
/// [lo, hi], (lo, hi), ... as the flags say
Range between(double lo, bool loOpen, double hi, bool hiOpen, std::string unit = "");

}  // namespace qs
