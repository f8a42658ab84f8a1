#pragma once
// Points packed for another rank: every field its set's registry lists (points/PointSet.hpp,
// forEachField), in that order, integers as doubles (exact below 2^53). PointMigration and
// RankShare's ghost copies send points so.
#include <cstddef>
#include <type_traits>
#include <vector>

#include "points/PointSet.hpp"

namespace qs {

/// Values a packed point takes.
template <class Set>
std::size_t packedWidth(const Set& set) {
    std::size_t w = 0;
    set.forEachField([&](const auto&, const FieldSpec& f) { w += static_cast<std::size_t>(f.components); });
    return w;
}

/// Appends point p's fields to out.
template <class Set>
void packPoint(const Set& set, std::size_t p, std::vector<double>& out) {
    set.forEachField([&](const auto& field, const FieldSpec& f) {
        for (int c = 0; c < f.components; ++c) out.push_back(static_cast<double>(field[p * f.components + c]));
    });
}

/// Appends the `count` points packed in `in` to the set (in their order).
template <class Set>
void unpackPoints(Set& set, const std::vector<double>& in, std::size_t width) {
    const std::size_t count = width > 0 ? in.size() / width : 0;
    const std::size_t first = set.size();
    resizePoints(set, first + count);
    std::size_t at = 0;
    for (std::size_t q = 0; q < count; ++q)
        set.forEachField([&](auto& field, const FieldSpec& f) {
            using T = typename std::decay_t<decltype(field)>::value_type;
            for (int c = 0; c < f.components; ++c) field[(first + q) * f.components + c] = static_cast<T>(in[at++]);
        });
}

/// Packs the points `which` (indices into the set) field by field: each field's values of all
/// of them, then the next field's (the registry's order). `out` is resized, so it allocates
/// nothing once it has held as many. unpackPointsByField reads it.
template <class Set, class Indices>
void packPointsByField(const Set& set, const Indices& which, std::vector<double>& out) {
    out.resize(which.size() * packedWidth(set));
    std::size_t at = 0;
    set.forEachField([&](const auto& field, const FieldSpec& f) {
        const std::size_t components = static_cast<std::size_t>(f.components);
        for (const auto p : which)
            for (std::size_t c = 0; c < components; ++c)
                out[at++] = static_cast<double>(field[static_cast<std::size_t>(p) * components + c]);
    });
}

/// Appends the points packed by packPointsByField (`width` values a point) to the set, in their
/// order.
template <class Set>
void unpackPointsByField(Set& set, const std::vector<double>& in, std::size_t width) {
    const std::size_t count = width > 0 ? in.size() / width : 0;
    const std::size_t first = set.size();
    resizePoints(set, first + count);
    std::size_t at = 0;
    set.forEachField([&](auto& field, const FieldSpec& f) {
        using T = typename std::decay_t<decltype(field)>::value_type;
        const std::size_t components = static_cast<std::size_t>(f.components);
        for (std::size_t q = 0; q < count; ++q)
            for (std::size_t c = 0; c < components; ++c) field[(first + q) * components + c] = static_cast<T>(in[at++]);
    });
}

}  // namespace qs
