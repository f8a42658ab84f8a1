#pragma once
// What every HDF5 writer and reader in io/ shares: a handle that closes what it owns, errors
// that name the file and HDF5's own reason, and publishing a finished file by rename.
//
// Publishing: a file is written under a temporary name beside its final one, closed, then
// renamed over the final name. A rename within one file system is atomic on POSIX, so a reader,
// a crash of the program or a full disk never finds a half-written file under the final name.
// Against the machine stopping (a power loss) a file must also reach the disk before its rename
// does. The checkpoint is forced to disk before its rename (Durability::Now); the field outputs
// are renamed at once and forced to disk together before the next checkpoint
// (FieldWriter::makeDurable, Durability::Deferred): two fsyncs per file per output cost a 1D
// column run an eighth of its wall time (docs/reliability.md).
#include <hdf5.h>

#include <string>
#include <utility>

namespace qs {

/// Owns one HDF5 identifier and releases it with the matching close function, so that every
/// early exit by exception leaves no object open (an open object keeps the file open).
class Hdf5Handle {
public:
    using Closer = herr_t (*)(hid_t);
    Hdf5Handle() = default;
    Hdf5Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
    Hdf5Handle(Hdf5Handle&& other) noexcept : id_(other.id_), closer_(other.closer_) { other.id_ = -1; }
    Hdf5Handle& operator=(Hdf5Handle&& other) noexcept {
        if (this != &other) {
            close();
            std::swap(id_, other.id_);
            closer_ = other.closer_;
        }
        return *this;
    }
    Hdf5Handle(const Hdf5Handle&) = delete;
    Hdf5Handle& operator=(const Hdf5Handle&) = delete;
    ~Hdf5Handle() { close(); }

    hid_t get() const { return id_; }
    bool valid() const { return id_ >= 0; }
    /// Closes now and reports whether closing succeeded (closing a file flushes it).
    bool close() {
        bool ok = true;
        if (id_ >= 0 && closer_) ok = closer_(id_) >= 0;
        id_ = -1;
        return ok;
    }

private:
    hid_t id_ = -1;
    Closer closer_ = nullptr;
};

/// The most specific message on HDF5's error stack, as " (HDF5: ...)", or "" when it is empty.
std::string hdf5Reason();

/// Throws qs::Error "FILE: cannot OPERATION (HDF5: reason)".
[[noreturn]] void failHdf5(const std::string& file, const std::string& operation);

/// Forces the file's bytes to disk, so that a rename that follows publishes a complete file even
/// if the machine (not only the program) stops. Throws qs::Error naming the file.
void syncToDisk(const std::string& path);

/// Forces the directory's entries (the renames in it) to disk; best effort, since some file
/// systems refuse to sync a directory.
void syncDirectory(const std::string& directory);

/// Forces every file of the file system that holds `directory` to disk (Linux's syncfs): one
/// journal commit for many files. Throws qs::Error naming the directory and the system's reason
/// if it fails (Linux reports write-back errors through it from 5.8 on). It flushes what other
/// programs wrote to that file system too.
void syncFileSystem(const std::string& directory);

/// When a published file reaches the disk: before its rename, or when its writer next syncs.
enum class Durability { Now, Deferred };

/// Renames `temporary` over `path`; with Durability::Now forces it to disk first and syncs the
/// directory after. Throws qs::Error naming both (and removes `temporary`) if the rename fails.
void publishFile(const std::string& temporary, const std::string& path, Durability durability = Durability::Now);

}  // namespace qs
