#include "solver/SlabCholesky.hpp"

#include <Eigen/OrderingMethods>
#include <algorithm>
#include <limits>
#include <numeric>

#include "core/Error.hpp"

namespace qs {

namespace {

using Matrix = SlabCholesky::Matrix;
using Permutation = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;

/// The pattern of A restricted to `cells`, in their order (values 1).
Matrix restrictPattern(const Matrix& A, const std::vector<Index>& cells) {
    std::vector<Index> local(A.rows(), -1);
    for (std::size_t i = 0; i < cells.size(); ++i) local[cells[i]] = static_cast<Index>(i);
    std::vector<Eigen::Triplet<double>> entries;
    for (std::size_t j = 0; j < cells.size(); ++j)
        for (Matrix::InnerIterator it(A, cells[j]); it; ++it)
            if (local[it.row()] >= 0) entries.emplace_back(static_cast<int>(local[it.row()]), static_cast<int>(j), 1.0);
    Matrix P(static_cast<Index>(cells.size()), static_cast<Index>(cells.size()));
    P.setFromTriplets(entries.begin(), entries.end());
    return P;
}

/// Eigen's approximate minimum degree order of `cells` within A: order[new] = cells[old]. With
/// cliqueFrom, the cells from that place on are joined all to all first, as the separator's block
/// of the factor will be: AMD then orders the rest for a dense block eliminated last.
std::vector<Index> amdOrder(const Matrix& A, const std::vector<Index>& cells, Index cliqueFrom = -1) {
    Matrix pattern = restrictPattern(A, cells);
    const Index m = static_cast<Index>(cells.size());
    if (cliqueFrom >= 0 && cliqueFrom < m) {
        std::vector<Eigen::Triplet<double>> entries;
        for (Index j = 0; j < m; ++j)
            for (Matrix::InnerIterator it(pattern, j); it; ++it) entries.emplace_back(it.row(), j, 1.0);
        for (Index a = cliqueFrom; a < m; ++a)
            for (Index b = cliqueFrom; b < m; ++b) entries.emplace_back(a, b, 1.0);
        pattern.setFromTriplets(entries.begin(), entries.end());
    }
    Permutation perm;
    Eigen::AMDOrdering<int>()(pattern, perm);
    std::vector<Index> order(cells.size());
    for (std::size_t i = 0; i < cells.size(); ++i) order[i] = cells[perm.indices()[i]];
    return order;
}

}  // namespace

double SlabCholesky::buildPattern(Slab& slab, const Matrix& A) {
    const Index m = static_cast<Index>(slab.cells.size());
    std::vector<Index> local(A.rows(), -1);
    for (Index i = 0; i < m; ++i) local[slab.cells[i]] = i;
    // M's upper triangle, each value first the number of its entry, to find where Eigen put it
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<Index> sourceOfEntry;
    for (Index j = 0; j < m; ++j) {
        const Index c = slab.cells[j];
        for (Index p = A.outerIndexPtr()[c]; p < A.outerIndexPtr()[c + 1]; ++p) {
            const Index i = local[A.innerIndexPtr()[p]];
            if (i < 0 || i > j) continue;
            entries.emplace_back(static_cast<int>(i), static_cast<int>(j), static_cast<double>(sourceOfEntry.size()));
            sourceOfEntry.push_back(p);
        }
    }
    slab.M.resize(m, m);
    slab.M.setFromTriplets(entries.begin(), entries.end());
    slab.M.makeCompressed();
    slab.source.resize(slab.M.nonZeros());
    for (Index p = 0; p < slab.M.nonZeros(); ++p)
        slab.source[p] = sourceOfEntry[static_cast<std::size_t>(slab.M.valuePtr()[p])];
    slab.factor = std::make_unique<InPlaceLDLT>();
    slab.factor->analyzePattern(slab.M);
    // the factor's column counts are set by the analysis; a factorisation of the identity on that
    // pattern makes Eigen's matrixL() readable
    Matrix identity = slab.M;
    for (Index j = 0; j < m; ++j)
        for (Matrix::InnerIterator it(identity, j); it; ++it) it.valueRef() = it.row() == j ? 1.0 : 0.0;
    slab.factor->factorizeInPlace(identity);
    return operationsOf(slab);
}

double SlabCholesky::operationsOf(const Slab& slab) {
    const int* Lp = slab.factor->matrixL().nestedExpression().outerIndexPtr();
    double operations = 0;
    for (Index j = 0; j < slab.M.cols(); ++j) operations += static_cast<double>(Lp[j + 1] - Lp[j]) * (Lp[j + 1] - Lp[j]);
    return operations;
}

SlabCholesky::Slab SlabCholesky::makeSlab(const Matrix& A, const std::vector<Index>& own,
                                          const std::vector<Index>& separators, const std::vector<Index>& globalRank) {
    // Three orders of the slab's own cells, the cheapest kept: AMD on the slab with its
    // separators, which then move last; the same with the separators joined all to all; and the
    // whole matrix's AMD order restricted to the slab. AMD is greedy, and which of them fills
    // least varies from slab to slab: on piping2D's 3.1 mm grid their operations differ by up to
    // 1.9 times, and the best of the three brought the larger slab's from 1.05e6 to 0.73e6
    std::vector<Index> withSeparators = own;
    withSeparators.insert(withSeparators.end(), separators.begin(), separators.end());
    std::vector<Index> isSeparator(A.rows(), 0);
    for (Index c : separators) isSeparator[c] = 1;
    auto ownCellsOf = [&](const std::vector<Index>& order) {
        std::vector<Index> ownOnly;
        for (Index c : order)
            if (!isSeparator[c]) ownOnly.push_back(c);
        return ownOnly;
    };
    std::vector<Index> first = ownCellsOf(amdOrder(A, withSeparators));
    std::vector<Index> clique = ownCellsOf(amdOrder(A, withSeparators, static_cast<Index>(own.size())));
    std::vector<Index> restricted = own;
    std::sort(restricted.begin(), restricted.end(), [&](Index a, Index b) { return globalRank[a] < globalRank[b]; });

    Slab best;
    double bestOperations = std::numeric_limits<double>::infinity();
    for (const auto* order : {&first, &clique, &restricted}) {
        Slab slab;
        slab.cells = *order;
        slab.cells.insert(slab.cells.end(), separators.begin(), separators.end());
        slab.own = static_cast<Index>(own.size());
        const double operations = buildPattern(slab, A);
        if (operations < bestOperations) { bestOperations = operations; best = std::move(slab); }
        if (separators.empty()) break;  // one slab: the whole matrix's AMD order is the first
    }
    const Index m = static_cast<Index>(best.cells.size()), ms = m - best.own;
    best.Lss.setIdentity(ms, ms);
    best.LD.setZero(ms, ms);
    best.T.setZero(ms, ms);
    best.y.setZero(m);
    best.c.setZero(ms);
    return best;
}

void SlabCholesky::analyse(const Matrix& A, const std::vector<int>& layer, int layers, int slabs) {
    const Index n = A.rows();
    rows_ = n;
    nonZeros_ = A.nonZeros();
    int count = std::max(1, std::min(slabs, (layers + 1) / (kMinLayers + 1)));
    std::vector<Index> all(n), globalRank(n);
    std::iota(all.begin(), all.end(), Index{0});
    const std::vector<Index> global = amdOrder(A, all);
    for (Index i = 0; i < n; ++i) globalRank[global[i]] = i;

    // the separators' layers for a first separator shifted by `shift` layers from an even split
    auto separatorLayers = [&](int shift) {
        std::vector<int> at;
        const int own = layers - (count - 1);
        int next = 0;
        for (int k = 0; k + 1 < count; ++k) {
            next += own / count + (k < own % count ? 1 : 0);
            at.push_back(next + (k == 0 ? shift : 0));
            next += 1;
        }
        return at;
    };
    auto build = [&](const std::vector<int>& at) {
        std::vector<Slab> built;
        separatorCells_.clear();
        std::vector<std::vector<Index>> own(at.size() + 1), separator(at.size());
        for (Index c = 0; c < n; ++c) {
            const auto k = std::lower_bound(at.begin(), at.end(), layer[c]) - at.begin();
            if (k < static_cast<long>(at.size()) && at[k] == layer[c]) separator[k].push_back(c);
            else own[k].push_back(c);
        }
        std::vector<Index> first(at.size() + 1, 0);
        for (std::size_t j = 0; j < at.size(); ++j) {
            first[j + 1] = first[j] + static_cast<Index>(separator[j].size());
            separatorCells_.insert(separatorCells_.end(), separator[j].begin(), separator[j].end());
        }
        for (std::size_t k = 0; k < own.size(); ++k) {
            std::vector<Index> seps;
            if (k > 0) seps.insert(seps.end(), separator[k - 1].begin(), separator[k - 1].end());
            if (k < at.size()) seps.insert(seps.end(), separator[k].begin(), separator[k].end());
            built.push_back(makeSlab(A, own[k], seps, globalRank));
            built.back().firstSeparator = k > 0 ? first[k - 1] : 0;
        }
        return built;
    };
    if (count == 1) {
        slabs_ = build({});
    } else {
        // two slabs: the separator moved a few layers either way to balance the two
        // factorisations, which run side by side
        const int reach = count == 2 ? kMinLayers : 0;
        double best = std::numeric_limits<double>::infinity();
        int bestShift = 0;
        for (int shift = -reach; shift <= reach; ++shift) {
            const std::vector<int> at = separatorLayers(shift);
            if (at.front() < kMinLayers || (count == 2 && layers - 1 - at.front() < kMinLayers)) continue;
            slabs_ = build(at);
            const double cost = largestSlabOperations();
            if (cost < best) { best = cost; bestShift = shift; }
        }
        slabs_ = build(separatorLayers(bestShift));
    }

    // A_ss's entries, to be taken once from the sum of the slabs' T_k
    const Index ns = static_cast<Index>(separatorCells_.size());
    std::vector<Index> joint(n, -1);
    for (Index j = 0; j < ns; ++j) joint[separatorCells_[j]] = j;
    separatorEntries_.clear();
    for (Index j = 0; j < ns; ++j) {
        const Index c = separatorCells_[j];
        for (Index p = A.outerIndexPtr()[c]; p < A.outerIndexPtr()[c + 1]; ++p)
            if (joint[A.innerIndexPtr()[p]] >= 0) separatorEntries_.push_back({joint[A.innerIndexPtr()[p]], j, p});
    }
    S_.setZero(ns, ns);
    r_.setZero(ns);
    // Sized by factorising the identity, not by LLT(ns): that constructor leaves LLT's info
    // unset, and assigning the object reads it (UBSan: invalid enum load).
    schur_.compute(Eigen::MatrixXd::Identity(ns, ns));
}

double SlabCholesky::largestSlabOperations() const {
    double largest = 0;
    for (const Slab& slab : slabs_) largest = std::max(largest, operationsOf(slab));
    return largest;
}

void SlabCholesky::factorizeSlab(Slab& slab, const Matrix& A) {
    double* value = slab.M.valuePtr();
    for (std::size_t p = 0; p < slab.source.size(); ++p) value[p] = A.valuePtr()[slab.source[p]];
    slab.factor->factorizeInPlace(slab.M);
    // LDL^T takes indefinite matrices too: a pivot at or below zero (or NaN) means M_k, and so A,
    // is not positive definite
    slab.ok = slab.factor->info() == Eigen::Success && (slab.factor->vectorD().array() > 0).all();
    const Index own = slab.own, m = static_cast<Index>(slab.cells.size());
    if (!slab.ok || own == m) return;
    const Matrix& L = slab.factor->matrixL().nestedExpression();
    for (Index j = own; j < m; ++j)
        for (Matrix::InnerIterator it(L, j); it; ++it)
            if (it.row() > j) slab.Lss(it.row() - own, j - own) = it.value();
    slab.LD.noalias() = slab.Lss * slab.factor->vectorD().tail(m - own).asDiagonal();
    slab.T.noalias() = slab.LD * slab.Lss.transpose();
}

bool SlabCholesky::factorize(const Matrix& A) {
    QS_CHECK(A.rows() == rows_ && A.nonZeros() == nonZeros_,
             "SlabCholesky::factorize: a matrix of " << A.rows() << " rows and " << A.nonZeros()
                                                     << " entries, analysed with " << rows_ << " and " << nonZeros_);
    const int count = slabs();
    if (count == 1) {
        factorizeSlab(slabs_.front(), A);
        return slabs_.front().ok;
    }
#pragma omp parallel for schedule(static, 1)
    for (int k = 0; k < count; ++k) factorizeSlab(slabs_[k], A);
    for (const Slab& slab : slabs_)
        if (!slab.ok) return false;
    S_.setZero();
    for (const Entry& e : separatorEntries_) S_(e.row, e.col) -= A.valuePtr()[e.source];
    for (const Slab& slab : slabs_) {
        const Index ms = slab.T.rows();
        S_.block(slab.firstSeparator, slab.firstSeparator, ms, ms) += slab.T;
    }
    if (!S_.allFinite()) return false;  // LLT's pivot test, d <= 0, lets a NaN through
    schur_.compute(S_);
    return schur_.info() == Eigen::Success;
}

void SlabCholesky::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
    x.resize(b.size());  // no allocation when it has the size already
    const int count = slabs();
    auto forward = [&](Slab& slab) {
        slab.y.setZero();
        for (Index i = 0; i < slab.own; ++i) slab.y[i] = b[slab.cells[i]];
        slab.factor->matrixL().solveInPlace(slab.y);
        const Index ms = slab.c.size();
        if (ms > 0) slab.c.noalias() = slab.Lss * slab.y.tail(ms);
    };
    auto backward = [&](Slab& slab) {
        const Index ms = slab.c.size();
        slab.y.head(slab.own).array() /= slab.factor->vectorD().head(slab.own).array();
        if (ms > 0) slab.y.tail(ms).noalias() = slab.Lss.transpose() * r_.segment(slab.firstSeparator, ms);
        slab.factor->matrixU().solveInPlace(slab.y);
        for (Index i = 0; i < slab.own; ++i) x[slab.cells[i]] = slab.y[i];
    };
    if (count == 1) {
        forward(slabs_.front());
        backward(slabs_.front());
        return;
    }
#pragma omp parallel for schedule(static, 1)
    for (int k = 0; k < count; ++k) forward(slabs_[k]);
    // the separators: S x_s = b_s - sum_k A_sk A_kk^-1 b_k = b_s + sum_k Lss y_s
    for (std::size_t j = 0; j < separatorCells_.size(); ++j) r_[j] = b[separatorCells_[j]];
    for (const Slab& slab : slabs_) r_.segment(slab.firstSeparator, slab.c.size()) += slab.c;
    schur_.solveInPlace(r_);
#pragma omp parallel for schedule(static, 1)
    for (int k = 0; k < count; ++k) backward(slabs_[k]);
    for (std::size_t j = 0; j < separatorCells_.size(); ++j) x[separatorCells_[j]] = r_[j];
}

}  // namespace qs
