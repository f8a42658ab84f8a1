#pragma once
// Halo<D>: the nodes a rank shares with its neighbours, and the two exchanges a step makes over
// them (ExaMPM's scatter and gather halos).
//
//   Halo<2> halo(decomposition, subdomain, world);
//   ... each rank scatters its own points to its local nodes ...
//   halo.sumShared(nodes.massS, 1);      // every holder of a node gets the sum of all holders'
//   halo.sumShared(nodes.momS, 2);       // shares: the grid as one rank would have it
//   ... the node loop, on owned and ghost nodes alike ...
//   halo.fillGhosts(cellField, 1);       // (or a node field computed on owned nodes only)
//
// Reproducible: a shared node's sum is added in rank order, (v_r1 + v_r2) + v_r3 for its holders
// r1 < r2 < r3, by every holder alike, so the holders agree to the bit and two runs at the same N
// give the same bytes. (It differs from one rank's sum, which adds the points in their order, by
// round-off.) The lists are built once; the exchanges allocate nothing after their first call
// with as many components.
#include <vector>

#include "core/Types.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/Decomposition.hpp"
#include "parallel/Subdomain.hpp"

namespace qs {

template <int D>
class Halo {
public:
    Halo(const Decomposition& d, const Subdomain<D>& mine, const Communicator& comm);

    /// The ranks this one shares nodes with, ascending.
    const std::vector<int>& neighbours() const { return neighbours_; }
    /// Nodes of the local grid that another rank holds too.
    std::size_t sharedNodes() const { return shared_.size(); }
    /// Values sent per exchange and component: shared nodes over all neighbours.
    std::size_t valuesPerExchange() const;

    /// field[node * components + c] over the local grid: each shared node's entries become the
    /// sum, in rank order, of every holder's.
    void sumShared(std::vector<Real>& field, int components);
    /// Each ghost node's entries become its owner's.
    void fillGhosts(std::vector<Real>& field, int components);

private:
    struct Source {
        int slot;      ///< the neighbour's slot, -1 for this rank's own value
        Index offset;  ///< the node's place in that neighbour's shared list
    };
    const Communicator& comm_;
    std::vector<int> neighbours_;
    std::vector<std::vector<Index>> sharedWith_;     ///< per slot, local nodes shared, by global index
    std::vector<std::vector<Index>> ownedFor_;       ///< per slot, my owned nodes it holds as ghosts
    std::vector<std::vector<Index>> ghostsFrom_;     ///< per slot, its owned nodes I hold as ghosts
    std::vector<Index> shared_;                      ///< local nodes with another holder
    std::vector<Index> sourceStart_;                 ///< shared_[s]'s sources: [start[s], start[s + 1])
    std::vector<Source> sources_;                    ///< in rank order, this rank among them
    std::vector<std::vector<double>> send_, recv_;   ///< per slot
    std::vector<double> totals_;
};

}  // namespace qs
