#pragma once
// The seam between quicksand and OpenFOAM: a plain C++ interface, no OpenFOAM header.
//
// The OpenFOAM side (plugin/FoamTubeSolver.cpp) is a shared library that quicksand loads with
// dlopen() only after it has set WM_PROJECT_DIR (libOpenFOAM reads etc/controlDict when it is
// loaded, and exits the process without it). Its one exported symbol creates a Tube.
//
// A Tube is an incompressible laminar flow (PISO, as icoFoam) in an OpenFOAM case with two
// coupled patches: the gate (the tube's end at the column: a fixed velocity, the developed laminar
// profile of the flux out of the tube) and the reservoir (a total pressure from the reservoir
// level). Pressures are
// kinematic (p / rho, m2/s2) and piezometric relative to the gate plane: OpenFOAM's
// incompressible solvers carry no gravity, so p = g (h_res - z_gate) at rest.
#include <string>

namespace qs::foam {

struct TubeSettings {
    const char* caseDirectory = nullptr;   ///< a working copy of the OpenFOAM case (mesh present)
    const char* gatePatch = "gate";
    const char* reservoirPatch = "reservoir";
    const char* logFile = nullptr;         ///< OpenFOAM's own output goes here
};

class Tube {
public:
    virtual ~Tube() = default;
    /// m2, the full cross-section of the gate patch (a wedge mesh counts as the whole circle).
    virtual double gateArea() const = 0;
    /// One CFD step of dt (s) with the gate flux Q (m3/s out of the tube into the column) and the
    /// reservoir patch's total pressure p0 (m2/s2). repeat = false starts a new step from the last
    /// one; repeat = true solves the same step again from the same start (coupling iterations).
    /// Returns the area-averaged kinematic gate pressure (m2/s2). Throws std::runtime_error with
    /// OpenFOAM's message when OpenFOAM fails.
    virtual double solve(double dt, double flux, double totalPressure, bool repeat) = 0;
    /// Writes the fields (U, p, phi) at the current CFD time (a time directory of the case).
    virtual void write(double time) = 0;
    /// Continues from the fields written at the time directory closest to `time` (a resume).
    virtual void restart(double time) = 0;
    /// s, the CFD time.
    virtual double time() const = 0;
};

}  // namespace qs::foam

/// The plugin's factory. Returns nullptr and a message in `error` when the case is unusable.
extern "C" qs::foam::Tube* quicksand_foam_create_tube(const qs::foam::TubeSettings* settings,
                                                      char* error, int errorSize);
