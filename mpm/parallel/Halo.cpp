#include "parallel/Halo.hpp"

#include <algorithm>

namespace qs {

namespace {

/// The global nodes two local grids both hold: the box [max of begins, min of ends] per axis,
/// listed with axis 0 fastest (ascending global index on both sides, so both list them alike).
template <int D>
std::vector<IVec<D>> commonNodes(const Subdomain<D>& a, const Subdomain<D>& b) {
    IVec<D> lo, hi;
    for (int k = 0; k < D; ++k) {
        lo[k] = std::max(a.localBegin()[k], b.localBegin()[k]);
        hi[k] = std::min(a.localBegin()[k] + a.local()[k], b.localBegin()[k] + b.local()[k]);
        if (lo[k] > hi[k]) return {};
    }
    std::vector<IVec<D>> nodes;
    IVec<D> n = lo;
    while (true) {
        nodes.push_back(n);
        int k = 0;
        while (k < D && ++n[k] > hi[k]) n[k] = lo[k], ++k;
        if (k == D) break;
    }
    return nodes;
}

}  // namespace

template <int D>
Halo<D>::Halo(const Decomposition& d, const Subdomain<D>& mine, const Communicator& comm) : comm_(comm) {
    const int me = mine.rank();
    // per local shared node, its holders' (rank, slot, offset), gathered neighbour by neighbour
    std::vector<std::vector<std::pair<int, Source>>> holders(static_cast<std::size_t>(mine.localNodes()));
    for (int r = 0; r < d.ranks; ++r) {
        if (r == me) continue;
        const Subdomain<D> other(d, r);
        const std::vector<IVec<D>> common = commonNodes(mine, other);
        if (common.empty()) continue;
        const int slot = static_cast<int>(neighbours_.size());
        neighbours_.push_back(r);
        sharedWith_.emplace_back();
        ownedFor_.emplace_back();
        ghostsFrom_.emplace_back();
        for (const IVec<D>& n : common) {
            const Index local = mine.localNode(n);
            holders[static_cast<std::size_t>(local)].push_back({r, Source{slot, Index(sharedWith_.back().size())}});
            sharedWith_.back().push_back(local);
            const int owner = mine.ownerOfNode(n);
            if (owner == me) ownedFor_.back().push_back(local);
            else if (owner == r) ghostsFrom_.back().push_back(local);
        }
    }
    sourceStart_.push_back(0);
    for (Index i = 0; i < mine.localNodes(); ++i) {
        auto& h = holders[static_cast<std::size_t>(i)];
        if (h.empty()) continue;
        h.push_back({me, Source{-1, i}});
        std::sort(h.begin(), h.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        shared_.push_back(i);
        for (const auto& e : h) sources_.push_back(e.second);
        sourceStart_.push_back(static_cast<Index>(sources_.size()));
    }
    send_.resize(neighbours_.size());
    recv_.resize(neighbours_.size());
}

template <int D>
std::size_t Halo<D>::valuesPerExchange() const {
    std::size_t n = 0;
    for (const auto& s : sharedWith_) n += s.size();
    return n;
}

template <int D>
void Halo<D>::sumShared(std::vector<Real>& field, int components) {
    if (neighbours_.empty()) return;
    const std::size_t nc = static_cast<std::size_t>(components);
    for (std::size_t k = 0; k < neighbours_.size(); ++k) {
        const auto& list = sharedWith_[k];
        send_[k].resize(list.size() * nc);
        recv_[k].resize(list.size() * nc);
        for (std::size_t j = 0; j < list.size(); ++j)
            for (std::size_t c = 0; c < nc; ++c) send_[k][j * nc + c] = field[static_cast<std::size_t>(list[j]) * nc + c];
    }
    comm_.exchange(neighbours_, send_, recv_);
    // the sums first, then written: a node's own value is read before any is overwritten
    totals_.resize(shared_.size() * nc);
    for (std::size_t s = 0; s < shared_.size(); ++s)
        for (std::size_t c = 0; c < nc; ++c) {
            double total = 0;
            for (Index k = sourceStart_[s]; k < sourceStart_[s + 1]; ++k) {
                const Source& src = sources_[static_cast<std::size_t>(k)];
                total += src.slot < 0 ? field[static_cast<std::size_t>(src.offset) * nc + c]
                                      : recv_[static_cast<std::size_t>(src.slot)][static_cast<std::size_t>(src.offset) * nc + c];
            }
            totals_[s * nc + c] = total;
        }
    for (std::size_t s = 0; s < shared_.size(); ++s)
        for (std::size_t c = 0; c < nc; ++c) field[static_cast<std::size_t>(shared_[s]) * nc + c] = totals_[s * nc + c];
}

template <int D>
void Halo<D>::fillGhosts(std::vector<Real>& field, int components) {
    if (neighbours_.empty()) return;
    const std::size_t nc = static_cast<std::size_t>(components);
    for (std::size_t k = 0; k < neighbours_.size(); ++k) {
        send_[k].resize(ownedFor_[k].size() * nc);
        recv_[k].resize(ghostsFrom_[k].size() * nc);
        for (std::size_t j = 0; j < ownedFor_[k].size(); ++j)
            for (std::size_t c = 0; c < nc; ++c)
                send_[k][j * nc + c] = field[static_cast<std::size_t>(ownedFor_[k][j]) * nc + c];
    }
    comm_.exchange(neighbours_, send_, recv_);
    for (std::size_t k = 0; k < neighbours_.size(); ++k)
        for (std::size_t j = 0; j < ghostsFrom_[k].size(); ++j)
            for (std::size_t c = 0; c < nc; ++c)
                field[static_cast<std::size_t>(ghostsFrom_[k][j]) * nc + c] = recv_[k][j * nc + c];
}

template class Halo<1>;
template class Halo<2>;
template class Halo<3>;

}  // namespace qs
