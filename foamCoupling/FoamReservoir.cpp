#include "FoamReservoir.hpp"

#include <dlfcn.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "FeedLineCase.hpp"
#include "core/Error.hpp"
#include "parallel/AgreeOnErrors.hpp"

namespace qs::foam {

namespace fs = std::filesystem;

namespace {

/// s a rank whose part of a decomposed line failed to open waits for the others' answer before
/// it ends the run (they may be held in OpenFOAM's reductions): 20, or the environment's
/// QUICKSAND_OPENING_WAIT. A longer opening on the other ranks (a large mesh) only turns the
/// agreed error into this rank's own, with the run ended.
double openingWait() {
    const char* text = std::getenv("QUICKSAND_OPENING_WAIT");
    if (!text || !*text) return 20;
    char* end = nullptr;
    const double s = std::strtod(text, &end);
    QS_CHECK(end && *end == '\0' && s > 0 && std::isfinite(s),
             "environment variable QUICKSAND_OPENING_WAIT is '" << text << "', expected seconds > 0 (default 20)");
    return s;
}

using CreateTube = Tube* (*)(const TubeSettings*, char*, int);
CreateTube createTube = nullptr;

std::string shellQuote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

/// Runs an OpenFOAM utility on the case in `dir` with `arguments`, its output to the log;
/// returns its exit code.
int runUtility(const std::string& program, const fs::path& dir, const std::string& arguments, const std::string& log) {
    const std::string cmd = program + " -case " + shellQuote(dir.string()) + " " + arguments + " >> " +
                            shellQuote(log) + " 2>&1";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The last FOAM FATAL ERROR in the log, on one line ("" where there is none): a failed opening
/// puts the earlier output back, the log with it, so the message must carry OpenFOAM's reason.
std::string lastFoamError(const std::string& log) {
    std::ifstream in(log);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    const auto at = text.rfind("FOAM FATAL");
    if (at == std::string::npos) return "";
    std::string said;
    std::istringstream lines(text.substr(at));
    std::getline(lines, said);  // the heading itself
    for (std::string line; std::getline(lines, line) && said.size() < 400;) {
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line.find("From function") != std::string::npos) continue;
        if (line.find("in file ") != std::string::npos || line.find("FOAM exiting") != std::string::npos) break;
        said += (said.empty() ? "" : " ") + line.substr(first);
    }
    return ": OpenFOAM said '" + said + "'";
}

/// Runs blockMesh in `dir` when it has no mesh yet; its output goes to the log.
void meshIfNeeded(const fs::path& dir, const std::string& log, const std::string& caseName) {
    if (fs::exists(dir / "constant/polyMesh/owner")) return;
    QS_CHECK(fs::exists(dir / "system/blockMeshDict"),
             "OpenFOAM case " << caseName << ": no mesh (constant/polyMesh) and no system/blockMeshDict to make one");
    const int rc = runUtility(QUICKSAND_BLOCKMESH, dir, "", log);
    QS_CHECK(rc == 0, "OpenFOAM case " << caseName << ": blockMesh could not mesh system/blockMeshDict (exit "
                                      << rc << ")" << lastFoamError(log) << "; see its messages in " << log);
}

/// The processorN/ folders of a decomposed case.
int processorFolders(const fs::path& dir) {
    int n = 0;
    while (fs::is_directory(dir / ("processor" + std::to_string(n)))) ++n;
    return n;
}

void removeProcessorFolders(const fs::path& dir) {
    for (int n = processorFolders(dir); n-- > 0;) fs::remove_all(dir / ("processor" + std::to_string(n)));
}

/// The processors' fields as one case again, every time folder of theirs (over any of the same
/// name: a serial run's fields written after its checkpoint are older than the ranks' that
/// resumed from it), for a resume on another number of ranks; the processor folders then go.
void reconstruct(const fs::path& dir, const std::string& log, const std::string& caseName) {
    const std::string program = fs::path(QUICKSAND_DECOMPOSEPAR).parent_path() / "reconstructPar";
    const int rc = runUtility(program, dir, "", log);
    QS_CHECK(rc == 0, "OpenFOAM case " << caseName << ": reconstructPar could not join the line's "
                                      << processorFolders(dir) << " processor folders in " << dir.string()
                                      << " (exit " << rc << ")" << lastFoamError(log) << "; see its messages in "
                                      << log);
    removeProcessorFolders(dir);
}

/// decomposePar on the working copy into one part per rank: its start, or (a resume) every time
/// folder the run has written, the checkpoint's among them.
void decompose(const fs::path& dir, const std::string& log, const std::string& caseName, int ranks, bool allTimes) {
    const int rc = runUtility(QUICKSAND_DECOMPOSEPAR, dir, allTimes ? "-force -copyUniform -time '0:'" : "-force", log);
    QS_CHECK(rc == 0, "OpenFOAM case " << caseName << ": decomposePar could not decompose the line with its "
                                      << "system/decomposeParDict (exit " << rc << ")" << lastFoamError(log)
                                      << "; see its messages in " << log);
    const int made = processorFolders(dir);
    QS_CHECK(made == ranks, "OpenFOAM case " << caseName << ": decomposePar made " << made << " processor folders, "
                                            << "not one per rank (" << ranks << "); see " << log);
}

}  // namespace

void prepareEnvironment() {
    // libOpenFOAM (and blockMesh) read $WM_PROJECT_DIR/etc/controlDict at start-up and end the
    // process without it: set it first (a user's own OpenFOAM environment wins)
    setenv("WM_PROJECT_DIR", QUICKSAND_OPENFOAM_PROJECT_DIR, 0);
}

void loadPlugin(bool mpi) {
    // one process, one plugin: both need "libPstream.so", and the process keeps the first it loads
    static int loaded = -1;
    if (createTube) {
        QS_CHECK(loaded == int(mpi), "this process already runs an OpenFOAM line "
                                         << (loaded ? "decomposed over MPI ranks" : "serially")
                                         << " and cannot load OpenFOAM's other Pstream; run the case in its own process");
        return;
    }
    const char* plugin = mpi ? QUICKSAND_FOAM_PLUGIN_MPI : QUICKSAND_FOAM_PLUGIN;
    QS_CHECK(*plugin, "a decomposed OpenFOAM line needs OpenFOAM's MPI Pstream, which this build lacks (quicksand "
                      "built without MPI, or no libPstream.so of OpenFOAM's MPI found); remove the case's "
                      "system/decomposeParDict to run the line on rank 0");
    prepareEnvironment();
    void* handle = dlopen(plugin, RTLD_NOW | RTLD_GLOBAL);
    QS_CHECK(handle, "cannot load the OpenFOAM plugin " << plugin << ": " << dlerror());
    createTube = reinterpret_cast<CreateTube>(dlsym(handle, "quicksand_foam_create_tube"));
    QS_CHECK(createTube, "the OpenFOAM plugin " << plugin << " lacks quicksand_foam_create_tube");
    loaded = int(mpi);
}

FoamReservoir::FoamReservoir(const CaseConfig& config, bool resume, const Communicator* ranks)
    : caseName_(config.reservoir.openfoamCase),
      gatePatch_(config.reservoir.gatePatch),
      reservoirPatch_(config.reservoir.reservoirPatch),
      density_(config.liquid.density),
      gravity_(config.gravity),
      shape_(config.reservoir.areaTable.empty() ? ReservoirShape::prismatic(config.reservoir.area)
                                                 : ReservoirShape::table(config.reservoir.areaTable)),
      ranks_(ranks && ranks->parallel() ? ranks : nullptr) {
    head_ = trialHead_ = config.reservoir.head;
    prepareEnvironment();
    const int rank = ranks_ ? ranks_->rank() : 0;
    const fs::path source(config.reservoir.openfoamCase);
    const fs::path out = fs::path(config.caseDirectory) / config.output.directory;
    // Each stage below is agreed over the ranks before the next begins: the case, rank 0's
    // working copy, the plugin, the line opened.
    agreeOnErrors(ranks_, [&] {
        QS_CHECK(fs::is_directory(source), "case.toml: key 'reservoir.openfoam_case': OpenFOAM case directory "
                                               << source.string() << " does not exist");
        requireSupportedCase(caseName_);
        // the working copy goes into the output: an output inside the OpenFOAM case would copy itself
        const std::string o = fs::weakly_canonical(out).string() + "/", c = fs::weakly_canonical(source).string() + "/";
        QS_CHECK(o.rfind(c, 0) != 0, "case.toml: key 'reservoir.openfoam_case': the OpenFOAM case "
                                         << source.string() << " holds the run's output directory " << out.string()
                                         << "; give the OpenFOAM case its own folder beside case.toml");
        decomposed_ = ranks_ && requireDecomposition(caseName_, ranks_->size());
        QS_CHECK(!decomposed_ || *QUICKSAND_FOAM_PLUGIN_MPI,
                 "OpenFOAM case " << caseName_ << ": system/decomposeParDict asks for the line on " << ranks_->size()
                                  << " MPI ranks, but this build has no OpenFOAM plugin on OpenFOAM's MPI Pstream "
                                     "(quicksand built without MPI, or no MPI libPstream.so found at build time); "
                                     "remove the dictionary to solve the line on rank 0");
    });
    workDir_ = fs::absolute(out / "openfoam").string();
    // OpenFOAM's output: rank 0's (Info, the master's) in openfoam.log; another rank's own
    // messages (its errors, Pout) in a log of its own
    logFile_ = fs::absolute(out / (rank == 0 ? std::string("openfoam.log")
                                             : "openfoam.processor" + std::to_string(rank) + ".log")).string();
    agreeOnErrors(ranks_, [&] {
        if (rank == 0) prepareWorkingCopy(source.string(), out.string(), resume);
    });
    agreeOnErrors(ranks_, [&] {
        if (decomposed_ || rank == 0) loadPlugin(decomposed_);
    });
    if (!resume) startTube(-1);  // a resume starts it at the checkpoint's CFD time (restoreState)
}

void FoamReservoir::prepareWorkingCopy(const std::string& sourceCase, const std::string& outDir, bool resume) {
    const fs::path source(sourceCase), out(outDir), work(workDir_);
    fs::create_directories(out);
    const bool fresh = !resume || !fs::exists(work / "system/controlDict");
    if (fresh) {
        fs::remove_all(work);
        fs::copy(source, work, fs::copy_options::recursive);
    }
    std::ofstream(work / "openfoam.foam");  // ParaView opens the case through this (empty) file
    meshIfNeeded(work, logFile_, caseName_);
    const int ranks = ranks_ ? ranks_->size() : 1;
    const int had = fresh ? 0 : processorFolders(work);
    if (decomposed_) {
        // the user's decomposition, also where it was added to the case since the copy was made
        fs::copy_file(source / "system/decomposeParDict", work / "system/decomposeParDict",
                      fs::copy_options::overwrite_existing);
        if (fresh || had != ranks) {
            // a resume on another number of ranks: the fields joined again, then cut anew
            if (had > 0) reconstruct(work, logFile_, caseName_);
            decompose(work, logFile_, caseName_, ranks, !fresh);
        }
    } else if (fresh) {
        removeProcessorFolders(work);  // a user's own decomposition, copied with the case
    } else if (had > 0) {
        reconstruct(work, logFile_, caseName_);  // a decomposed run resumed on one rank
    }
}

template <class F>
void FoamReservoir::onLine(F&& f) {
    if (ranks_ && !decomposed_)
        agreeOnErrors(ranks_, [&] {
            if (tube_) f();
        });
    else
        f();
}

FoamReservoir::~FoamReservoir() = default;

void FoamReservoir::startTube(double startTime) {
    tube_.reset();  // one OpenFOAM case open at a time
    const int rank = ranks_ ? ranks_->rank() : 0;
    const bool solves = decomposed_ || rank == 0;  // rank 0 alone solves a line that is not decomposed
    const std::string dir = decomposed_ ? workDir_ + "/processor" + std::to_string(rank) : workDir_;
    TubeSettings s;
    s.caseDirectory = dir.c_str();
    s.gatePatch = gatePatch_.c_str();
    s.reservoirPatch = reservoirPatch_.c_str();
    s.logFile = logFile_.c_str();
    s.startTime = startTime;
    s.parallel = decomposed_;
    char error[8192] = "";
    std::unique_ptr<Tube> tube;
    // every rank opens its part, and agrees; a rank that failed alone (a processor folder of its
    // own edited by hand, damaged) may leave the others waiting in one of OpenFOAM's reductions
    // as it reads the mesh and fields, and ends the run if they do not answer within openingWait()
    double wait = 20;
    agreeOnErrors(ranks_, [&] { wait = openingWait(); });
    agreeOnErrorsWithin(ranks_, wait, [&] {
        if (!solves) return;
        tube.reset(createTube(&s, error, sizeof error));
        // OpenFOAM names the run's working copy; the user knows their own case
        QS_CHECK(tube, "OpenFOAM case " << caseName_ << ": " << userPaths(error));
    });
    tube_ = std::move(tube);
}

std::string FoamReservoir::userPaths(std::string text) const {
    // a processor folder is the working copy's alone (decomposePar's): its path stays
    const std::string user = fs::absolute(caseName_).lexically_normal().string();
    for (std::size_t at = 0; (at = text.find(workDir_, at)) != std::string::npos;) {
        if (text.compare(at + workDir_.size(), 10, "/processor") == 0) {
            at += workDir_.size();
            continue;
        }
        text.replace(at, workDir_.size(), user);
        at += user.size();
    }
    return text;
}

std::string FoamReservoir::name() const { return "OpenFOAM case " + caseName_; }

std::string FoamReservoir::description() const {
    std::string d = tube_ ? tube_->description() : "";
    if (decomposed_)
        d += "; decomposed over " + std::to_string(ranks_->size()) + " MPI ranks (system/decomposeParDict)";
    else if (ranks_)
        d += "; solved on rank 0 of " + std::to_string(ranks_->size()) +
             " (the case has no system/decomposeParDict: give it one to solve the line on every rank)";
    return d;
}

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
    onLine([&] {
        try {
            p = tube_->solve(dt, flux, p0, pending_);
        } catch (const std::exception& e) {
            throw Error("OpenFOAM case " + caseName_ + " failed at t = " + std::to_string(tube_->time()) +
                        " s: " + userPaths(e.what()) + " (OpenFOAM's log: " + logFile_ + ")");
        }
    });
    // rank 0's pressure on every rank (p + 0 + ... is p, bit for bit). A decomposed line's is
    // OpenFOAM's sum over every rank's gate faces on each rank already, but MPI does not promise
    // an Allreduce the same bits everywhere, and the ranks' columns must not part by an ulp
    if (ranks_) p = ranks_->sum(ranks_->rank() == 0 ? p : 0.0);
    pending_ = true;
    return density_ * p;
}

