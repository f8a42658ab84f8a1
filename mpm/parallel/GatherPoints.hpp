#pragma once
// The points of every rank on one, for what rank 0 writes alone (fields.h5, the checkpoint): a
// decomposed run's files are laid out as one rank's, and resume on any number of ranks.
//
//   SolidPoints<2> all = gatherPoints(solid, world);   // rank 0: every rank's, in rank order
#include <vector>

#include "parallel/Communicator.hpp"
#include "parallel/PointPacking.hpp"

namespace qs {

/// Every rank's points on `root`, in rank order, each rank's in its own order (elsewhere: none).
/// Collective. A copy of the local set's layout (a solid set's internal state width) is kept.
template <class Set>
Set gatherPoints(const Set& local, const Communicator& comm, int root = 0) {
    const std::size_t width = packedWidth(local);
    std::vector<double> packed;
    packed.reserve(local.size() * width);
    for (std::size_t p = 0; p < local.size(); ++p) packPoint(local, p, packed);
    const std::vector<double> all = comm.gatherv(packed, root);
    Set out = local;  // the layout (internalCount) with it; emptied below
    resizePoints(out, 0);
    if (comm.rank() == root) unpackPoints(out, all, width);
    return out;
}

/// A per-point value beside the registry (a scratch the output shows), gathered as the points are.
template <class T>
std::vector<T> gatherValues(const std::vector<T>& local, const Communicator& comm, int root = 0) {
    const std::vector<double> all = comm.gatherv(std::vector<double>(local.begin(), local.end()), root);
    return std::vector<T>(all.begin(), all.end());
}

}  // namespace qs
