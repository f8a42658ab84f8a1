#pragma once
// Operations shared by SolidPoints and LiquidPoints, written once over their fields.
//
// A point set is a structure of arrays: one contiguous std::vector per field, `components`
// values per point. Each set lists its persistent fields in forEachField(f), which calls
// f(vector, FieldSpec): this list is the point fields' registry. Everything that handles a
// point's state goes through it: resize, reorder, append and remove here, the checkpoint (each
// field an entry named by the spec: solver/SolverCheckpoint.cpp), the field output (the fields
// flagged written, under the same name: solver/Run.cpp), the memory estimate (bytesPerPoint,
// solver/RunSize.cpp) and, over MPI ranks, the packing of the points that move to another rank.
// A new field is added in one place. Capacity is reserved up front: inside the time loop these
// operations never allocate as long as the count stays below the reserved capacity.
#include <algorithm>
#include <vector>

#include "core/ForAll.hpp"
#include "core/Types.hpp"

namespace qs {

/// What the registry says of one point field (forEachField's second argument).
struct FieldSpec {
    /// The field's name, a physical one ("velocity", "pore_pressure"): the checkpoint's entry is
    /// SET/NAME, fields.h5's dataset NAME.
    const char* name;
    int components;              ///< values per point (0: the field is empty for this run)
    bool written = false;        ///< in fields.h5 at every output (integers as doubles)
    bool vector = false;         ///< one value per axis: padded to 3 in the output, as positions are
    /// Non-null for a field added after checkpoints were first written: the date it came, and
    /// what an older checkpoint, which has none, starts it with (zeros).
    const char* since = nullptr;
};

/// Per-point shape-function cache, recomputed every step from the positions: the cell holding
/// the point and, for uGIMP only, the stencil's origin node and per-axis weights (see
/// grid/ShapeFunctions.hpp). Linear weights are cheaper to take from the position where they are
/// used than to store and load (grid/LinearStencil.hpp), so a linear run keeps only the cells.
template <int D>
struct ShapeCache {
    std::vector<Index> cell;    ///< cell holding the point
    std::vector<Index> start;   ///< flat index of the stencil's first node (uGIMP)
    std::vector<Real> w, dw;    ///< [point][axis][3] (uGIMP)
    bool weights = true;        ///< whether start, w and dw are kept
    void resize(std::size_t n) {
        cell.resize(n);
        if (!weights) return;
        start.resize(n);
        w.resize(n * D * 3);
        dw.resize(n * D * 3);
    }
    void reserve(std::size_t n) {
        cell.reserve(n);
        if (!weights) return;
        start.reserve(n);
        w.reserve(n * D * 3);
        dw.reserve(n * D * 3);
    }
};

/// Scratch for reordering fields, sized once.
struct ReorderScratch {
    std::vector<Real> reals;
    std::vector<int> ints;
    std::vector<Index> order;
};

template <class Set>
void resizePoints(Set& set, std::size_t n) {
    set.forEachField([n](auto& field, const FieldSpec& f) { field.resize(n * f.components); });
}

template <class Set>
void reservePoints(Set& set, std::size_t n, ReorderScratch& scratch, int maxComponents) {
    set.forEachField([n](auto& field, const FieldSpec& f) { field.reserve(n * f.components); });
    scratch.reals.reserve(n * maxComponents);
    scratch.ints.reserve(n * maxComponents);
    scratch.order.reserve(n);
}

namespace detail {
template <class T>
std::vector<T>& scratchFor(ReorderScratch& s);
template <>
inline std::vector<Real>& scratchFor<Real>(ReorderScratch& s) { return s.reals; }
template <>
inline std::vector<int>& scratchFor<int>(ReorderScratch& s) { return s.ints; }
}  // namespace detail

/// Reorders every field so that new point k is old point order[k]. In parallel, with the points
/// split as every other loop over them splits them (core/ForAll.hpp): each thread writes the
/// points it will update next. (Serial, the whole set went through one core's cache, and the
/// other core fetched its half from there in the next phase.)
template <class Set>
void reorderPoints(Set& set, const std::vector<Index>& order, ReorderScratch& scratch) {
    const Index n = static_cast<Index>(order.size());
    set.forEachField([&](auto& field, const FieldSpec& f) {
        using T = typename std::decay_t<decltype(field)>::value_type;
        const int components = f.components;
        if (components == 0) return;  // a field of no components (no constitutive state)
        auto& tmp = detail::scratchFor<T>(scratch);
        tmp.resize(n * components);
        forAll(n, [&](Index k) {
            for (int c = 0; c < components; ++c) tmp[k * components + c] = field[order[k] * components + c];
        });
        // copy back rather than swap: the scratch keeps its capacity and nothing reallocates
        forAll(n, [&](Index k) {
            for (int c = 0; c < components; ++c) field[k * components + c] = tmp[k * components + c];
        });
    });
}

/// Removes the points whose drop flag is set, keeping the order of the others (so a sorted set
/// stays sorted). `drop` has one entry per point from `first` on and is owned by the caller (no
/// allocation here); the points before `first` stay and are not touched (rewritten in place by
/// one thread, they would all move to its core's cache: core/ForAll.hpp).
template <class Set>
std::size_t compactPoints(Set& set, const std::vector<char>& drop, std::size_t first = 0) {
    const std::size_t n = set.size();
    std::size_t kept = n;
    set.forEachField([&](auto& field, const FieldSpec& f) {
        const int components = f.components;
        std::size_t out = first;
        for (std::size_t p = first; p < n; ++p) {
            if (drop[p]) continue;
            for (int c = 0; c < components; ++c) field[out * components + c] = field[p * components + c];
            ++out;
        }
        field.resize(out * components);
        kept = out;
    });
    return n - kept;
}

/// Bytes of persistent state per point: what a checkpoint holds of it, and what a point that
/// moves to another rank carries. (A set's internalCount must be set: it sizes one field.)
template <class Set>
double bytesPerPoint(const Set& set) {
    double bytes = 0;
    set.forEachField([&](auto& field, const FieldSpec& f) {
        bytes += double(sizeof(typename std::decay_t<decltype(field)>::value_type)) * f.components;
    });
    return bytes;
}

}  // namespace qs
