#include "core/BuildInfo.hpp"

#include <hdf5.h>

#include <sstream>

#include "parallel/Communicator.hpp"
#include "quicksand_commit.hpp"  // QUICKSAND_COMMIT, written at each build (cmake/WriteCommit.cmake)

#ifdef _OPENMP
#include <omp.h>
#endif

namespace qs {

std::string version() { return QUICKSAND_VERSION; }

std::string buildCommit() { return QUICKSAND_COMMIT; }

std::string openFoamBuildVersion() { return QUICKSAND_OPENFOAM_BUILD; }

namespace {
std::string hdf5Version() {
    unsigned major = 0, minor = 0, release = 0;
    H5get_libversion(&major, &minor, &release);
    return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(release);
}
}  // namespace

std::string buildLine() {
    std::ostringstream s;
    s << "quicksand " << version() << " (commit " << buildCommit() << ", " << QUICKSAND_BUILD_TYPE << "; ";
    const std::string foam = openFoamBuildVersion();
    s << (foam.rfind("none", 0) == 0 ? "no OpenFOAM" : foam.substr(0, foam.find(" (")));
    s << ", " << (builtWithMpi() ? mpiLibraryVersion() : std::string("no MPI"));
#ifdef _OPENMP
    s << ", OpenMP " << _OPENMP;
#else
    s << ", no OpenMP";
#endif
    s << ", HDF5 " << hdf5Version() << ")";
    return s.str();
}

std::string versionText() {
    std::ostringstream s;
    s << "quicksand " << version() << " (commit " << buildCommit() << ", " << QUICKSAND_BUILD_TYPE << ")\n";
    s << "  OpenFOAM: " << openFoamBuildVersion() << "\n";
    s << "  MPI:      " << (builtWithMpi() ? mpiLibraryVersion() : std::string("none (built without MPI)")) << "\n";
#ifdef _OPENMP
    s << "  OpenMP:   " << _OPENMP << ", " << omp_get_max_threads() << " threads\n";
#else
    s << "  OpenMP:   none\n";
#endif
    s << "  HDF5:     " << hdf5Version() << "\n";
    return s.str();
}

}  // namespace qs
