// Checkpoint and resume of DoublePointSolver: the persistent state (points, per-node relative
// speed of the Forchheimer term, chamber gaps, clock and ledger) and the reservoir's own state.
// Per-step scratch (shape functions, cell lists, nodal fields) is rebuilt by the next step.
#include <string>

#include "core/Error.hpp"
#include "io/Checkpoint.hpp"
#include "solver/DoublePointSolver.hpp"

namespace qs {

namespace {

template <class Set>
void putSet(CheckpointData& data, const std::string& prefix, Set& set) {
    int k = 0;
    set.forEachField([&](auto& field, int) {
        using T = typename std::decay_t<decltype(field)>::value_type;
        const std::string name = prefix + "_field" + std::to_string(k++);
        if constexpr (std::is_same_v<T, double>) {
            data.put(name, std::vector<double>(field.begin(), field.end()));
        } else {
            data.put(name, std::vector<std::int64_t>(field.begin(), field.end()));
        }
    });
}

template <class Set>
void getSet(const CheckpointData& data, const std::string& prefix, Set& set) {
    int k = 0;
    set.forEachField([&](auto& field, int) {
        using T = typename std::decay_t<decltype(field)>::value_type;
        const std::string name = prefix + "_field" + std::to_string(k++);
        if constexpr (std::is_same_v<T, double>) {
            const auto& v = data.doubles(name);
            field.assign(v.begin(), v.end());
        } else {
            const auto& v = data.integers(name);
            field.assign(v.begin(), v.end());
        }
    });
}

}  // namespace

template <int D>
void DoublePointSolver<D>::saveState(CheckpointData& data) const {
    auto& self = const_cast<DoublePointSolver<D>&>(*this);  // forEachField is non-const by design
    data.putScalar("dimension", D);
    data.putScalar("time", time_);
    data.putScalar("steps", static_cast<double>(steps_));
    data.putScalar("dt", dt_);
    putSet(data, "solid", self.solid_);
    putSet(data, "liquid", self.liquid_);
    data.put("rel_speed", relSpeed_);
    data.put("gap", const_cast<InflowChamber<D>&>(chamber_).gaps());
    data.put("reservoir", reservoir_.saveState());
    data.put("ledger", std::vector<double>{cumulativeInflow_, chamber_.injectedVolume(), outflowVolume_,
                                           initialLiquidMass_, initialGapVolume_, gateFlux_,
                                           gatePressure_});
}

template <int D>
void DoublePointSolver<D>::loadState(const CheckpointData& data) {
    QS_CHECK(static_cast<int>(data.scalar("dimension")) == D,
             "the checkpoint is of a " << data.scalar("dimension") << "D run, the case is " << D << "D");
    time_ = data.scalar("time");
    steps_ = static_cast<long>(data.scalar("steps"));
    QS_CHECK(std::abs(data.scalar("dt") - dt_) <= 1e-12 * dt_,
             "the checkpoint was written with dt = " << data.scalar("dt") << " s, the case now gives "
                                                     << dt_ << " s: grid or material data changed");
    getSet(data, "solid", solid_);
    getSet(data, "liquid", liquid_);
    const auto& rs = data.doubles("rel_speed");
    QS_CHECK(rs.size() == relSpeed_.size(), "the checkpoint's grid differs from the case's grid");
    relSpeed_ = rs;
    const auto& gaps = data.doubles("gap");
    QS_CHECK(gaps.size() == chamber_.gaps().size(),
             "the checkpoint's chamber has " << gaps.size() << " injection slots, the case's " << chamber_.gaps().size()
                                             << ": written by another version of quicksand or for another grid");
    chamber_.gaps() = gaps;
    reservoir_.restoreState(data.doubles("reservoir"));
    const auto& l = data.doubles("ledger");
    cumulativeInflow_ = l.at(0);
    chamber_.setInjectedVolume(l.at(1));
    outflowVolume_ = l.at(2);
    initialLiquidMass_ = l.at(3);
    initialGapVolume_ = l.at(4);
    gateFlux_ = l.at(5);
    gatePressure_ = l.at(6);
    gateLaw_ = reservoir_.gateLaw(time_);
}

template void DoublePointSolver<1>::saveState(CheckpointData&) const;
template void DoublePointSolver<2>::saveState(CheckpointData&) const;
template void DoublePointSolver<3>::saveState(CheckpointData&) const;
template void DoublePointSolver<1>::loadState(const CheckpointData&);
template void DoublePointSolver<2>::loadState(const CheckpointData&);
template void DoublePointSolver<3>::loadState(const CheckpointData&);

}  // namespace qs
