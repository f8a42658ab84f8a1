// libFuzzer target, structure-aware: the bytes edit a real checkpoint's entries (drop one, resize
// it, change its type, put NaN, infinities, negative or huge values in it), then the result is
// loaded into a fresh solver of the same case, which then takes a step. Loading must either
// succeed or throw qs::Error, and a loaded state must step or stop with qs::Error; anything else
// is a defect. (fuzz_checkpoint fuzzes the file; HDF5 is never handed a damaged file, so the
// values it returns are only ever what a checkpoint held: this target fuzzes those.)
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "case/CaseLoader.hpp"
#include "io/Checkpoint.hpp"
#include "reservoir/ReservoirModel.hpp"
#include "solver/DoublePointSolver.hpp"

namespace {

struct Entry {
    std::string name;
    enum Kind { Doubles, Integers, Scalar } kind;
    std::vector<double> doubles;  // the scalar too, as one value
    std::vector<std::int64_t> integers;
};

const qs::CaseConfig& fuzzCase() {
    static const qs::CaseConfig config = qs::loadCase(QUICKSAND_FUZZ_CASE);
    return config;
}

/// The checkpoint of the geostatic column after its gravity stage and a few steps, as entries.
const std::vector<Entry>& realCheckpoint() {
    static const std::vector<Entry> entries = [] {
        const std::unique_ptr<qs::ReservoirModel> reservoir = qs::makeReservoirModel(fuzzCase());
        qs::DoublePointSolver<1> solver(fuzzCase(), *reservoir);
        solver.runGravityStage();
        for (int k = 0; k < 20; ++k) solver.step();
        qs::CheckpointData data;
        solver.saveState(data);
        std::vector<Entry> list;
        for (const std::string& name : data.names()) {
            Entry e{name, Entry::Doubles, {}, {}};
            try {
                e.doubles = data.doubles(name);
            } catch (const qs::Error&) {
                try {
                    e.integers = data.integers(name);
                    e.kind = Entry::Integers;
                } catch (const qs::Error&) {
                    e.doubles = {data.scalar(name)};
                    e.kind = Entry::Scalar;
                }
            }
            list.push_back(std::move(e));
        }
        return list;
    }();
    return entries;
}

double awkwardDouble(FuzzedDataProvider& in) {
    static const double values[] = {std::numeric_limits<double>::quiet_NaN(),
                                    std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity(),
                                    0.0, -0.0, -1.0, 1e300, -1e300, 1e-300, 4.9e-324, 2147483648.0, -2147483649.0};
    if (in.ConsumeBool()) return in.PickValueInArray(values);
    return in.ConsumeFloatingPoint<double>();
}

std::int64_t awkwardInteger(FuzzedDataProvider& in) {
    static const std::int64_t values[] = {-1, 0, 1, 2, 3, 1 << 20, std::numeric_limits<std::int32_t>::max(),
                                          std::numeric_limits<std::int64_t>::max(),
                                          std::numeric_limits<std::int64_t>::min()};
    if (in.ConsumeBool()) return in.PickValueInArray(values);
    return in.ConsumeIntegral<std::int64_t>();
}

void edit(std::vector<Entry>& entries, FuzzedDataProvider& in) {
    if (entries.empty()) return;
    Entry& e = entries[in.ConsumeIntegralInRange<std::size_t>(0, entries.size() - 1)];
    const std::size_t size = e.kind == Entry::Integers ? e.integers.size() : e.doubles.size();
    switch (in.ConsumeIntegralInRange(0, 4)) {
        case 0:  // drop the entry
            e.name.clear();
            break;
        case 1: {  // resize it: shorter, longer, empty
            const std::size_t n = in.ConsumeIntegralInRange<std::size_t>(0, 2 * size + 2);
            if (e.kind == Entry::Integers) e.integers.resize(n, awkwardInteger(in));
            else if (e.kind == Entry::Doubles) e.doubles.resize(n, awkwardDouble(in));
            break;
        }
        case 2:  // change its kind
            e.kind = static_cast<Entry::Kind>(in.ConsumeIntegralInRange(0, 2));
            if (e.kind == Entry::Integers && e.integers.empty())
                for (double d : e.doubles) e.integers.push_back(std::abs(d) < 9e18 ? static_cast<std::int64_t>(d) : 0);
            if (e.kind == Entry::Scalar) e.doubles.resize(1, 0.0);
            break;
        default:  // put an awkward value somewhere in it
            if (size == 0) break;
            if (e.kind == Entry::Integers)
                e.integers[in.ConsumeIntegralInRange<std::size_t>(0, size - 1)] = awkwardInteger(in);
            else
                e.doubles[in.ConsumeIntegralInRange<std::size_t>(0, size - 1)] = awkwardDouble(in);
            break;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzedDataProvider in(data, size);
    std::vector<Entry> entries = realCheckpoint();
    const int edits = in.ConsumeIntegralInRange(1, 4);
    for (int k = 0; k < edits; ++k) edit(entries, in);

    qs::CheckpointData checkpoint;
    for (const Entry& e : entries) {
        if (e.name.empty()) continue;
        if (e.kind == Entry::Doubles) checkpoint.put(e.name, e.doubles);
        else if (e.kind == Entry::Integers) checkpoint.put(e.name, e.integers);
        else checkpoint.putScalar(e.name, e.doubles.at(0));
    }
    try {
        const std::unique_ptr<qs::ReservoirModel> reservoir = qs::makeReservoirModel(fuzzCase());
        qs::DoublePointSolver<1> solver(fuzzCase(), *reservoir);
        solver.loadState(checkpoint);
        solver.step();
    } catch (const qs::Error& e) {
        // refused, or stopped by the health check, with a message
        if (std::getenv("QUICKSAND_FUZZ_VERBOSE")) std::fprintf(stderr, "refused: %s\n", e.what());
    }
    return 0;
}
