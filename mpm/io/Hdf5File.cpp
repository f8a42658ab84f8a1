#include "io/Hdf5File.hpp"

#include "core/Error.hpp"

#include <fcntl.h>
#include <cerrno>
#include <cstring>
#include <unistd.h>

#include <filesystem>

namespace qs {

std::string hdf5Reason() {
    std::string reason;
    auto collect = [](unsigned, const H5E_error2_t* error, void* data) -> herr_t {
        if (error && error->desc && *error->desc) *static_cast<std::string*>(data) = error->desc;
        return 0;
    };
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collect, &reason);
    return reason.empty() ? std::string() : " (HDF5: " + reason + ")";
}

void failHdf5(const std::string& file, const std::string& operation) {
    throw Error(file + ": cannot " + operation + hdf5Reason());
}

void syncToDisk(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY);
    if (fd < 0) throw Error(path + ": cannot open to flush to disk");
    const int status = ::fsync(fd);
    ::close(fd);
    if (status != 0) throw Error(path + ": cannot flush to disk");
}

void syncDirectory(const std::string& directory) {
    const int fd = ::open(directory.empty() ? "." : directory.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
}

void syncFileSystem(const std::string& directory) {
    const std::string path = directory.empty() ? "." : directory;
    const int fd = ::open(path.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd < 0) throw Error(path + ": cannot open to flush its files to disk");
    const int status = ::syncfs(fd);
    const int reason = errno;
    ::close(fd);
    if (status != 0) throw Error(path + ": cannot flush its files to disk: " + std::strerror(reason));
}

void publishFile(const std::string& temporary, const std::string& path, Durability durability) {
    if (durability == Durability::Now) syncToDisk(temporary);
    std::error_code error;
    std::filesystem::rename(temporary, path, error);  // atomic on POSIX within one file system
    if (error) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw Error(path + ": cannot replace with " + temporary + ": " + error.message());
    }
    // The rename lives in the directory: sync it too, so that after a power loss the file is
    // found under its name (a checkpoint that says it was written is there to resume from).
    if (durability == Durability::Now) syncDirectory(std::filesystem::path(path).parent_path().string());
}

}  // namespace qs
