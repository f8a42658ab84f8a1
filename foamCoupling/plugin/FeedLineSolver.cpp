// The OpenFOAM side of the reservoir coupling: the feed line (reservoir, valve, U-tube) solved
// with pimpleFoam's algorithm, one coupling window at a time, from the user's own OpenFOAM case.
//
// Everything physical comes from OpenFOAM's libraries through its run-time selection, as under
// pimpleFoam: the viscosity model (constant/transportProperties), the turbulence model, laminar,
// RAS or LES (constant/turbulenceProperties), MRF zones, fvOptions (constant/ or system/), every
// boundary condition (a valve as a porousBafflePressure baffle) and the controlDict's function
// objects (probes, surfaceFieldValue, fieldAverage, ... writing to the case's postProcessing/).
// What quicksand adds is the coupling:
//   - the gate patch's velocity, the window's flux spread over the profile arriving at the gate
//     (GateProfile.H);
//   - the reservoir patch's pressure, from the reservoir's level;
//   - redoing a window from the same start for implicit coupling (FieldSnapshot.H);
//   - the function objects run once per accepted window, never for a trial solve.
// The PIMPLE loop below is pimpleFoam's UEqn.H and pEqn.H on a static mesh (v1912).
//
// The only file compiled against OpenFOAM's solver libraries; built as a shared library loaded
// with dlopen() (see FoamTube.hpp).
#include <dlfcn.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "FieldSnapshot.H"
#include "FoamErrors.H"
#include "FoamTube.hpp"
#include "GateProfile.H"

#include "fvCFD.H"
#include "IOMRFZoneList.H"
#include "fvOptions.H"
#include "pimpleControl.H"
#include "singlePhaseTransportModel.H"
#include "totalPressureFvPatchScalarField.H"
#include "turbulentTransportModel.H"

namespace {

using namespace Foam;
using qs::foam::guarded;

class FeedLineSolver final : public qs::foam::Tube {
public:
    explicit FeedLineSolver(const qs::foam::TubeSettings& s) {
        log_.open(s.logFile ? s.logFile : "/dev/null", std::ios::app);
        guarded(log_, [&] { construct(s); return 0; });
    }

    ~FeedLineSolver() override {
        // as pimpleFoam's last Time::run(): function objects close their files (fieldAverage
        // writes its means); a failure here must not escape a destructor
        try {
            guarded(log_, [&] { if (runTime_) runTime_->functionObjects().end(); return 0; });
        } catch (...) {
        }
    }

    double gateArea() const override { return profile_->fullArea(); }
    double time() const override { return runTime_->value(); }
    long timeIndex() const override { return runTime_->timeIndex(); }
    std::string description() const override { return description_; }

    double solve(double dt, double flux, double reservoirPressure, bool repeat) override {
        return guarded(log_, [&] { return step(dt, flux, reservoirPressure, repeat); });
    }

    void accept() override {
        guarded(log_, [&] { runTime_->functionObjects().execute(); return 0; });
    }

