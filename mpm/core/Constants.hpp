#pragma once
// Mathematical constants shared by every part of quicksand (no dependencies, so that the input
// layer can use them without the numeric types).

namespace qs {

constexpr double kPi = 3.14159265358979323846;

}  // namespace qs
