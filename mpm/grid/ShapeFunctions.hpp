#pragma once
// Shape functions of the structured grid, evaluated one axis at a time (tensor products).
//
// Every point touches a fixed stencil of 3 nodes per axis, starting at node s: enough for linear
// hats (2 non-zero) and for uGIMP with particle half-length lp <= h/2 (3 non-zero). A fixed
// stencil keeps the transfer loops branch-free and the same for both kinds.
//   linear: N(r) = max(0, 1 - |r|/h)
//   uGIMP (Bardenhagen & Kober 2004), r = x - x_i:
//     |r| < lp            N = 1 - (r^2 + lp^2) / (2 h lp)
//     lp <= |r| < h - lp  N = 1 - |r|/h
//     h - lp <= |r| < h+lp N = (h + lp - |r|)^2 / (4 h lp)
#include <cmath>

#include "core/ModelChoices.hpp"
#include "core/Types.hpp"

namespace qs {

constexpr int kStencil = 3;  ///< nodes per axis touched by one point

struct AxisWeights {
    Index start;             ///< first stencil node along this axis
    Real w[kStencil];        ///< N of the stencil nodes
    Real dw[kStencil];       ///< dN/dx of the stencil nodes (1/m)
};

/// invH is 1 / h (one division per point and axis, not one per node: -1/h is -(1/h) exactly).
inline void linearHat(Real r, Real h, Real invH, Real& N, Real& dN) {
    const Real a = std::abs(r);
    if (a >= h) { N = 0; dN = 0; return; }
    N = 1 - a / h;
    dN = r > 0 ? -invH : invH;
}

inline void linearHat(Real r, Real h, Real& N, Real& dN) { linearHat(r, h, 1.0 / h, N, dN); }

inline void gimpHat(Real r, Real h, Real lp, Real& N, Real& dN) {
    const Real a = std::abs(r);
    const Real sign = r > 0 ? 1.0 : -1.0;
    if (a < lp) {
        N = 1 - (r * r + lp * lp) / (2 * h * lp);
        dN = -r / (h * lp);
    } else if (a < h - lp) {
        N = 1 - a / h;
        dN = -sign / h;
    } else if (a < h + lp) {
        const Real s = h + lp - a;
        N = s * s / (4 * h * lp);
        dN = -sign * s / (2 * h * lp);
    } else {
        N = 0;
        dN = 0;
    }
}

/// The integral of the hat of node 0 from -h to u (m): the hat's running area.
inline Real hatArea(Real u, Real h) {
    if (u <= -h) return 0;
    if (u <= 0) return (u + h) * (u + h) / (2 * h);
    if (u < h) return h - (h - u) * (h - u) / (2 * h);
    return h;
}

/// uGIMP for a particle whose domain [x - lp, x + lp] reaches past the end of the region its
/// material fills: the domain is cut to [a, b] there, and the weights are the mean of each hat
/// over what is left, N_i = (1/(b-a)) int_a^b N_i, with grad N_i = (N_i(b) - N_i(a)) / (b - a)
/// (the mean of the hat's gradient; for the whole domain both are uGIMP's own formulas). So the
/// weights still sum to 1, their gradients to 0, and sum N_i x_i is the cut domain's centre: a
/// point beside a smooth wall keeps the velocity of the grid, where uGIMP's weight beyond the wall
/// was lost and the wall held the point back (partial no-slip).
inline void cutGimpHat(Real node, Real h, Real a, Real b, Real& N, Real& dN) {
    const Real length = b - a;
    N = (hatArea(b - node, h) - hatArea(a - node, h)) / length;
    Real Nb, Na, unused;
    linearHat(b - node, h, Nb, unused);
    linearHat(a - node, h, Na, unused);
    dN = (Nb - Na) / length;
}

/// Weights along one axis for a point at x (m from the grid origin) on an axis with `cells` cells.
/// [lo, hi] (m) is the region the point's material fills along the axis: the grid, or for the sand
/// the part above the filter. A uGIMP domain is cut at its ends (cutGimpHat); linear hats need no
/// cut. A point outside its region by more than lp keeps its whole domain (it cannot be cut to
/// nothing; the sand's transfer drops its weight below the filter, PointsToGrid.cpp).
inline AxisWeights axisWeights(Real x, Real h, Index cells, ShapeFunctionKind kind, Real lp, Real lo, Real hi) {
    AxisWeights a;
    const Real xi = x / h;
    // the cell, floor(xi) clamped to [-1, cells] before the conversion: a point gone to infinity
    // or NaN is the health check's to report, not undefined behaviour here. For xi >= 0 the
    // conversion is the floor (std::floor is a library call without SSE4.1, a tenth of the cost
    // of the shape functions)
    const Index c = xi >= 0 ? (xi < static_cast<Real>(cells) ? static_cast<Index>(xi) : cells) : -1;
    // uGIMP reaches the node below when the point sits in the lower half of its cell.
    Index s = (kind == ShapeFunctionKind::Gimp && xi - c < 0.5) ? c - 1 : c;
    s = s < 0 ? 0 : (s > cells - 2 ? cells - 2 : s);
    a.start = s;
    if (kind == ShapeFunctionKind::Linear) {
        const Real invH = 1.0 / h;
        const Index off = c - s;
        if (off == 0 || off == 1) {
            // inside the grid: only the two nodes of the point's cell, the third is zeroed below.
            // The third hat's test, whether it reaches, is the branch a predictor gets wrong (the
            // point is in the stencil's lower or upper cell), and its division is a third of the work
            linearHat(x - (s + off) * h, h, invH, a.w[off], a.dw[off]);
            linearHat(x - (s + off + 1) * h, h, invH, a.w[off + 1], a.dw[off + 1]);
        } else {  // outside the grid: off is -1 or 2
            for (int k = 0; k < kStencil; ++k) linearHat(x - (s + k) * h, h, invH, a.w[k], a.dw[k]);
        }
        // The hat reaches only the two nodes of the point's cell (the stencil's second and third
        // in the grid's top cell, where s is clamped). In exact arithmetic the third is zero
        // anyway, but with the node positions rounded a point within an ulp below a node could
        // get a third weight of ~1e-16 with a full slope 1/h (the slopes would then no longer sum
        // to zero): it is zeroed. (The solver takes linear weights from grid/LinearStencil.hpp;
        // these per-axis ones are the reference its tests compare with.)
        const int other = off <= 0 ? 2 : 0;
        a.w[other] = a.dw[other] = 0;
        return a;
    }
    const Real from = x - lp > lo ? x - lp : lo, to = x + lp < hi ? x + lp : hi;
    const bool cut = (from > x - lp || to < x + lp) && to - from > 1e-6 * h;
    for (int k = 0; k < kStencil; ++k) {
        const Real node = (s + k) * h;
        if (cut) cutGimpHat(node, h, from, to, a.w[k], a.dw[k]);
        else gimpHat(x - node, h, lp, a.w[k], a.dw[k]);
    }
    return a;
}

}  // namespace qs
