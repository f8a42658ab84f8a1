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
    unsigned major = 0, minor = 0, release = 0;
    H5get_libversion(&major, &minor, &release);
    s << "  HDF5:     " << major << "." << minor << "." << release << "\n";
    return s.str();
}

}  // namespace qs
