#pragma once
// Basic numeric types shared by every part of quicksand.
//
// The spatial dimension D of the background grid is a template parameter (1, 2 or 3). The last
// grid axis is always the vertical one (gravity points along -e_{D-1}). Constitutive models work
// on full 3D tensors whatever D is, see materials/StressTensor.hpp.
#include <Eigen/Core>
#include <array>
#include <cstdint>

#include "core/Constants.hpp"

namespace qs {

using Real = double;
using Index = std::int64_t;

template <int D>
using Vec = Eigen::Matrix<Real, D, 1>;

template <int D>
using IVec = std::array<Index, D>;

/// The vertical axis of a D-dimensional grid.
template <int D>
constexpr int verticalAxis() { return D - 1; }

}  // namespace qs
