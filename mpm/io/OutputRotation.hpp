#pragma once
// OutputRotation: a fresh output directory for a run, with the earlier one kept. It is moved
// aside at once and becomes OUTPUT.previous only when the run has started (commit()); a run
// that fails before that (a case or an OpenFOAM line that does not load) puts it back, so
// earlier results are never lost.
#include <filesystem>
#include <string>
#include <utility>
#include <system_error>

#include "core/Error.hpp"

namespace qs {

class OutputRotation {
public:
    explicit OutputRotation(std::filesystem::path outDir, const std::string& caseFile) : outDir_(std::move(outDir)) {
        // a file (not a directory) where the output should go is the user's, not old output
        std::error_code ec;
        if (std::filesystem::exists(outDir_, ec) && !std::filesystem::is_directory(outDir_, ec))
            throw Error(caseFile + ": key 'output.directory': " + outDir_.string() +
                        " is a file, not a directory; choose another output.directory or move the file");
        aside_ = outDir_.string() + ".moving-aside";
        std::filesystem::remove_all(aside_);
        if (std::filesystem::exists(outDir_)) std::filesystem::rename(outDir_, aside_);
        std::filesystem::create_directories(outDir_);
        active_ = true;
    }
    void commit() {
        if (!active_) return;
        const std::filesystem::path previous = outDir_.string() + ".previous";
        if (std::filesystem::exists(aside_)) {
            std::filesystem::remove_all(previous);
            std::filesystem::rename(aside_, previous);
        }
        active_ = false;
    }
    ~OutputRotation() {
        if (!active_) return;
        std::error_code ignored;  // a destructor must not throw: best effort
        std::filesystem::remove_all(outDir_, ignored);
        if (std::filesystem::exists(aside_, ignored)) std::filesystem::rename(aside_, outDir_, ignored);
    }

private:
    std::filesystem::path outDir_, aside_;
    bool active_ = false;
};

}  // namespace qs
