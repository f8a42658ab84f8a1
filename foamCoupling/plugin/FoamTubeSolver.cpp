// The OpenFOAM side of the reservoir coupling: a PISO solver for incompressible laminar flow in
// the U-tube (icoFoam's algorithm, written out so quicksand can drive it one coupling window at
// a time and repeat a window). The only file that includes OpenFOAM headers; built as a shared
// library loaded with dlopen() (see FoamTube.hpp).
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <algorithm>
#include <memory>
#include <stdexcept>

#include "FoamTube.hpp"

#include "fvCFD.H"
#include "totalPressureFvPatchScalarField.H"
#include "wedgePolyPatch.H"

namespace {

using namespace Foam;

/// Sends std::cout and std::cerr (OpenFOAM's Info, Warning, Pout) to the log while alive.
class OutputToLog {
public:
    explicit OutputToLog(std::ofstream& log)
        : out_(std::cout.rdbuf(log.rdbuf())), err_(std::cerr.rdbuf(log.rdbuf())) {}
    ~OutputToLog() {
        std::cout.rdbuf(out_);
        std::cerr.rdbuf(err_);
    }

private:
    std::streambuf* out_;
    std::streambuf* err_;
};

template <class F>
auto guarded(std::ofstream& log, F&& f) -> decltype(f()) {
    OutputToLog redirect(log);
    try {
        return f();
    } catch (const Foam::IOerror& e) {
        // a dictionary error: name the file and line, as OpenFOAM's own report does
        throw std::runtime_error(std::string(e.message()) + " (file " + e.ioFileName() + ", line " +
                                 std::to_string(e.ioStartLineNumber()) + ")");
    } catch (const Foam::error& e) {
        throw std::runtime_error(std::string(e.message()));
    }
}

class TubeSolver final : public qs::foam::Tube {
public:
    explicit TubeSolver(const qs::foam::TubeSettings& s) {
        log_.open(s.logFile ? s.logFile : "/dev/null", std::ios::app);
        guarded(log_, [&] { construct(s); return 0; });
    }

    double gateArea() const override { return gateArea_; }
    double time() const override { return runTime_->value(); }

    double solve(double dt, double flux, double totalPressure, bool repeat) override {
        return guarded(log_, [&] { return step(dt, flux, totalPressure, repeat); });
    }

    void write(double) override {
        guarded(log_, [&] { runTime_->writeNow(); return 0; });
    }

    void restart(double time) override {
        guarded(log_, [&] {
            const instantList times = runTime_->times();
            const label i = Time::findClosestTimeIndex(times, time);
            if (i < 0 || std::abs(times[i].value() - time) > 1e-6 * std::max(1.0, time))
                FatalErrorInFunction << "no fields written at t = " << time << " s in " << runTime_->path()
                                     << " to resume from" << exit(FatalError);
            runTime_->setTime(times[i], i);
            U0_.reset(); p0_.reset(); phi0_.reset();
            phi_.reset(); U_.reset(); p_.reset();  // unregister before reading again
            readFields();
            return 0;
        });
    }

private:
    void construct(const qs::foam::TubeSettings& s) {
        FatalError.throwExceptions();
        FatalIOError.throwExceptions();
        const fileName dir(s.caseDirectory);
        runTime_.reset(new Time(Time::controlDictName, fileName(dir.path()), fileName(dir.name())));
        mesh_.reset(new fvMesh(IOobject(fvMesh::defaultRegion, runTime_->timeName(), *runTime_,
                                        IOobject::MUST_READ)));
        fvMesh& mesh = *mesh_;
        readFields();
        IOdictionary transport(IOobject("transportProperties", runTime_->constant(), mesh,
                                        IOobject::MUST_READ, IOobject::NO_WRITE));
        nu_.reset(new dimensionedScalar("nu", dimViscosity, transport));

        gateID_ = patchIndex(s.gatePatch);
        reservoirID_ = patchIndex(s.reservoirPatch);
        if (!isA<fixedValueFvPatchVectorField>(U_->boundaryField()[gateID_]))
            FatalErrorInFunction << "patch " << s.gatePatch << ": U must be fixedValue (the coupling sets the "
                                 << "gate velocity), found " << U_->boundaryField()[gateID_].type()
                                 << exit(FatalError);
        if (!isA<totalPressureFvPatchScalarField>(p_->boundaryField()[reservoirID_]))
            FatalErrorInFunction << "patch " << s.reservoirPatch << ": p must be totalPressure (the coupling "
                                 << "sets the reservoir head), found "
                                 << p_->boundaryField()[reservoirID_].type() << exit(FatalError);

        const dictionary& piso = mesh.solutionDict().subDict("PISO");
        nCorrectors_ = piso.lookupOrDefault<label>("nCorrectors", 2);
        nNonOrthCorrectors_ = piso.lookupOrDefault<label>("nNonOrthogonalCorrectors", 0);
        gateArea_ = fullArea(gateID_);
        gateProfile_.reset(new vectorField(developedProfile(gateID_)));
    }

