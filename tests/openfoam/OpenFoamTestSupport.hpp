#pragma once
// Support for the OpenFOAM tests (ctest label `openfoam`): a fresh working copy of a shipped case
// in the build tree, and the skip rule: these tests skip, saying why, only when this build has
// no OpenFOAM.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "FoamAvailability.hpp"
#include "io/CaseLoader.hpp"

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

}  // namespace qs::test
