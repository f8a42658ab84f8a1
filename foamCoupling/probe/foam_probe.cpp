// foam_probe: proves that OpenFOAM runs inside a quicksand process built with CMake
// (cmake/FindOpenFOAM.cmake: Debian's libraries, headers from tools/setup.sh's source cache).
//
// One file, two parts:
//   - without FOAM_PROBE_MAIN: the shared library foam_probe_lib, the only part that includes
//     OpenFOAM. foam_probe_run() builds a Foam::Time and an fvMesh for a meshed case, reads p and
//     U and advances the icoFoam PISO loop a few steps (run-time selected boundary conditions,
//     schemes and linear solvers: the tables --no-as-needed keeps), then reports.
//   - with FOAM_PROBE_MAIN: the program foam_probe, which knows nothing of OpenFOAM. libOpenFOAM's
//     static initialisation reads $WM_PROJECT_DIR/etc/controlDict and ends the process when it is
//     missing, so main sets WM_PROJECT_DIR first and only then dlopen()s the library. It copies
//     the icoFoam cavity tutorial to /tmp, meshes it with blockMesh, calls foam_probe_run and says
//     which libPstream was loaded (serial dummy or MPI).
//
//   foam_probe [steps] [--keep]     steps default 20 (t = 0.1 s, a written time of the tutorial);
//                                   --keep leaves the case in /tmp to compare with icoFoam's.

#ifndef FOAM_PROBE_MAIN

#include "fvCFD.H"
#include "pisoControl.H"

#include <cstdio>
#include <string>

// Runs `steps` icoFoam steps on the meshed case `caseDir`; returns the number of cells, or -1
// with OpenFOAM's message in `report`.
extern "C" __attribute__((visibility("default"))) int
foam_probe_run(const char* caseDir, int steps, char* report, int reportSize)
{
    try
    {
        Foam::FatalError.throwExceptions();
        Foam::FatalIOError.throwExceptions();
        Foam::messageStream::level = 0;  // silence Info (solver residuals); errors still throw

        const Foam::fileName casePath(caseDir);
        Foam::Time runTime
        (
            Foam::Time::controlDictName, casePath.path(), Foam::fileName(casePath.name())
        );
        Foam::fvMesh mesh
        (
            Foam::IOobject(Foam::fvMesh::defaultRegion, runTime.timeName(), runTime,
                           Foam::IOobject::MUST_READ)
        );
        Foam::pisoControl piso(mesh);

        // icoFoam's createFields.H
        Foam::IOdictionary transportProperties
        (
            Foam::IOobject("transportProperties", runTime.constant(), mesh,
                           Foam::IOobject::MUST_READ_IF_MODIFIED, Foam::IOobject::NO_WRITE)
        );
        const Foam::dimensionedScalar nu("nu", Foam::dimViscosity, transportProperties);
        Foam::volScalarField p
        (
            Foam::IOobject("p", runTime.timeName(), mesh, Foam::IOobject::MUST_READ,
                           Foam::IOobject::AUTO_WRITE),
            mesh
        );
        Foam::volVectorField U
        (
            Foam::IOobject("U", runTime.timeName(), mesh, Foam::IOobject::MUST_READ,
                           Foam::IOobject::AUTO_WRITE),
            mesh
        );
        Foam::surfaceScalarField phi
        (
            Foam::IOobject("phi", runTime.timeName(), mesh, Foam::IOobject::READ_IF_PRESENT,
                           Foam::IOobject::AUTO_WRITE),
            Foam::fvc::flux(U)
        );
        Foam::label pRefCell = 0;
        Foam::scalar pRefValue = 0.0;
        Foam::setRefCell(p, mesh.solutionDict().subDict("PISO"), pRefCell, pRefValue);
        mesh.setFluxRequired(p.name());

        // icoFoam's time loop, `steps` times
        using namespace Foam;
        for (int step = 0; step < steps; ++step)
        {
            ++runTime;
            fvVectorMatrix UEqn(fvm::ddt(U) + fvm::div(phi, U) - fvm::laplacian(nu, U));
            if (piso.momentumPredictor())
            {
                solve(UEqn == -fvc::grad(p));
            }
            while (piso.correct())
            {
                volScalarField rAU(1.0/UEqn.A());
                volVectorField HbyA(constrainHbyA(rAU*UEqn.H(), U, p));
                surfaceScalarField phiHbyA
                (
                    "phiHbyA",
                    fvc::flux(HbyA) + fvc::interpolate(rAU)*fvc::ddtCorr(U, phi)
                );
                adjustPhi(phiHbyA, U, p);
                constrainPressure(p, U, phiHbyA, rAU);
                while (piso.correctNonOrthogonal())
                {
                    fvScalarMatrix pEqn(fvm::laplacian(rAU, p) == fvc::div(phiHbyA));
                    pEqn.setReference(pRefCell, pRefValue);
                    pEqn.solve(mesh.solver(p.select(piso.finalInnerIter())));
                    if (piso.finalNonOrthogonalIter())
                    {
                        phi = phiHbyA - pEqn.flux();
                    }
                }
                U = HbyA - rAU*fvc::grad(p);
                U.correctBoundaryConditions();
            }
            runTime.write();  // writes at the tutorial's write times only (every 20 steps)
        }

        const scalar continuity =
            runTime.deltaTValue()*mag(fvc::div(phi))().weightedAverage(mesh.V()).value();
        std::string patches;
        for (const auto& pf : U.boundaryField())
        {
            patches += (patches.empty() ? "" : ", ") + pf.patch().name() + ":" + pf.type();
        }
        std::snprintf
        (
            report, static_cast<std::size_t>(reportSize),
            "t = %g s after %d steps: max|U| = %.6g m/s, p in [%.6g, %.6g] m2/s2, "
            "continuity error %.3g, U patches %s",
            runTime.value(), steps, gMax(mag(U)().primitiveField()),
            gMin(p.primitiveField()), gMax(p.primitiveField()), continuity, patches.c_str()
        );
        return mesh.nCells();
    }
    catch (const Foam::error& e)
    {
        std::snprintf(report, static_cast<std::size_t>(reportSize), "OpenFOAM error: %s",
                      e.message().c_str());
        return -1;
    }
}