    /// The gate velocity per unit flux (1/m2): the developed laminar profile 2 (1 - r^2/R^2) of
    /// a pipe leaving the tube, normalised so that its flux over the full circle is 1. (A uniform
    /// velocity would meet the no-slip wall in a jump and recover pressure that a real jet loses.)
    /// r is measured from the axis: where the two wedge patches meet, or for a full 3D mesh the
    /// line through the patch's centroid along its normal.
    vectorField developedProfile(label patch) const {
        const fvPatch& fp = mesh_->boundary()[patch];
        const vectorField nf(fp.nf());
        const vectorField& Cf = fp.Cf();
        const scalarField& magSf = fp.magSf();
        vector axisPoint = gSum(Cf * magSf) / gSum(magSf);
        vector axisDir = gSum(nf * magSf);
        axisDir /= mag(axisDir);
        const wedgePolyPatch* wedges[2] = {nullptr, nullptr};
        int count = 0;
        for (const polyPatch& pp : mesh_->boundaryMesh())
            if (isA<wedgePolyPatch>(pp) && !pp.empty() && count < 2) wedges[count++] = &refCast<const wedgePolyPatch>(pp);
        if (count == 2) {
            // a point on the axis: a mesh point shared by both wedge patches
            const labelList& a = wedges[0]->meshPoints();
            const labelList& b = wedges[1]->meshPoints();
            for (label i : a)
                if (std::find(b.begin(), b.end(), i) != b.end()) { axisPoint = mesh_->points()[i]; break; }
        }
        auto radius = [&](const vector& x) {
            const vector d = x - axisPoint;
            return mag(d - (d & axisDir) * axisDir);
        };
        scalar R = 0;
        for (const label i : mesh_->boundaryMesh()[patch].meshPoints()) R = max(R, radius(mesh_->points()[i]));
        reduce(R, maxOp<scalar>());
        scalarField w(Cf.size());
        forAll(w, f) w[f] = max(scalar(0), 1 - sqr(radius(Cf[f]) / R));
        // flux over the patch (sector) scaled to the full circle: gateArea_ / sector area
        const scalar sector = gSum(magSf);
        const scalar flux = gSum(w * magSf) * gateArea_ / sector;
        return (w / flux) * nf;
    }

    /// U, p and phi of the current time directory.
    void readFields() {
        fvMesh& mesh = *mesh_;
        U_.reset(new volVectorField(IOobject("U", runTime_->timeName(), mesh, IOobject::MUST_READ,
                                             IOobject::AUTO_WRITE),
                                    mesh));
        p_.reset(new volScalarField(IOobject("p", runTime_->timeName(), mesh, IOobject::MUST_READ,
                                             IOobject::AUTO_WRITE),
                                    mesh));
        mesh.setFluxRequired(p_->name());
        phi_.reset(new surfaceScalarField(IOobject("phi", runTime_->timeName(), mesh,
                                                   IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE),
                                          fvc::flux(*U_)));
    }

    label patchIndex(const char* name) const {
        const label id = mesh_->boundaryMesh().findPatchID(name);
        if (id < 0)
            FatalErrorInFunction << "no patch named " << name << " in the OpenFOAM case "
                                 << runTime_->path() << "; its patches: " << mesh_->boundaryMesh().names()
                                 << exit(FatalError);
        return id;
    }