void FoamReservoir::acceptWindow() {
    head_ = trialHead_;
    pending_ = false;
    onLine([&] {
        try {
            tube_->accept();  // the case's function objects see the coupled solution
        } catch (const std::exception& e) {
            throw Error("OpenFOAM case " + caseName_ + ": a function object of system/controlDict failed at t = " +
                        std::to_string(tube_->time()) + " s: " + userPaths(e.what()));
        }
    });
}

std::vector<double> FoamReservoir::saveState() const {
    // the CFD time from a rank that solves the line (rank 0 does; it writes the checkpoint)
    return {head_, tube_ ? tube_->time() : -1.0};
}

void FoamReservoir::restoreState(const std::vector<double>& state) {
    QS_CHECK(state.size() == 2, "OpenFOAM reservoir: the checkpoint holds no reservoir level and CFD time");
    head_ = trialHead_ = state[0];
    pending_ = false;
    try {
        startTube(state[1]);
    } catch (const SharedError& e) {
        throw SharedError(std::string(e.what()) + " (cannot resume; OpenFOAM's log: " + logFile_ + ")");
    } catch (const Error& e) {
        throw Error(std::string(e.what()) + " (cannot resume; OpenFOAM's log: " + logFile_ + ")");
    }
}

void FoamReservoir::writeOutput(double /*t*/) {
    onLine([&] {
        try {
            tube_->write();  // a decomposed line: each rank its processor folder
        } catch (const std::exception& e) {
            throw Error("OpenFOAM case " + caseName_ + ": writing fields failed: " + userPaths(e.what()));
        }
    });
}

}  // namespace qs::foam
