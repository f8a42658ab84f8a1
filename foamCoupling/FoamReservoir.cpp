#include "FoamReservoir.hpp"

#include <dlfcn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "FeedLineCase.hpp"
#include "core/Error.hpp"

namespace qs::foam {

namespace fs = std::filesystem;

namespace {

using CreateTube = Tube* (*)(const TubeSettings*, char*, int);
CreateTube createTube = nullptr;

std::string shellQuote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

/// Runs blockMesh in `dir` when it has no mesh yet; its output goes to the log.
void meshIfNeeded(const fs::path& dir, const std::string& log, const std::string& caseName) {
    if (fs::exists(dir / "constant/polyMesh/owner")) return;
    QS_CHECK(fs::exists(dir / "system/blockMeshDict"),
             "OpenFOAM case " << caseName << ": no mesh (constant/polyMesh) and no system/blockMeshDict to make one");
    const std::string cmd = std::string(QUICKSAND_BLOCKMESH) + " -case " + shellQuote(dir.string()) +
                            " >> " + shellQuote(log) + " 2>&1";
    const int status = std::system(cmd.c_str());
    const int rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    QS_CHECK(rc == 0, "OpenFOAM case " << caseName << ": blockMesh could not mesh system/blockMeshDict (exit "
                                      << rc << "); see its messages in " << log);
}

}  // namespace

void prepareEnvironment() {
    // libOpenFOAM (and blockMesh) read $WM_PROJECT_DIR/etc/controlDict at start-up and end the
    // process without it: set it first (a user's own OpenFOAM environment wins)
    setenv("WM_PROJECT_DIR", QUICKSAND_OPENFOAM_PROJECT_DIR, 0);
}

void loadPlugin() {
    if (createTube) return;
    prepareEnvironment();
    void* handle = dlopen(QUICKSAND_FOAM_PLUGIN, RTLD_NOW | RTLD_GLOBAL);
    QS_CHECK(handle, "cannot load the OpenFOAM plugin " << QUICKSAND_FOAM_PLUGIN << ": " << dlerror());
    createTube = reinterpret_cast<CreateTube>(dlsym(handle, "quicksand_foam_create_tube"));
    QS_CHECK(createTube, "the OpenFOAM plugin " << QUICKSAND_FOAM_PLUGIN << " lacks quicksand_foam_create_tube");
}

FoamReservoir::FoamReservoir(const CaseConfig& config, bool resume)
    : caseName_(config.reservoir.openfoamCase),
      gatePatch_(config.reservoir.gatePatch),
      reservoirPatch_(config.reservoir.reservoirPatch),
      density_(config.liquid.density),
      gravity_(config.gravity),
      shape_(config.reservoir.areaTable.empty() ? ReservoirShape::prismatic(config.reservoir.area)
                                                 : ReservoirShape::table(config.reservoir.areaTable)) {
    head_ = trialHead_ = config.reservoir.head;
    prepareEnvironment();
    const fs::path source(config.reservoir.openfoamCase);
    QS_CHECK(fs::is_directory(source), "case.toml: key 'reservoir.openfoam_case': OpenFOAM case directory "
                                           << source.string() << " does not exist");
    requireSupportedCase(caseName_);

    const fs::path out = fs::path(config.caseDirectory) / config.output.directory;
    {  // the working copy goes into the output: an output inside the OpenFOAM case would copy itself
        const std::string o = fs::weakly_canonical(out).string() + "/", c = fs::weakly_canonical(source).string() + "/";
        QS_CHECK(o.rfind(c, 0) != 0, "case.toml: key 'reservoir.openfoam_case': the OpenFOAM case "
                                         << source.string() << " holds the run's output directory " << out.string()
                                         << "; give the OpenFOAM case its own folder beside case.toml");
    }
    fs::create_directories(out);
    const fs::path work = out / "openfoam";
    if (!resume || !fs::exists(work / "system/controlDict")) {
        fs::remove_all(work);
        fs::copy(source, work, fs::copy_options::recursive);
    }
    workDir_ = fs::absolute(work).string();
    std::ofstream(work / "openfoam.foam");  // ParaView opens the case through this (empty) file
    logFile_ = fs::absolute(out / "openfoam.log").string();
    meshIfNeeded(work, logFile_, caseName_);
    loadPlugin();
    if (!resume) startTube(-1);  // a resume starts it at the checkpoint's CFD time (restoreState)
}

FoamReservoir::~FoamReservoir() = default;

void FoamReservoir::startTube(double startTime) {
    tube_.reset();  // one OpenFOAM case open at a time
    TubeSettings s;
    s.caseDirectory = workDir_.c_str();
    s.gatePatch = gatePatch_.c_str();
    s.reservoirPatch = reservoirPatch_.c_str();
    s.logFile = logFile_.c_str();
    s.startTime = startTime;
    char error[8192] = "";
    tube_.reset(createTube(&s, error, sizeof error));
    // OpenFOAM names the run's working copy; the user knows their own case
    QS_CHECK(tube_, "OpenFOAM case " << caseName_ << ": " << userPaths(error));
}

std::string FoamReservoir::userPaths(std::string text) const {
    const std::string user = fs::absolute(caseName_).lexically_normal().string();
    for (std::size_t at; (at = text.find(workDir_)) != std::string::npos;) text.replace(at, workDir_.size(), user);
    return text;
}

std::string FoamReservoir::name() const { return "OpenFOAM case " + caseName_; }

std::string FoamReservoir::description() const { return tube_ ? tube_->description() : ""; }

double FoamReservoir::initialGatePressure() const { return density_ * gravity_ * head_; }

double FoamReservoir::solveWindow(double /*t*/, double dt, double flux) {
    trialHead_ = shape_.levelAfter(head_, flux * dt);
    QS_CHECK(trialHead_ >= shape_.lowestLevel(),
             "OpenFOAM reservoir: the level fell to " << trialHead_ << " m, below the reservoir's lowest level "
             << shape_.lowestLevel() << " m: the reservoir ran empty, which quicksand does not model; extend "
             "reservoir.area_table down to the tailwater or raise the head");
    // the level at the window's middle drives the line over the window
    const double p0 = gravity_ * 0.5 * (head_ + trialHead_);
    double p = 0;
    try {
        p = tube_->solve(dt, flux, p0, pending_);
    } catch (const std::exception& e) {
        throw Error("OpenFOAM case " + caseName_ + " failed at t = " + std::to_string(tube_->time()) +
                    " s: " + userPaths(e.what()) + " (OpenFOAM's log: " + logFile_ + ")");
    }
    pending_ = true;
    return density_ * p;
}

void FoamReservoir::acceptWindow() {
    head_ = trialHead_;
    pending_ = false;
    try {
        tube_->accept();  // the case's function objects see the coupled solution
    } catch (const std::exception& e) {
        throw Error("OpenFOAM case " + caseName_ + ": a function object of system/controlDict failed at t = " +
                    std::to_string(tube_->time()) + " s: " + userPaths(e.what()));
    }
}

std::vector<double> FoamReservoir::saveState() const { return {head_, tube_->time()}; }

void FoamReservoir::restoreState(const std::vector<double>& state) {
    QS_CHECK(state.size() == 2, "OpenFOAM reservoir: the checkpoint holds no reservoir level and CFD time");
    head_ = trialHead_ = state[0];
    pending_ = false;
    try {
        startTube(state[1]);
    } catch (const Error& e) {
        throw Error(std::string(e.what()) + " (cannot resume; OpenFOAM's log: " + logFile_ + ")");
    }
}

void FoamReservoir::writeOutput(double /*t*/) {
    try {
        tube_->write();
    } catch (const std::exception& e) {
        throw Error("OpenFOAM case " + caseName_ + ": writing fields failed: " + userPaths(e.what()));
    }
}

}  // namespace qs::foam