    /// The patch's full area: a wedge mesh (axisymmetric) stands for theta / 2 pi of the circle,
    /// theta the angle between its two wedge patches.
    double fullArea(label patch) const {
        const double sector = gSum(mesh_->magSf().boundaryField()[patch]);
        vector n[2];
        int wedges = 0;
        for (const polyPatch& pp : mesh_->boundaryMesh()) {
            if (!isA<wedgePolyPatch>(pp) || pp.empty() || wedges == 2) continue;
            n[wedges++] = pp.faceAreas()[0] / mag(pp.faceAreas()[0]);
        }
        if (wedges < 2) return sector;
        const double theta = std::acos(std::min(1.0, std::max(-1.0, double(-(n[0] & n[1])))));
        return sector * 2 * M_PI / theta;
    }

    double step(double dt, double flux, double totalPressure, bool repeat) {
        Time& runTime = *runTime_;
        fvMesh& mesh = *mesh_;
        volVectorField& U = *U_;
        volScalarField& p = *p_;
        surfaceScalarField& phi = *phi_;
        if (!repeat) {
            runTime.setDeltaT(dt, false);
            ++runTime;
            // the start of this step, for repeats (old times are stored once per time index)
            U0_.reset(new volVectorField("U0", U));
            p0_.reset(new volScalarField("p0", p));
            phi0_.reset(new surfaceScalarField("phi0", phi));
        } else {
            U = *U0_;
            p = *p0_;
            phi = *phi0_;
        }
        // coupled boundary values
        U.boundaryFieldRef()[gateID_] == flux * (*gateProfile_);
        refCast<totalPressureFvPatchScalarField>(p.boundaryFieldRef()[reservoirID_]).p0() = totalPressure;

        // PISO (icoFoam)
        fvVectorMatrix UEqn(fvm::ddt(U) + fvm::div(phi, U) - fvm::laplacian(*nu_, U));
        Foam::solve(UEqn == -fvc::grad(p));
        for (label corr = 0; corr < nCorrectors_; ++corr) {
            volScalarField rAU(1.0 / UEqn.A());
            volVectorField HbyA(constrainHbyA(rAU * UEqn.H(), U, p));
            surfaceScalarField phiHbyA("phiHbyA", fvc::flux(HbyA) + fvc::interpolate(rAU) * fvc::ddtCorr(U, phi));
            adjustPhi(phiHbyA, U, p);
            constrainPressure(p, U, phiHbyA, rAU);
            for (label nonOrth = 0; nonOrth <= nNonOrthCorrectors_; ++nonOrth) {
                fvScalarMatrix pEqn(fvm::laplacian(rAU, p) == fvc::div(phiHbyA));
                const bool final = corr == nCorrectors_ - 1 && nonOrth == nNonOrthCorrectors_;
                pEqn.solve(mesh.solver(final ? "pFinal" : "p"));
                if (nonOrth == nNonOrthCorrectors_) phi = phiHbyA - pEqn.flux();
            }
            U = HbyA - rAU * fvc::grad(p);
            U.correctBoundaryConditions();
        }
        const scalarField& magSf = mesh.magSf().boundaryField()[gateID_];
        return gSum(p.boundaryField()[gateID_] * magSf) / gSum(magSf);
    }

    std::ofstream log_;
    std::unique_ptr<Time> runTime_;
    std::unique_ptr<fvMesh> mesh_;
    std::unique_ptr<volVectorField> U_, U0_;
    std::unique_ptr<volScalarField> p_, p0_;
    std::unique_ptr<surfaceScalarField> phi_, phi0_;
    std::unique_ptr<dimensionedScalar> nu_;
    label gateID_ = -1, reservoirID_ = -1, nCorrectors_ = 2, nNonOrthCorrectors_ = 0;
    double gateArea_ = 0;
    std::unique_ptr<vectorField> gateProfile_;  ///< velocity per unit flux on the gate faces
};

}  // namespace

extern "C" __attribute__((visibility("default"))) qs::foam::Tube* quicksand_foam_create_tube(
    const qs::foam::TubeSettings* settings, char* error, int errorSize) {
    try {
        return new TubeSolver(*settings);
    } catch (const std::exception& e) {
        std::snprintf(error, errorSize, "%s", e.what());
    } catch (...) {
        std::snprintf(error, errorSize, "unknown error from OpenFOAM");
    }
    return nullptr;
}
