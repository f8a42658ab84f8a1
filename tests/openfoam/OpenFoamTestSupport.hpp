#pragma once
// Support for the OpenFOAM tests (ctest label `openfoam`): a fresh working copy of a shipped case
// in the build tree, and the skip rule: these tests skip, saying why, only when this build has
// no OpenFOAM.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "FoamAvailability.hpp"
#include "case/CaseLoader.hpp"

namespace qs::test {

#define QS_REQUIRE_OPENFOAM()                                                                   \
    do {                                                                                        \
        if (!::qs::foam::available())                                                           \
            GTEST_SKIP() << "this build has no OpenFOAM (install it with "                      \
                            "bash tools/setup.sh --openfoam and rebuild)";                      \
        ::qs::foam::registerFoamCoupling();                                                     \
    } while (0)

/// Copies cases/<relative> (case.toml and everything beside it) to a fresh folder in the build
/// tree, so runs write their output there and never into the source tree.
inline std::filesystem::path freshCaseCopy(const std::string& relative, const std::string& tag) {
    namespace fs = std::filesystem;
    const fs::path src = fs::path(QUICKSAND_SOURCE_DIR) / "cases" / relative;
    const fs::path dst = fs::path(QUICKSAND_BINARY_DIR) / "openfoam-tests" / (tag);
    fs::remove_all(dst);
    fs::create_directories(dst.parent_path());
    fs::copy(src, dst, fs::copy_options::recursive);
    fs::remove_all(dst / "output");
    return dst;
}

/// The whole text of a file ("" when it cannot be read).
inline std::string readFile(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// Replaces the first `from` in a file with `to`, as a user edits it; fails the test without one.
inline void replaceInFile(const std::filesystem::path& file, const std::string& from, const std::string& to) {
    std::string text = readFile(file);
    const auto pos = text.find(from);
    ASSERT_NE(pos, std::string::npos) << from << " not in " << file;
    text.replace(pos, from.size(), to);
    std::ofstream(file) << text;
}

}  // namespace qs::test