    void write() override {
        guarded(log_, [&] {
            // every digit, so that a resume reads back the fields the run had (bit for bit)
            const unsigned old = IOstream::defaultPrecision(17);
            runTime_->writeNow();
            IOstream::defaultPrecision(old);
            return 0;
        });
    }

private:
    void construct(const qs::foam::TubeSettings& s) {
        FatalError.throwExceptions();
        FatalIOError.throwExceptions();
        if (s.parallel) joinTheRanks();
        startAgglomerationAsAFreshProcess();
        const fileName dir(s.caseDirectory);
        runTime_.reset(new Time(Time::controlDictName, fileName(dir.path()), fileName(dir.name())));
        if (s.startTime >= 0) startAt(s.startTime);
        mesh_.reset(new fvMesh(IOobject(fvMesh::defaultRegion, runTime_->timeName(), *runTime_,
                                        IOobject::MUST_READ)));
        fvMesh& mesh = *mesh_;
        pimple_.reset(new pimpleControl(mesh));

        // createFields.H of pimpleFoam
        p_.reset(new volScalarField(IOobject("p", runTime_->timeName(), mesh, IOobject::MUST_READ,
                                             IOobject::AUTO_WRITE),
                                    mesh));
        U_.reset(new volVectorField(IOobject("U", runTime_->timeName(), mesh, IOobject::MUST_READ,
                                             IOobject::AUTO_WRITE),
                                    mesh));
        phi_.reset(new surfaceScalarField(IOobject("phi", runTime_->timeName(), mesh,
                                                   IOobject::READ_IF_PRESENT, IOobject::AUTO_WRITE),
                                          fvc::flux(*U_)));
        setRefCell(*p_, pimple_->dict(), pRefCell_, pRefValue_);
        mesh.setFluxRequired(p_->name());
        transport_.reset(new singlePhaseTransportModel(*U_, *phi_));
        turbulence_ = incompressible::turbulenceModel::New(*U_, *phi_, *transport_);
        MRF_.reset(new IOMRFZoneList(mesh));
        fvOptions_ = &fv::options::New(mesh);
        turbulence_->validate();

        gateID_ = patchIndex(s.gatePatch, "gate_patch");
        reservoirID_ = patchIndex(s.reservoirPatch, "reservoir_patch");
        checkCoupledConditions(s);
        profile_.reset(new qs::foam::GateProfile(mesh, gateID_));
        runTime_->functionObjects().start();  // as pimpleFoam's first Time::run()
        describe();
    }

    /// A decomposed line: OpenFOAM's Pstream takes the MPI that quicksand started (UPstream::init
    /// finds MPI initialised and leaves its start and its end to quicksand), and from then on
    /// this process is one rank of a parallel OpenFOAM run: each rank reads its processorN/,
    /// processor patches exchange their faces, gSum and the linear solvers reduce over the
    /// ranks, Info is the master's.
    static void joinTheRanks() {
#ifdef QUICKSAND_FOAM_PSTREAM_MPI
        if (Pstream::parRun()) return;
        static int argc = 1;
        static char name[] = "quicksand";
        static char* args[] = {name, nullptr};
        static char** argv = args;
        UPstream::init(argc, argv, false);
#else
        FatalErrorInFunction << "this OpenFOAM plugin is built on the serial (dummy) Pstream and cannot solve a "
                                "decomposed line" << exit(FatalError);
#endif
    }

    /// OpenFOAM's pair agglomeration (GAMG's default) flips the direction of its sweep over the
    /// cells after each level it builds, in one process-wide flag (pairGAMGAgglomeration::
    /// forward_, private). A second feed line in the same process then agglomerates its mesh the
    /// other way and its pressure solves differ at the solver's tolerance (3.5e-8 of the gate
    /// pressure here), so the flag starts where a fresh process starts it: a resumed run, a new
    /// process, then repeats the straight run bit for bit, and runs in one process (tests, studies)
    /// are reproducible. Looked up by its symbol; where it is absent nothing is changed.
    static void startAgglomerationAsAFreshProcess() {
        if (void* flag = dlsym(RTLD_DEFAULT, "_ZN4Foam21pairGAMGAgglomeration8forward_E"))
            *static_cast<bool*>(flag) = true;
    }

    /// A resume: the fields of the time directory written at `time`, the time index as then.
    void startAt(double time) {
        const instantList times = runTime_->times();
        const label i = Time::findClosestTimeIndex(times, time);
        if (i < 0 || std::abs(times[i].value() - time) > 1e-6 * std::max(1.0, std::abs(time)))
            FatalErrorInFunction << "no fields written at t = " << time << " s in " << runTime_->path()
                                 << " to resume from" << exit(FatalError);
        // the exact time, not the one its directory's name rounds to
        runTime_->setTime(instant(time, times[i].name()), runTime_->timeIndex());
    }

