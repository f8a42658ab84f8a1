// The halo's two exchanges and the points' migration (parallel/Halo.hpp, PointMigration.hpp),
// under mpirun: on 3 ranks over piping2D's bands of columns, on 4 over piping3D's 2 x 2 blocks
// (where a node on the blocks' common edge has four holders).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "case/CaseLoader.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/Decomposition.hpp"
#include "parallel/Halo.hpp"
#include "parallel/PointMigration.hpp"
#include "points/LiquidPoints.hpp"
#include "points/SolidPoints.hpp"

using namespace qs;

namespace {

/// piping2D on 2 or 3 ranks, piping3D on 4 (2 x 2 blocks of whole columns).
int dimensionForRanks() { return Communicator::world().size() >= 4 ? 3 : 2; }

/// With uGIMP the decomposition keeps two ghost layers, as its stencil reaches a cell further.
CaseConfig caseForRanks(bool gimp = false) {
    std::vector<CaseOverride> overrides;
    if (gimp) overrides.push_back(parseOverride("grid.shape_functions=\"gimp\""));
    return loadCase(std::string(QUICKSAND_SOURCE_DIR) + (dimensionForRanks() == 3 ? "/cases/piping3D" : "/cases/piping2D"),
                    overrides);
}

/// A cell corner's share, a value whose sums depend on their order.
double share(Index cell, int corner, int c) { return std::sin(1.3 * double(cell) + 0.7 * corner + c) * 1e3 + 1e-7 * cell; }

template <int D>
IVec<D> cellCoords(Index k, const IVec<D>& cells) {
    IVec<D> c;
    for (int a = 0; a < D; ++a) c[a] = k % cells[a], k /= cells[a];
    return c;
}
template <int D>
Index cellIndex(const IVec<D>& c, const IVec<D>& cells) {
    Index k = 0;
    for (int a = D; a-- > 0;) k = k * cells[a] + c[a];
    return k;
}

/// Rank r's shares at the nodes of local grid `on` (zero where r scatters nothing), in the
/// order r adds them: its owned cells in global order, their corners in order; with reach 1 the
/// corners of the cells beside them too (uGIMP's stencil).
template <int D>
std::vector<double> partialOf(const Decomposition& d, int r, const Subdomain<D>& on, int components, int reach = 0) {
    const Subdomain<D> theirs(d, r);
    std::vector<double> field(static_cast<std::size_t>(on.localNodes() * components), 0.0);
    const IVec<D>& cells = on.globalCells();
    Index count = 1;
    for (int a = 0; a < D; ++a) count *= cells[a];
    for (Index k = 0; k < count; ++k) {
        const IVec<D> c = cellCoords<D>(k, cells);
        if (!theirs.ownsCell(c)) continue;
        const int width = 2 + 2 * reach;  // nodes per axis the cell's points reach
        int stencil = 1;
        for (int a = 0; a < D; ++a) stencil *= width;
        for (int corner = 0; corner < stencil; ++corner) {
            IVec<D> n = c;
            bool inside = true;
            for (int a = 0, rest = corner; a < D; ++a, rest /= width) {
                n[a] += rest % width - reach;
                inside = inside && n[a] >= 0 && n[a] <= cells[a];
            }
            if (!inside) continue;
            const Index local = on.localNode(n);
            if (local < 0) continue;
            for (int comp = 0; comp < components; ++comp) field[local * components + comp] += share(k, corner, comp);
        }
    }
    return field;
}

std::uint64_t bits(double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

template <int D>
void checkSumShared(bool gimp) {
    const Communicator& world = Communicator::world();
    const CaseConfig c = caseForRanks(gimp);
    const Decomposition d = decompose(c, world.size());
    ASSERT_EQ(d.ghostLayers, gimp ? 2 : 1);
    const int reach = gimp ? 1 : 0;
    const Subdomain<D> mine(d, world.rank());
    Halo<D> halo(d, mine, world);
    ASSERT_FALSE(halo.neighbours().empty());
    constexpr int kComponents = 2;
    std::vector<double> field = partialOf<D>(d, world.rank(), mine, kComponents, reach);
    halo.sumShared(field, kComponents);
    // every node of the local grid: the holders' shares added in rank order (a rank that does not
    // hold the node adds zero), so all holders agree to the bit
    std::vector<double> expected(field.size(), 0.0);
    for (int r = 0; r < world.size(); ++r) {
        const std::vector<double> p = partialOf<D>(d, r, mine, kComponents, reach);
        for (std::size_t i = 0; i < p.size(); ++i) expected[i] += p[i];
    }
    int wrong = 0;
    for (std::size_t i = 0; i < field.size(); ++i)
        if (bits(field[i]) != bits(expected[i]) && ++wrong < 5)
            ADD_FAILURE() << "rank " << world.rank() << " node " << i / kComponents << ": " << field[i] << " against "
                          << expected[i];
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(halo.sharedNodes(), 0u);
    // the shared nodes were summed, not left as this rank's shares: some differ from them
    const std::vector<double> own = partialOf<D>(d, world.rank(), mine, kComponents, reach);
    std::size_t changed = 0;
    for (std::size_t i = 0; i < field.size(); ++i) changed += field[i] != own[i];
    EXPECT_GT(changed, 0u);
}

template <int D>
void checkFillGhosts() {
    const Communicator& world = Communicator::world();
    const CaseConfig c = caseForRanks();
    const Decomposition d = decompose(c, world.size());
    const Subdomain<D> mine(d, world.rank());
    Halo<D> halo(d, mine, world);
    auto value = [&](const IVec<D>& n, int comp) {
        double v = comp;
        for (int a = 0; a < D; ++a) v = v * 1000 + double(n[a]);
        return v;
    };
    std::vector<double> field(static_cast<std::size_t>(mine.localNodes() * D));
    for (Index i = 0; i < mine.localNodes(); ++i) {
        const IVec<D> n = mine.globalNode(i);
        for (int comp = 0; comp < D; ++comp) field[i * D + comp] = mine.ownsNode(n) ? value(n, comp) : std::nan("");
    }
    halo.fillGhosts(field, D);
    for (Index i = 0; i < mine.localNodes(); ++i)
        for (int comp = 0; comp < D; ++comp)
            ASSERT_EQ(field[i * D + comp], value(mine.globalNode(i), comp)) << "rank " << world.rank() << " node " << i;
}

/// Points in every owned cell, each field a function of the point's id (its velocity's first
/// component), moved up to 0.9 cells sideways, then migrated.
template <int D, class Set>
void checkMigration(Set& set) {
    const Communicator& world = Communicator::world();
    const CaseConfig c = caseForRanks();
    const Decomposition d = decompose(c, world.size());
    const Subdomain<D> mine(d, world.rank());
    const Halo<D> halo(d, mine, world);
    const double h = c.grid.cellSize;
    const IVec<D>& cells = mine.globalCells();
    Index count = 1;
    for (int a = 0; a < D; ++a) count *= cells[a];
    std::vector<double> ids;
    for (Index k = 0; k < count; ++k) {
        const IVec<D> cell = cellCoords<D>(k, cells);
        if (!mine.ownsCell(cell)) continue;
        for (int j = 0; j < 2; ++j) ids.push_back(double(2 * k + j));
    }
    resizePoints(set, ids.size());
    long long idSum = 0;
    for (std::size_t p = 0; p < ids.size(); ++p) {
        const long long id = static_cast<long long>(ids[p]);
        idSum += id;
        const IVec<D> cell = cellCoords<D>(id / 2, cells);
        int f = 0;
        set.forEachField([&](auto& field, const FieldSpec& spec) {
            using T = typename std::decay_t<decltype(field)>::value_type;
            for (int comp = 0; comp < spec.components; ++comp)
                field[p * spec.components + comp] = static_cast<T>(id * 10 + f * 3 + comp);
            ++f;
        });
        set.v[p * D] = double(id);
        for (int a = 0; a < D; ++a) {
            double x = (double(cell[a]) + 0.25 + 0.5 * (id % 2)) * h;
            if (a < D - 1) x += (double((id * 7919) % 3) - 1) * 0.9 * h;  // sideways only: whole columns
            // one point in five on a cell face, fl(c h): where x / h and x (1 / h) may differ
            if (a < D - 1 && id % 5 == 0) x = double(cell[a] + (id % 2)) * h;
            set.x[p * D + a] = std::min(std::max(x, 0.0), double(cells[a]) * h);
        }
    }
    PointMigration<D> migration(mine, halo.neighbours(), h);
    const MigrationCount moved = migration.migrate(set, world);
    EXPECT_EQ(world.sum(static_cast<long long>(moved.sent)), world.sum(static_cast<long long>(moved.received)));
    EXPECT_GT(world.sum(static_cast<long long>(moved.sent)), 0);
    EXPECT_EQ(world.sum(static_cast<long long>(set.size())), world.sum(static_cast<long long>(ids.size())));
    long long after = 0;
    for (std::size_t p = 0; p < set.size(); ++p) {
        const long long id = static_cast<long long>(set.v[p * D]);
        after += id;
        IVec<D> cell;
        for (int a = 0; a < D; ++a)  // as the grid files it (Grid::cellAlong: x times 1/h)
            cell[a] = std::min<Index>(static_cast<Index>(set.x[p * D + a] * (1 / h)), cells[a] - 1);
        ASSERT_TRUE(mine.ownsCell(cell)) << "rank " << world.rank() << " holds point " << id << " of another's cell";
        int f = 0;
        set.forEachField([&](auto& field, const FieldSpec& spec) {
            using T = typename std::decay_t<decltype(field)>::value_type;
            for (int comp = 0; comp < spec.components; ++comp) {
                if (f <= 1 && (f == 0 || comp == 0)) continue;  // the position and the id
                ASSERT_EQ(field[p * spec.components + comp], static_cast<T>(id * 10 + f * 3 + comp))
                    << spec.name << " of point " << id;
            }
            ++f;
        });
    }
    EXPECT_EQ(world.sum(after), world.sum(idSum));
    // nothing moved: nothing goes
    const MigrationCount again = migration.migrate(set, world);
    EXPECT_EQ(world.sum(static_cast<long long>(again.sent)), 0);
}

}  // namespace

TEST(Halo, SharedNodesAreSummedInRankOrderByEveryHolder) {
    if (dimensionForRanks() == 3) checkSumShared<3>(false);
    else checkSumShared<2>(false);
}

// uGIMP: two ghost layers, and each cell's points reach the nodes of the cells beside it
TEST(Halo, TheWiderGimpStencilIsSummedToo) {
    if (dimensionForRanks() == 3) checkSumShared<3>(true);
    else checkSumShared<2>(true);
}

TEST(Halo, GhostNodesTakeTheirOwnersValues) {
    if (dimensionForRanks() == 3) checkFillGhosts<3>();
    else checkFillGhosts<2>();
}

TEST(PointMigration, PointsGoToTheRankOwningTheirCellWithEveryField) {
    if (dimensionForRanks() == 3) {
        LiquidPoints<3> liquid;
        checkMigration<3>(liquid);
        SolidPoints<3> solid;
        solid.internalCount = 2;
        checkMigration<3>(solid);
    } else {
        LiquidPoints<2> liquid;
        checkMigration<2>(liquid);
        SolidPoints<2> solid;
        solid.internalCount = 2;
        checkMigration<2>(solid);
    }
}
