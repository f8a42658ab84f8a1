#pragma once
// The seam between quicksand and OpenFOAM: a plain C++ interface, no OpenFOAM header.
//
// The OpenFOAM side (plugin/FeedLineSolver.cpp) is a shared library that quicksand loads with
// dlopen() only after it has set WM_PROJECT_DIR (libOpenFOAM reads etc/controlDict when it is
// loaded, and exits the process without it). Its one exported symbol creates a Tube.
//
// A Tube is the feed line: an incompressible single-phase OpenFOAM case solved with pimpleFoam's
// algorithm and the case's own transport, turbulence, fvOptions and function objects, with two
// coupled patches: the gate (the line's end at the column: a fixed velocity, the window's flux
// spread over the profile of the flow arriving there) and the reservoir (a total or static
// pressure from the reservoir's level). Pressures are kinematic (p / rho, m2/s2) and piezometric
// relative to the gate plane: OpenFOAM's incompressible solvers carry no gravity, so
// p = g (h_res - z_gate) at rest.
#include <string>

namespace qs::foam {

struct TubeSettings {
    const char* caseDirectory = nullptr;   ///< a working copy of the OpenFOAM case (mesh present)
    const char* gatePatch = "gate";
    const char* reservoirPatch = "reservoir";
    const char* logFile = nullptr;         ///< OpenFOAM's own output goes here
    /// s: a resume starts from the fields written at this CFD time; < 0: the case's own start
    double startTime = -1;
    /// caseDirectory is this rank's processorN/ of a decomposed case: OpenFOAM's Pstream joins
    /// the MPI the program started (the plugin built on the MPI libPstream only)
    bool parallel = false;
};

class Tube {
public:
    virtual ~Tube() = default;
    /// m2, the full cross-section of the gate patch (a wedge mesh counts as the whole circle).
    virtual double gateArea() const = 0;
    /// One CFD step of dt (s) with the gate flux Q (m3/s out of the line into the column) and the
    /// reservoir patch's pressure (m2/s2; total or static, as the patch's condition is).
    /// repeat = false starts a new step from the last one; repeat = true solves the same step
    /// again from the same start, every registered field and its old times restored (coupling
    /// iterations). Returns the area-averaged kinematic gate pressure (m2/s2). Throws
    /// std::runtime_error with OpenFOAM's message when OpenFOAM fails.
    virtual double solve(double dt, double flux, double reservoirPressure, bool repeat) = 0;
    /// The last solved step is the coupled solution: the case's function objects run on it.
    virtual void accept() = 0;
    /// Writes every registered field (and old times) at the current CFD time, all digits.
    virtual void write() = 0;
    /// s, the CFD time, and the time step's index.
    virtual double time() const = 0;
    virtual long timeIndex() const = 0;
    /// One line: the algorithm and the models selected from the case.
    virtual std::string description() const = 0;
};

}  // namespace qs::foam

/// The plugin's factory. Returns nullptr and a message in `error` when the case is unusable.
extern "C" qs::foam::Tube* quicksand_foam_create_tube(const qs::foam::TubeSettings* settings,
                                                      char* error, int errorSize);
