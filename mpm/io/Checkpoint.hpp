#pragma once
// Checkpoints: the solver state as named arrays in one HDF5 file, to resume a run.
//
// Usage:
//   CheckpointData data;
//   data.putScalar("time", t);                          // s
//   data.put("solid/positions", std::move(x));          // any doubles
//   data.put("solid/state", std::move(states));         // any 64-bit integers
//   writeCheckpoint(dir + "/checkpoint.h5", data);      // atomic: .tmp, then rename
//   ...
//   CheckpointData back = readCheckpoint(dir + "/checkpoint.h5");
//   double t = back.scalar("time");                     // throws qs::Error if missing
//
// What the entries mean (and their units) is the writer's business: this is only a typed
// key-value store. A '/' in a name makes HDF5 groups, so `h5ls -r` shows the state tidily.
//
// File layout: a 512-byte seal (HDF5 user block: magic, byte count and CRC-32 of the rest,
// checked before HDF5 reads anything; see Checkpoint.cpp), root attributes format =
// "quicksand-checkpoint" and version = 2; each entry a dataset at its name: doubles as float64
// [n], integers as int64 [n], scalars as a float64 scalar dataspace.
#include <cstdint>
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace qs {

/// In-memory checkpoint: entries by name, each doubles, integers or one double.
/// put() of an existing name replaces the entry, whatever its type was.
class CheckpointData {
public:
    void put(const std::string& name, std::vector<double> values);
    void put(const std::string& name, std::vector<std::int64_t> values);
    void putScalar(const std::string& name, double v);

    /// Each throws qs::Error naming the entry when it is missing or of another type.
    const std::vector<double>& doubles(const std::string& name) const;
    const std::vector<std::int64_t>& integers(const std::string& name) const;
    double scalar(const std::string& name) const;

    bool has(const std::string& name) const;
    /// All entry names, sorted.
    std::vector<std::string> names() const;

private:
    using Entry = std::variant<std::vector<double>, std::vector<std::int64_t>, double>;
    friend void writeCheckpoint(const std::string& path, const CheckpointData& data);
    const Entry& entry(const std::string& name, const char* wanted) const;
    static void checkName(const std::string& name);
    std::map<std::string, Entry> entries_;
};

/// Writes atomically: to path + ".tmp" (flushed to disk), then renamed over path, so a crash
/// never leaves a half checkpoint; the previous checkpoint stays until the new one is complete.
/// Throws qs::Error naming the file on failure (the .tmp is removed).
void writeCheckpoint(const std::string& path, const CheckpointData& data);

/// Reads a file written by writeCheckpoint. Throws qs::Error naming the file if it is missing,
/// not HDF5, not a quicksand checkpoint, or holds an entry of an unsupported type.
CheckpointData readCheckpoint(const std::string& path);

}  // namespace qs