    label patchIndex(const char* name, const char* key) const {
        const label id = mesh_->boundaryMesh().findPatchID(name);
        if (id < 0)
            FatalErrorInFunction << "no patch named " << name << " (case.toml key reservoir." << key
                                 << "); the mesh's patches: " << mesh_->boundaryMesh().names() << exit(FatalError);
        return id;
    }

    /// The gate's U must take the velocity the coupling sets; the reservoir's p the level.
    void checkCoupledConditions(const qs::foam::TubeSettings& s) const {
        const word gateU = U_->boundaryField()[gateID_].type();
        if (gateU != "fixedValue")
            FatalErrorInFunction << "0/U: patch " << s.gatePatch << " has type " << gateU
                                 << "; the gate's velocity is set by the coupling each window, so it must be"
                                 << " 'type fixedValue; value uniform (0 0 0);' (docs/openfoam.md)"
                                 << exit(FatalError);
        const word resP = p_->boundaryField()[reservoirID_].type();
        if (!isA<totalPressureFvPatchScalarField>(p_->boundaryField()[reservoirID_]) && resP != "fixedValue")
            FatalErrorInFunction << "0/p: patch " << s.reservoirPatch << " has type " << resP
                                 << "; the reservoir's level is set by the coupling, so it must be"
                                 << " 'type totalPressure; p0 uniform 0; value uniform 0;' (the water enters"
                                 << " from rest) or 'type fixedValue; value uniform 0;' (static pressure)"
                                 << " (docs/openfoam.md)" << exit(FatalError);
    }

    void describe() {
        std::ostringstream d;
        d << "pimpleFoam algorithm (" << pimple_->nCorrPIMPLE() << " outer, " << pimple_->nCorrPISO()
          << " pressure correctors), turbulence " << turbulence_->type();
        d << ", " << fvOptions_->optionList::size() << " fvOptions, " << runTime_->functionObjects().size()
          << " function objects";
        description_ = d.str();
    }

    double step(double dt, double flux, double reservoirPressure, bool repeat) {
        Time& runTime = *runTime_;
        fvMesh& mesh = *mesh_;
        volVectorField& U = *U_;
        volScalarField& p = *p_;
        if (!repeat) {
            runTime.setDeltaT(dt, false);
            ++runTime;
            snapshot_.take(mesh);
            gateVelocity_ = profile_->perUnitFlux(U);  // the flow arriving at the window's start
        } else {
            snapshot_.restore(mesh);
        }
        U.boundaryFieldRef()[gateID_] == flux * gateVelocity_;
        fvPatchScalarField& reservoir = p.boundaryFieldRef()[reservoirID_];
        if (isA<totalPressureFvPatchScalarField>(reservoir))
            refCast<totalPressureFvPatchScalarField>(reservoir).p0() = reservoirPressure;
        else
            reservoir == reservoirPressure;

        pimpleControl& pimple = *pimple_;
        while (pimple.loop()) {
            tmp<fvVectorMatrix> tUEqn = momentumEquation();
            while (pimple.correct()) pressureCorrector(tUEqn);
            if (pimple.turbCorr()) {
                transport_->correct();
                turbulence_->correct();
            }
        }
        const scalarField& magSf = mesh.magSf().boundaryField()[gateID_];
        return gSum(p.boundaryField()[gateID_] * magSf) / gSum(magSf);
    }

    /// pimpleFoam's UEqn.H.
    tmp<fvVectorMatrix> momentumEquation() {
        volVectorField& U = *U_;
        IOMRFZoneList& MRF = *MRF_;
        fv::options& fvOptions = *fvOptions_;
        MRF.correctBoundaryVelocity(U);
        tmp<fvVectorMatrix> tUEqn(fvm::ddt(U) + fvm::div(*phi_, U) + MRF.DDt(U) + turbulence_->divDevReff(U) ==
                                  fvOptions(U));
        fvVectorMatrix& UEqn = tUEqn.ref();
        UEqn.relax();
        fvOptions.constrain(UEqn);
        if (pimple_->momentumPredictor()) {
            Foam::solve(UEqn == -fvc::grad(*p_));
            fvOptions.correct(U);
        }
        return tUEqn;
    }