#else  // FOAM_PROBE_MAIN: the program, no OpenFOAM headers

#include <dlfcn.h>
#include <stdlib.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

namespace fs = std::filesystem;

namespace {

// The loaded objects whose path contains `what`, from /proc/self/maps.
std::string loaded(const char* what)
{
    std::ifstream maps("/proc/self/maps");
    std::string line, found;
    while (std::getline(maps, line))
    {
        const auto slash = line.find('/');
        if (slash == std::string::npos) continue;
        const std::string path = line.substr(slash);
        if (path.find(what) != std::string::npos && found.find(path) == std::string::npos)
        {
            found += (found.empty() ? "" : " ") + path;
        }
    }
    return found.empty() ? "(none)" : found;
}

}  // namespace

int main(int argc, char** argv)
{
    int steps = 20;
    bool keep = false;
    for (int i = 1; i < argc; ++i)
    {
        if (std::strcmp(argv[i], "--keep") == 0) keep = true;
        else steps = std::atoi(argv[i]);
    }

    // 1. The environment libOpenFOAM needs when it loads (a user's own stays).
    setenv("WM_PROJECT_DIR", FOAM_PROBE_PROJECT_DIR, 0);
    std::cout << "WM_PROJECT_DIR = " << getenv("WM_PROJECT_DIR") << "\n";

    // 2. The cavity tutorial, copied and meshed.
    char tmpl[] = "/tmp/foam_probe.XXXXXX";
    if (!mkdtemp(tmpl)) { std::perror("mkdtemp"); return 1; }
    const fs::path caseDir = fs::path(tmpl) / "cavity";
    fs::copy(FOAM_PROBE_TUTORIAL, caseDir, fs::copy_options::recursive);
    const std::string blockMesh = std::string("'") + FOAM_PROBE_BLOCKMESH + "' -case '"
        + caseDir.string() + "' > '" + caseDir.string() + "/log.blockMesh' 2>&1";
    if (std::system(blockMesh.c_str()) != 0)
    {
        std::cerr << "blockMesh failed: see " << caseDir << "/log.blockMesh\n";
        return 1;
    }
    std::cout << "case " << caseDir << " (copied from " << FOAM_PROBE_TUTORIAL
              << ", meshed with blockMesh)\n";

    // 3. Only now OpenFOAM: the library next to this program.
    const fs::path lib = fs::canonical("/proc/self/exe").parent_path() / FOAM_PROBE_LIBRARY;
    void* handle = dlopen(lib.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (!handle) { std::cerr << "dlopen: " << dlerror() << "\n"; return 1; }
    using RunFn = int (*)(const char*, int, char*, int);
    auto run = reinterpret_cast<RunFn>(dlsym(handle, "foam_probe_run"));
    if (!run) { std::cerr << "dlsym: " << dlerror() << "\n"; return 1; }

    char report[4096] = {0};
    const int cells = run(caseDir.c_str(), steps, report, sizeof report);
    std::cout << "libPstream loaded: " << loaded("libPstream") << "\n"
              << "MPI loaded:        " << loaded("libmpi") << "\n";
    if (cells < 0)
    {
        std::cerr << report << "\n";
        return 1;
    }
    std::cout << "cells: " << cells << "\n" << report << "\n";

    if (keep) std::cout << "kept " << caseDir << "\n";
    else fs::remove_all(tmpl);
    return 0;
}

#endif
