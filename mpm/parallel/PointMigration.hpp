#pragma once
// PointMigration<D>: after the points move, those whose cell another rank's block holds go to
// that rank, every field with them.
//
//   PointMigration<2> migration(subdomain, halo.neighbours(), grid.h());
//   migration.migrate(solid, world);    // packed and unpacked through the set's registry
//   migration.migrate(liquid, world);
//
// A point carries every field its set's registry lists (points/PointSet.hpp, forEachField), in
// that order, integers as doubles (exact below 2^53). The points that stay keep their order; the
// arrivals are appended in the senders' rank order, each sender's in its own order, so the same
// N gives the same point order, run after run. A point can only have moved into a neighbour's
// block (a step moves none further than a cell: the health check); one found beyond stops the
// run, naming it. A point's cell is found as the Grid finds it (x times 1/h, Grid::cellAlong),
// so that a point on a cut face is filed in the same cell by the rank it goes to. Per-point
// scratch outside the registry (shape-function caches, the stress return's code) is not carried:
// it is stale after a migration until the step rebuilds it (sortPoints), and must be resized
// before anything reads it.
#include <cmath>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "core/Types.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/PointPacking.hpp"
#include "parallel/Subdomain.hpp"
#include "points/PointSet.hpp"

namespace qs {

struct MigrationCount {
    std::size_t sent = 0, received = 0;
};

template <int D>
class PointMigration {
public:
    PointMigration(const Subdomain<D>& mine, const std::vector<int>& neighbours, Real h)
        : mine_(mine), neighbours_(neighbours), invH_(1 / h), send_(neighbours.size()), recv_(neighbours.size()),
          countsOut_(neighbours.size(), std::vector<double>(1)), countsIn_(neighbours.size(), std::vector<double>(1)) {}

    template <class Set>
    MigrationCount migrate(Set& set, const Communicator& comm) {
        MigrationCount count;
        const std::size_t n = set.size();
        const std::size_t width = packedWidth(set);
        drop_.assign(n, 0);
        for (auto& s : send_) s.clear();
        for (std::size_t p = 0; p < n; ++p) {
            const int owner = mine_.ownerOfCell(cellOf(&set.x[p * D]));
            if (owner == mine_.rank()) continue;
            const int slot = slotOf(owner);
            QS_CHECK(slot >= 0, "rank " << mine_.rank() << ": a point at " << describe(&set.x[p * D])
                                        << " has left for rank " << owner
                                        << ", which is not a neighbour: it moved past the ghost cells in one step");
            packPoint(set, p, send_[static_cast<std::size_t>(slot)]);
            drop_[p] = 1;
            ++count.sent;
        }
        for (std::size_t k = 0; k < neighbours_.size(); ++k) countsOut_[k][0] = double(send_[k].size() / width);
        comm.exchange(neighbours_, countsOut_, countsIn_);
        for (std::size_t k = 0; k < neighbours_.size(); ++k)
            recv_[k].resize(static_cast<std::size_t>(countsIn_[k][0]) * width);
        comm.exchange(neighbours_, send_, recv_);
        if (count.sent > 0) compactPoints(set, drop_);
        for (std::size_t k = 0; k < neighbours_.size(); ++k) {
            unpackPoints(set, recv_[k], width);
            count.received += recv_[k].size() / width;
        }
        return count;
    }

private:
    IVec<D> cellOf(const Real* x) const {
        IVec<D> k;
        for (int a = 0; a < D; ++a) {
            const Real u = x[a] * invH_;  // as Grid::cellAlong: the same cell on every rank
            const Index last = mine_.globalCells()[a] - 1;
            k[a] = !(u >= 0) ? 0 : (u >= static_cast<Real>(last) ? last : static_cast<Index>(u));
        }
        return k;
    }
    int slotOf(int rank) const {
        for (std::size_t k = 0; k < neighbours_.size(); ++k)
            if (neighbours_[k] == rank) return static_cast<int>(k);
        return -1;
    }
    std::string describe(const Real* x) const {
        std::string s = "(";
        for (int a = 0; a < D; ++a) s += (a ? ", " : "") + std::to_string(x[a]);
        return s + ") m";
    }

    const Subdomain<D>& mine_;
    std::vector<int> neighbours_;
    Real invH_;
    std::vector<std::vector<double>> send_, recv_, countsOut_, countsIn_;
    std::vector<char> drop_;
};

}  // namespace qs
