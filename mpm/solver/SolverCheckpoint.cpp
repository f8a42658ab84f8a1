// Checkpoint and resume of DoublePointSolver: the persistent state (points, per-node relative
// speed of the Forchheimer term, the cells' pore-pressure gradient, chamber gaps, clock and ledger) and the reservoir's own state.
// Per-step scratch (shape functions, cell lists, nodal fields) is rebuilt by the next step.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>

#include "core/Error.hpp"
#include "io/Checkpoint.hpp"
#include "parallel/GatherPoints.hpp"
#include "solver/DoublePointSolver.hpp"
#include "solver/RunSize.hpp"

namespace qs {

namespace {

/// Each persistent field of a point set as the entry SET/NAME (the registry's names,
/// points/PointSet.hpp): doubles as doubles, integer codes as integers.
template <class Set>
void putSet(CheckpointData& data, const std::string& set, const Set& points) {
    points.forEachField([&](auto& field, const FieldSpec& f) {
        using T = typename std::decay_t<decltype(field)>::value_type;
        const std::string name = set + "/" + f.name;
        if constexpr (std::is_same_v<T, double>) {
            data.put(name, std::vector<double>(field.begin(), field.end()));
        } else {
            data.put(name, std::vector<std::int64_t>(field.begin(), field.end()));
        }
    });
}

// A checkpoint is only ever what saveState wrote, unless the file is damaged or another case's:
// the seal (io/Checkpoint.cpp) catches the first, these checks the second and anything the seal
// cannot see. What a step would index with (sizes, integer codes, positions) is checked here,
// before the first step; found by fuzzing (tests/fuzz/fuzz_checkpoint_state.cpp).
const char* const kNotThisCase = ": the checkpoint is damaged or of another case";

/// The entry of field number k, named f: SET/NAME, or in a checkpoint written before the
/// registry (2026-12-07) SET_fieldK, the fields numbered in the registry's order.
std::string entryName(const CheckpointData& data, const std::string& set, const FieldSpec& f, int k) {
    const std::string name = set + "/" + f.name;
    const std::string numbered = set + "_field" + std::to_string(k);
    QS_CHECK(!(data.has(name) && data.has(numbered)),
             "entries '" << name << "' and '" << numbered << "' are one field written twice" << kNotThisCase);
    return data.has(numbered) ? numbered : name;
}

/// The day checkpoints began to name their entries (the field registry).
constexpr const char* kRegistryDate = "2026-12-07";

/// Whether a checkpoint may lack field f: f is dated (FieldSpec::since), and the checkpoint was
/// written before that date. One that names its entries was written on the registry's date or
/// later, so it lacks a field dated before that only if it is damaged.
bool mayLack(const FieldSpec& f, bool named) {
    return f.since && (!named || std::string(f.since) >= kRegistryDate);
}

/// Every field of the registry from its entry. A field the checkpoint may lack (mayLack) starts
/// at zero when it does.
template <class Set>
void getSet(const CheckpointData& data, const std::string& set, Set& points, int dimension) {
    int k = 0;
    std::size_t count = 0;
    const bool named = data.has(set + "/position");
    points.forEachField([&](auto& field, const FieldSpec& f) {
        using T = typename std::decay_t<decltype(field)>::value_type;
        const std::string name = entryName(data, set, f, k++);
        const std::size_t components = static_cast<std::size_t>(f.components);
        if (mayLack(f, named) && !data.has(name)) {
            field.assign(count * components, T{});
            return;
        }
        std::size_t size = 0;
        if constexpr (std::is_same_v<T, double>) {
            const auto& v = data.doubles(name);
            for (std::size_t i = 0; i < v.size(); ++i)
                QS_CHECK(std::isfinite(v[i]), "entry '" << name << "' value " << i << " is " << v[i] << kNotThisCase);
            field.assign(v.begin(), v.end());
            size = v.size();
        } else {
            const auto& v = data.integers(name);
            for (std::size_t i = 0; i < v.size(); ++i)
                QS_CHECK(v[i] >= std::numeric_limits<int>::min() && v[i] <= std::numeric_limits<int>::max(),
                         "entry '" << name << "' value " << i << " is " << v[i] << kNotThisCase);
            field.assign(v.begin(), v.end());
            size = v.size();
        }
        if (k == 1) count = size / static_cast<std::size_t>(dimension);  // the first field is the position
        QS_CHECK(size == count * components,
                 "entry '" << name << "' holds " << size << " values, " << count << " " << set << " points need "
                           << count * components << kNotThisCase);
    });
}

/// An integer code per point (a state, a material index) within [0, count).
void requireCodes(const std::vector<int>& codes, int count, const char* what) {
    for (std::size_t p = 0; p < codes.size(); ++p)
        QS_CHECK(codes[p] >= 0 && codes[p] < count,
                 "point " << p << " has " << what << " " << codes[p] << ", expected 0.." << count - 1 << kNotThisCase);
}

/// Every point inside the grid's box (walls included: gridToPoints clamps onto them), with
/// positive mass and volume.
template <int D, class Set>
void requireInside(const Set& set, const Grid<D>& grid, const char* name) {
    for (std::size_t p = 0; p < set.mass.size(); ++p) {
        for (int d = 0; d < D; ++d) {
            const double x = set.x[p * D + d], extent = grid.cells(d) * grid.h();
            QS_CHECK(x >= 0 && x <= extent, name << " point " << p << " at x" << d << " = " << x
                                                 << " m, outside the grid's [0, " << extent << "] m" << kNotThisCase);
        }
        QS_CHECK(set.mass[p] > 0 && set.volume[p] > 0,
                 name << " point " << p << " has mass " << set.mass[p] << " kg and volume " << set.volume[p]
                      << " m3, both must be > 0" << kNotThisCase);
    }
}

/// A scalar entry that the solver uses as a whole number (a count, a dimension).
double wholeNumber(const CheckpointData& data, const char* name, double largest) {
    const double v = data.scalar(name);
    QS_CHECK(std::isfinite(v) && v >= 0 && v <= largest && v == std::floor(v),
             "entry '" << name << "' is " << v << ", expected a whole number in [0, " << largest << "]" << kNotThisCase);
    return v;
}

const std::vector<double>& finiteValues(const CheckpointData& data, const char* name, std::size_t size) {
    const auto& v = data.doubles(name);
    QS_CHECK(size == 0 || v.size() == size,
             "entry '" << name << "' holds " << v.size() << " values, expected " << size << kNotThisCase);
    for (std::size_t i = 0; i < v.size(); ++i)
        QS_CHECK(std::isfinite(v[i]), "entry '" << name << "' value " << i << " is " << v[i] << kNotThisCase);
    return v;
}

/// The grid's carried fields (solver/GridFields.hpp) as the entries GRID/NAME.
template <class Fields>
void putGridFields(CheckpointData& data, const std::string& grid, const Fields& fields) {
    fields.forEachStateField(
        [&](const std::vector<Real>& field, const FieldSpec& f) { data.put(grid + "/" + f.name, field); });
}

/// The grid's carried fields from GRID/NAME, or from NAME in a checkpoint written before the
/// registry (2026-12-07). A field the checkpoint may lack (mayLack) starts at zero when it does.
template <class Fields>
void getGridFields(const CheckpointData& data, const std::string& grid, Fields& fields) {
    const bool named = data.has("solid/position");  // the registry's names (getSet)
    fields.forEachStateField([&](std::vector<Real>& field, const FieldSpec& f) {
        std::string name = grid + "/" + f.name;
        QS_CHECK(!(data.has(name) && data.has(f.name)),
                 "entries '" << name << "' and '" << f.name << "' are one field written twice" << kNotThisCase);
        if (!data.has(name) && data.has(f.name)) name = f.name;
        if (mayLack(f, named) && !data.has(name)) {
            std::fill(field.begin(), field.end(), 0.0);
            return;
        }
        const auto& v = finiteValues(data, name.c_str(), 0);
        QS_CHECK(v.size() == field.size(), "entry '" << name << "' holds " << v.size() << " values, the case's grid needs "
                                                     << field.size() << ": the checkpoint's grid differs from the case's grid");
        field = v;
    });
}

/// A copy of a grid's carried fields (forEachStateField) with each entry its owner's: zero where
/// this rank does not own the node or cell, then added over the ranks.
template <class Fields, class Owns>
Fields ownersOnly(const Fields& fields, Index count, Owns&& owns, const Communicator& comm) {
    Fields out = fields;
    out.forEachStateField([&](std::vector<Real>& field, const FieldSpec&) {
        const std::size_t per = field.size() / static_cast<std::size_t>(count);
        for (Index k = 0; k < count; ++k)
            if (!owns(k))
                for (std::size_t c = 0; c < per; ++c) field[static_cast<std::size_t>(k) * per + c] = 0;
        comm.sumInPlace(field);
    });
    return out;
}

}  // namespace

// The water the checkpoint was written with: the semi-implicit step's size does not see K_L, so
// the dt check below cannot catch a change of water. A checkpoint without the entry (before
// 2026-12-06) was written when liquid.bulk_modulus defaulted to the soft 2.128e7 Pa under both
// schemes; a semi-implicit case that leaves the key out now means real water.
template <int D>
void DoublePointSolver<D>::checkWater(const CheckpointData& data, bool semi) const {
    const double K = config_.liquid.bulkModulus;
    if (!data.has("bulk_modulus")) {
        QS_CHECK(!semi || config_.liquid.bulkModulusGiven,
                 "the checkpoint predates liquid.bulk_modulus's default by time.scheme (2026-12-06): it was "
                 "written with the soft 2.128e7 Pa unless the case gave the key, and the semi-implicit scheme "
                 "now defaults to real water, 2.2e9 Pa; give liquid.bulk_modulus = 2.128e7 to resume it as it was");
        return;
    }
    const double written = data.scalar("bulk_modulus");
    QS_CHECK(std::abs(written - K) <= 1e-12 * K,
             "the checkpoint was written with liquid.bulk_modulus = " << written << " Pa, the case now gives " << K
                 << " Pa" << (config_.liquid.bulkModulusGiven ? "" : " (the key left out: the scheme's default)")
                 << ": resume with the water it was written with");
}

template <int D>
void DoublePointSolver<D>::saveState(CheckpointData& data) const {
    data.putScalar("dimension", D);
    data.putScalar("time", time_);
    data.putScalar("steps", static_cast<double>(steps_));
    data.putScalar("dt", dt_);
    data.putScalar("stable_dt", stableTimeStep(config_));  // what dt was fitted from (loadState)
    data.putScalar("semi_implicit", config_.time.scheme == TimeScheme::SemiImplicit ? 1 : 0);
    data.putScalar("bulk_modulus", config_.liquid.bulkModulus);
    if (ranks_) {
        // over MPI ranks: the points of every rank in rank order, each node and cell its owner's,
        // the ranks' own sums added, as one rank writes them (rank 0 writes the file)
        const Communicator& comm = ranks_->comm();
        putSet(data, "solid", gatherPoints(solid_, comm));
        putSet(data, "liquid", gatherPoints(liquid_, comm));
        putGridFields(data, "nodes", ownersOnly(nodes_, grid_.numNodes(), [&](Index i) { return ranks_->ownsNode(i); }, comm));
        putGridFields(data, "cells", ownersOnly(water_, grid_.numCells(), [&](Index c) { return ranks_->ownsCell(c); }, comm));
    } else {
        putSet(data, "solid", solid_);
        putSet(data, "liquid", liquid_);
        putGridFields(data, "nodes", nodes_);
        putGridFields(data, "cells", water_);
    }
    data.putScalar("cavity_is_water_strain", 1);
    data.put("gap", const_cast<InflowChamber<D>&>(chamber_).gaps());
    data.put("reservoir", reservoir_.saveState());
    data.put("integrator", integrator_->saveState());
    data.put("ledger", std::vector<double>{cumulativeInflow_, sumOverRanks(chamber_.injectedVolume()), outflowVolume_,
                                           initialLiquidMass_, initialGapVolume_, gateFlux_,
                                           gatePressure_, sumOverRanks(solidOutflowMass_)});
}

template <int D>
void DoublePointSolver<D>::loadState(const CheckpointData& data) {
    const double dimension = wholeNumber(data, "dimension", 3);
    QS_CHECK(static_cast<int>(dimension) == D, "the checkpoint is of a " << dimension << "D run, the case is " << D << "D");
    time_ = data.scalar("time");
    QS_CHECK(std::isfinite(time_) && time_ >= 0, "entry 'time' is " << time_ << kNotThisCase);
    steps_ = static_cast<long>(wholeNumber(data, "steps", 9007199254740992.0));  // 2^53: exact in a double
    // a checkpoint without the entry (written before the time-integrator seam) is the explicit scheme's
    const bool semi = data.has("semi_implicit") && data.scalar("semi_implicit") != 0;
    QS_CHECK(semi == (config_.time.scheme == TimeScheme::SemiImplicit),
             "the checkpoint was written by the " << (semi ? "semi-implicit" : "explicit")
                 << " scheme, the case now asks for time.scheme = \""
                 << (semi ? "explicit" : "semi_implicit") << "\": resume with the scheme it was written with");
    checkWater(data, semi);
    // The step a checkpoint was taken with was fitted to its run's output interval
    // (solver/TimeLattice.hpp); the resumed run keeps it, so that it repeats the straight run bit
    // for bit even where the resume asks for another time.end or output_interval (outputs then
    // fall within a step of their times). What must not change is the stable step it was fitted
    // from: the grid, the materials, the water, the Courant number. Before 2026-12-07 the step
    // was the stable one.
    const double written = data.scalar("dt");
    const double writtenStable = data.has("stable_dt") ? data.scalar("stable_dt") : written;
    const double stable = stableTimeStep(config_);
    QS_CHECK(std::isfinite(written) && written > 0 && written <= writtenStable * (1 + 1e-12),
             "entry 'dt' is " << written << " s, above the stable step " << writtenStable << " s" << kNotThisCase);
    // the run's time is its step count times its step (a running sum before 2026-12-07, within
    // 1e-6 after 1e8 steps): a damaged step shows against the two
    QS_CHECK(std::abs(double(steps_) * written - time_) <= 1e-6 * std::max(time_, written),
             "entries 'dt' (" << written << " s), 'steps' (" << steps_ << ") and 'time' (" << time_
                              << " s) disagree" << kNotThisCase);
    QS_CHECK(std::abs(writtenStable - stable) <= 1e-12 * stable,
             "the checkpoint was written with a stable step of " << writtenStable << " s, the case now gives "
                                                                 << stable << " s: grid, material or water data changed");
    dt_ = written;
    // fields the registry dates (the solid's velocity gradient, the water's cavity) start at zero
    // from a checkpoint written before them
    getSet(data, "solid", solid_, D);
    getSet(data, "liquid", liquid_, D);
    // Until 2026-12-05 a cavity was a strain of the mixture, which is n times the water's (n the
    // porosity): read as the water's, an old checkpoint's cavities in sand are a factor n too
    // small, and close early. Rare (cavities), and warned rather than converted.
    if (!data.has("cavity_is_water_strain")) {
        const auto held = std::count_if(liquid_.cavity.begin(), liquid_.cavity.end(), [](Real c) { return c > 0; });
        if (held > 0)
            std::cerr << "warning: the checkpoint does not say what its cavities measure (written before 2026-12-05's "
                      << "eec36d6): " << held << " liquid points hold one, read as strains of the water; if it was "
                         "written before c94904a they are mixture strains, in sand the porosity times the water's, "
                         "and close early\n";
    }
    requireCodes(solid_.state, 2, "solid state");
    requireCodes(solid_.material, static_cast<int>(materials_.size()), "material");
    requireCodes(liquid_.state, 2, "liquid state");
    requireInside(solid_, grid_, "solid");
    requireInside(liquid_, grid_, "liquid");
    for (std::size_t p = 0; p < solid_.porosity.size(); ++p)
        QS_CHECK(solid_.porosity[p] > 0 && solid_.porosity[p] < 1,
                 "solid point " << p << " has porosity " << solid_.porosity[p] << ", outside (0, 1)" << kNotThisCase);
    // over MPI ranks, on any number of them: every rank reads the whole checkpoint and keeps the
    // points of its block (the grid's carried fields are whole on every rank)
    if (ranks_) {
        ranks_->keepOwned(solid_);
        ranks_->keepOwned(liquid_);
    }
    solid_.stressReturn.assign(solid_.size(), 0);  // per-step scratch, one per point
    getGridFields(data, "nodes", nodes_);
    // the cells' pore-pressure gradient of the last step, which centres this step's cell pressures
    // (PorePressure.cpp)
    getGridFields(data, "cells", water_);
    const auto& gaps = finiteValues(data, "gap", 0);
    QS_CHECK(gaps.size() == chamber_.gaps().size(),
             "the checkpoint's chamber has " << gaps.size() << " injection slots, the case's " << chamber_.gaps().size()
                                             << ": written by another version of quicksand or for another grid");
    chamber_.gaps() = gaps;
    reservoir_.restoreState(finiteValues(data, "reservoir", 0));
    // the time scheme's carried state: a semi-implicit checkpoint before 2026-12-05 has none,
    // and CG then starts from zeros (the same solution within its tolerance)
    if (data.has("integrator")) {
        const auto& carried = finiteValues(data, "integrator", 0);
        if (!carried.empty()) integrator_->restoreState(carried);
    }
    const auto& l = finiteValues(data, "ledger", 0);
    QS_CHECK(l.size() == 7 || l.size() == 8,
             "entry 'ledger' holds " << l.size() << " values, expected 8 (7 before the solid ledger)" << kNotThisCase);
    // the ledger's sums that each rank keeps of its own (the chamber's slots, the sand out):
    // the checkpoint's totals on rank 0, the others start from zero
    const bool first = !ranks_ || ranks_->rank() == 0;
    cumulativeInflow_ = l.at(0);
    chamber_.setInjectedVolume(first ? l.at(1) : 0.0);
    outflowVolume_ = l.at(2);
    initialLiquidMass_ = l.at(3);
    initialGapVolume_ = l.at(4);
    gateFlux_ = l.at(5);
    gatePressure_ = l.at(6);
    solidOutflowMass_ = l.size() > 7 ? l.at(7) : 0.0;  // sand carried out: kept from 2026-12-04
    warnedSandOut_ = warnedSandOut_ || solidOutflowMass_ > 0;
    if (!first) solidOutflowMass_ = 0;
    gateLaw_ = reservoir_.gateLaw(time_);
    checkHealth();  // a state that loads must be one a step can take (a cell per step at most, ...)
}

// A window's start on a rank: the points it owns between steps (they are the rank's alone, and
// stay in the order the rank stepped them), its whole copy of the grid's carried fields (their
// window cells included, which a checkpoint takes from their owners), and its own parts of the
// sums that a checkpoint adds over the ranks (the chamber's injected volume, the sand carried
// out). Nothing here is collective.
template <int D>
void DoublePointSolver<D>::saveWindowStart(CheckpointData& data) const {
    if (!ranks_) return saveState(data);
    data.putScalar("time", time_);
    data.putScalar("steps", static_cast<double>(steps_));
    putSet(data, "solid", solid_);
    putSet(data, "liquid", liquid_);
    putGridFields(data, "nodes", nodes_);
    putGridFields(data, "cells", water_);
    data.put("gap", const_cast<InflowChamber<D>&>(chamber_).gaps());
    data.put("reservoir", reservoir_.saveState());
    data.put("integrator", integrator_->saveWindowStart());
    data.put("ledger", std::vector<double>{cumulativeInflow_, chamber_.injectedVolume(), outflowVolume_,
                                           initialLiquidMass_, initialGapVolume_, gateFlux_, gatePressure_,
                                           solidOutflowMass_});
}

template <int D>
void DoublePointSolver<D>::loadWindowStart(const CheckpointData& data) {
    if (!ranks_) return loadState(data);
    time_ = data.scalar("time");
    steps_ = static_cast<long>(data.scalar("steps"));
    getSet(data, "solid", solid_, D);
    getSet(data, "liquid", liquid_, D);
    solid_.stressReturn.assign(solid_.size(), 0);
    getGridFields(data, "nodes", nodes_);
    getGridFields(data, "cells", water_);
    chamber_.gaps() = data.doubles("gap");
    reservoir_.restoreState(data.doubles("reservoir"));
    integrator_->restoreWindowStart(data.doubles("integrator"));
    const auto& l = data.doubles("ledger");
    cumulativeInflow_ = l[0];
    chamber_.setInjectedVolume(l[1]);
    outflowVolume_ = l[2];
    initialLiquidMass_ = l[3];
    initialGapVolume_ = l[4];
    gateFlux_ = l[5];
    gatePressure_ = l[6];
    solidOutflowMass_ = l[7];
    gateLaw_ = reservoir_.gateLaw(time_);
}

template void DoublePointSolver<1>::saveWindowStart(CheckpointData&) const;
template void DoublePointSolver<2>::saveWindowStart(CheckpointData&) const;
template void DoublePointSolver<3>::saveWindowStart(CheckpointData&) const;
template void DoublePointSolver<1>::loadWindowStart(const CheckpointData&);
template void DoublePointSolver<2>::loadWindowStart(const CheckpointData&);
template void DoublePointSolver<3>::loadWindowStart(const CheckpointData&);

template void DoublePointSolver<1>::saveState(CheckpointData&) const;
template void DoublePointSolver<2>::saveState(CheckpointData&) const;
template void DoublePointSolver<3>::saveState(CheckpointData&) const;
template void DoublePointSolver<1>::loadState(const CheckpointData&);
template void DoublePointSolver<2>::loadState(const CheckpointData&);
template void DoublePointSolver<3>::loadState(const CheckpointData&);

}  // namespace qs
