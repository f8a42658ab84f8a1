#include "case/Range.hpp"

#include <cmath>
#include <utility>

#include "case/MessageText.hpp"

namespace qs {

std::string Range::describe() const {
    const bool hasLo = std::isfinite(lo), hasHi = std::isfinite(hi);
    std::string text;
    if (hasLo && hasHi)
        text = std::string("in ") + (loOpen ? "(" : "[") + number(lo) + ", " + number(hi) + (hiOpen ? ")" : "]");
    else if (hasLo)
        text = (loOpen ? "> " : ">= ") + number(lo);
    else if (hasHi)
        text = (hiOpen ? "< " : "<= ") + number(hi);
    else
        text = "any finite number";
    return text + (unit.empty() ? "" : " " + unit);
}

Range positive(std::string unit) {
    return {0.0, std::numeric_limits<double>::infinity(), true, false, std::move(unit)};
}
Range nonNegative(std::string unit) {
    return {0.0, std::numeric_limits<double>::infinity(), false, false, std::move(unit)};
}
Range anyValue(std::string unit) {
    return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), false, false,
            std::move(unit)};
}
Range between(double lo, bool loOpen, double hi, bool hiOpen, std::string unit) {
    return {lo, hi, loOpen, hiOpen, std::move(unit)};
}

}  // namespace qs