    /// pimpleFoam's pEqn.H (static mesh: no Uf, no relative fluxes).
    void pressureCorrector(tmp<fvVectorMatrix>& tUEqn) {
        fvMesh& mesh = *mesh_;
        volVectorField& U = *U_;
        volScalarField& p = *p_;
        surfaceScalarField& phi = *phi_;
        IOMRFZoneList& MRF = *MRF_;
        pimpleControl& pimple = *pimple_;
        fvVectorMatrix& UEqn = tUEqn.ref();

        volScalarField rAU(1.0 / UEqn.A());
        volVectorField HbyA(constrainHbyA(rAU * UEqn.H(), U, p));
        surfaceScalarField phiHbyA("phiHbyA",
                                   fvc::flux(HbyA) + MRF.zeroFilter(fvc::interpolate(rAU) * fvc::ddtCorr(U, phi)));
        MRF.makeRelative(phiHbyA);
        if (p.needReference()) adjustPhi(phiHbyA, U, p);

        tmp<volScalarField> rAtU(rAU);
        if (pimple.consistent()) {
            rAtU = 1.0 / max(1.0 / rAU - UEqn.H1(), 0.1 / rAU);
            phiHbyA += fvc::interpolate(rAtU() - rAU) * fvc::snGrad(p) * mesh.magSf();
            HbyA -= (rAU - rAtU()) * fvc::grad(p);
        }
        // the momentum matrix is kept for the next corrector, as pimpleFoam does with nCorrPISO > 1
        constrainPressure(p, U, phiHbyA, rAtU(), MRF);
        while (pimple.correctNonOrthogonal()) {
            fvScalarMatrix pEqn(fvm::laplacian(rAtU(), p) == fvc::div(phiHbyA));
            pEqn.setReference(pRefCell_, pRefValue_);
            pEqn.solve(mesh.solver(p.select(pimple.finalInnerIter())));
            if (pimple.finalNonOrthogonalIter()) phi = phiHbyA - pEqn.flux();
        }
        p.relax();
        U = HbyA - rAtU * fvc::grad(p);
        U.correctBoundaryConditions();
        fvOptions_->correct(U);
    }

    std::ofstream log_;
    // declared in pimpleFoam's order of construction, so they are destroyed in its reverse
    std::unique_ptr<Time> runTime_;
    std::unique_ptr<fvMesh> mesh_;
    std::unique_ptr<pimpleControl> pimple_;
    std::unique_ptr<volScalarField> p_;
    std::unique_ptr<volVectorField> U_;
    std::unique_ptr<surfaceScalarField> phi_;
    std::unique_ptr<singlePhaseTransportModel> transport_;
    autoPtr<incompressible::turbulenceModel> turbulence_;
    std::unique_ptr<IOMRFZoneList> MRF_;
    fv::options* fvOptions_ = nullptr;  ///< owned by the mesh (a MeshObject)
    label pRefCell_ = 0;
    scalar pRefValue_ = 0;
    label gateID_ = -1, reservoirID_ = -1;
    std::unique_ptr<qs::foam::GateProfile> profile_;
    vectorField gateVelocity_;         ///< this window's gate velocity per unit flux
    qs::foam::FieldSnapshot snapshot_;  ///< the registry at this window's start
    std::string description_;
};

}  // namespace

extern "C" __attribute__((visibility("default"))) qs::foam::Tube* quicksand_foam_create_tube(
    const qs::foam::TubeSettings* settings, char* error, int errorSize) {
    try {
        return new FeedLineSolver(*settings);
    } catch (const std::exception& e) {
        std::snprintf(error, errorSize, "%s", e.what());
    } catch (...) {
        std::snprintf(error, errorSize, "unknown error from OpenFOAM");
    }
    return nullptr;
}
