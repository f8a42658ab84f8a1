#include "parallel/Communicator.hpp"

#include <chrono>
#include <thread>

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <string>

#include "core/Error.hpp"

#ifdef QUICKSAND_HAVE_MPI
#include <mpi.h>
#endif

namespace qs {

Communicator& Communicator::mutableWorld() {
    static Communicator world;
    return world;
}

const Communicator& Communicator::world() { return mutableWorld(); }

#ifdef QUICKSAND_HAVE_MPI

bool builtWithMpi() { return true; }

std::string mpiLibraryVersion() {
    char text[MPI_MAX_LIBRARY_VERSION_STRING];
    int length = 0;
    MPI_Get_library_version(text, &length);
    std::string v(text, static_cast<std::size_t>(length));
    const auto line = v.find_first_of("\n,");  // the first clause: "Open MPI v4.1.4"
    return line == std::string::npos ? v : v.substr(0, line);
}

bool launchedByMpi() {
    // Open MPI's mpirun; a PMIx launcher (srun --mpi=pmix, prterun); MPICH's Hydra and PMI-1/2
    // launchers (srun --mpi=pmi2)
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
        if (std::getenv(name)) return true;
    return false;
}

namespace {
/// A communicator of quicksand's own for allGatherWithin: a gather that one rank may enter while
/// the others are inside a collective of OpenFOAM's on MPI_COMM_WORLD must never match one of
/// those. Made (collectively) when MPI starts.
MPI_Comm agreementComm = MPI_COMM_NULL;
}  // namespace

MpiSession::MpiSession(int& argc, char**& argv) {
    // Without a launcher quicksand is one process and leaves MPI alone: no singleton start (its
    // start-up time, its allocations that LeakSanitizer reports at exit, its signal handling),
    // as OpenFOAM's solvers touch MPI only with -parallel.
    if (!launchedByMpi()) return;
    initialized_ = true;
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    // MPI's own errors stay fatal (MPI_ERRORS_ARE_FATAL, the default): a failed reduction ends
    // every rank with MPI's message rather than handing back a value that differs by rank
    Communicator& w = Communicator::mutableWorld();
    MPI_Comm_rank(MPI_COMM_WORLD, &w.rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &w.size_);
    MPI_Comm_dup(MPI_COMM_WORLD, &agreementComm);
}

MpiSession::~MpiSession() {
    if (!initialized_) return;
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) {
        if (agreementComm != MPI_COMM_NULL) MPI_Comm_free(&agreementComm);
        MPI_Finalize();
    }
}

namespace {
bool active() {
    int initialized = 0, finalized = 0;
    MPI_Initialized(&initialized);
    MPI_Finalized(&finalized);
    return initialized && !finalized;
}
}  // namespace

std::vector<double> Communicator::allGather(double local) const {
    std::vector<double> all(static_cast<std::size_t>(size_), local);
    if (size_ > 1) MPI_Allgather(&local, 1, MPI_DOUBLE, all.data(), 1, MPI_DOUBLE, MPI_COMM_WORLD);
    return all;
}

double Communicator::sum(double local) const {
    if (size_ == 1) return local;
    const std::vector<double> all = allGather(local);
    // rank order, from zero: the same additions on every rank
    return std::accumulate(all.begin(), all.end(), 0.0);
}

long long Communicator::sum(long long local) const {
    if (size_ == 1) return local;
    long long total = 0;  // integers: any order gives the same sum
    MPI_Allreduce(&local, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
    return total;
}

void Communicator::sumInPlace(std::vector<double>& values) const {
    if (size_ == 1 || values.empty()) return;
    const int n = static_cast<int>(values.size());
    std::vector<double> all(values.size() * static_cast<std::size_t>(size_));
    MPI_Gather(values.data(), n, MPI_DOUBLE, all.data(), n, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    if (rank_ == 0) {
        std::fill(values.begin(), values.end(), 0.0);
        for (int r = 0; r < size_; ++r)
            for (int k = 0; k < n; ++k) values[k] += all[static_cast<std::size_t>(r) * n + k];
    }
    MPI_Bcast(values.data(), n, MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

void Communicator::maxInPlace(std::vector<double>& values) const {
    if (size_ == 1 || values.empty()) return;
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
}

void Communicator::minInPlace(std::vector<double>& values) const {
    if (size_ == 1 || values.empty()) return;
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
}

namespace {
/// Each rank's count and its offset in the concatenation, in rank order.
void countsAndOffsets(int size, int count, std::vector<int>& counts, std::vector<int>& offsets) {
    counts.assign(static_cast<std::size_t>(size), 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
    offsets.assign(static_cast<std::size_t>(size), 0);
    for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
}
}  // namespace

bool Communicator::allGatherWithin(double local, double seconds, std::vector<double>& all) const {
    all.assign(static_cast<std::size_t>(size_), local);
    if (size_ == 1) return true;
    static double sent;  // the request outlives a call that gives up on it: its buffers must too
    static std::vector<double> received;
    sent = local;
    received.assign(static_cast<std::size_t>(size_), 0.0);
    MPI_Request request;
    MPI_Iallgather(&sent, 1, MPI_DOUBLE, received.data(), 1, MPI_DOUBLE,
                   agreementComm != MPI_COMM_NULL ? agreementComm : MPI_COMM_WORLD, &request);
    const auto start = std::chrono::steady_clock::now();
    for (int done = 0;;) {
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        if (done) break;
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > seconds)
            return false;  // the run is ended by the caller
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    all = received;
    return true;
}

std::vector<double> Communicator::allGatherv(const std::vector<double>& local) const {
    if (size_ == 1) return local;
    std::vector<int> counts, offsets;
    countsAndOffsets(size_, static_cast<int>(local.size()), counts, offsets);
    std::vector<double> all(static_cast<std::size_t>(offsets.back() + counts.back()));
    MPI_Allgatherv(local.data(), static_cast<int>(local.size()), MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
                   MPI_DOUBLE, MPI_COMM_WORLD);
    return all;
}

std::vector<double> Communicator::gatherv(const std::vector<double>& local, int root) const {
    if (size_ == 1) return local;
    std::vector<int> counts, offsets;
    countsAndOffsets(size_, static_cast<int>(local.size()), counts, offsets);
    std::vector<double> all(rank_ == root ? static_cast<std::size_t>(offsets.back() + counts.back()) : 0);
    MPI_Gatherv(local.data(), static_cast<int>(local.size()), MPI_DOUBLE, all.data(), counts.data(), offsets.data(),
                MPI_DOUBLE, root, MPI_COMM_WORLD);
    return all;
}

double Communicator::max(double local) const {
    if (size_ == 1) return local;
    double m = local;  // max and min are exact in any order
    MPI_Allreduce(&local, &m, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return m;
}

double Communicator::min(double local) const {
    if (size_ == 1) return local;
    double m = local;
    MPI_Allreduce(&local, &m, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
    return m;
}

bool Communicator::any(bool local) const {
    if (size_ == 1) return local;
    int in = local ? 1 : 0, out = 0;
    MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD);
    return out != 0;
}

std::string Communicator::broadcast(const std::string& text, int root) const {
    if (size_ == 1) return text;
    long long length = rank_ == root ? static_cast<long long>(text.size()) : 0;
    MPI_Bcast(&length, 1, MPI_LONG_LONG, root, MPI_COMM_WORLD);
    std::string out = rank_ == root ? text : std::string(static_cast<std::size_t>(length), '\0');
    MPI_Bcast(out.data(), static_cast<int>(length), MPI_CHAR, root, MPI_COMM_WORLD);
    return out;
}

void Communicator::barrier() const {
    if (size_ > 1) MPI_Barrier(MPI_COMM_WORLD);
}

void Communicator::exchange(const std::vector<int>& neighbours, const std::vector<std::vector<double>>& send,
                            std::vector<std::vector<double>>& recv) const {
    const std::size_t n = neighbours.size();
    if (n == 0) return;
    requests_.resize(2 * n * sizeof(MPI_Request));
    auto* requests = reinterpret_cast<MPI_Request*>(requests_.data());
    constexpr int kTag = 41;
    for (std::size_t k = 0; k < n; ++k)
        MPI_Irecv(recv[k].data(), static_cast<int>(recv[k].size()), MPI_DOUBLE, neighbours[k], kTag, MPI_COMM_WORLD,
                  &requests[k]);
    for (std::size_t k = 0; k < n; ++k)
        MPI_Isend(send[k].data(), static_cast<int>(send[k].size()), MPI_DOUBLE, neighbours[k], kTag, MPI_COMM_WORLD,
                  &requests[n + k]);
    MPI_Waitall(static_cast<int>(2 * n), requests, MPI_STATUSES_IGNORE);  // a failure is fatal
}

void Communicator::abort(int code) const {
    if (active()) MPI_Abort(MPI_COMM_WORLD, code);
    std::_Exit(code);
}

#else  // built without MPI: one rank

bool builtWithMpi() { return false; }
std::string mpiLibraryVersion() { return "none"; }
bool launchedByMpi() { return false; }
MpiSession::MpiSession(int&, char**&) {}
MpiSession::~MpiSession() = default;
std::vector<double> Communicator::allGather(double local) const { return {local}; }
bool Communicator::allGatherWithin(double local, double, std::vector<double>& all) const {
    all = {local};
    return true;
}
std::vector<double> Communicator::allGatherv(const std::vector<double>& local) const { return local; }
std::vector<double> Communicator::gatherv(const std::vector<double>& local, int) const { return local; }
void Communicator::maxInPlace(std::vector<double>&) const {}
void Communicator::minInPlace(std::vector<double>&) const {}
double Communicator::sum(double local) const { return local; }
long long Communicator::sum(long long local) const { return local; }
void Communicator::sumInPlace(std::vector<double>&) const {}
double Communicator::max(double local) const { return local; }
double Communicator::min(double local) const { return local; }
bool Communicator::any(bool local) const { return local; }
std::string Communicator::broadcast(const std::string& text, int) const { return text; }
void Communicator::barrier() const {}
void Communicator::exchange(const std::vector<int>& neighbours, const std::vector<std::vector<double>>&,
                            std::vector<std::vector<double>>&) const {
    QS_CHECK(neighbours.empty(), "an exchange with other ranks in a build without MPI");
}
void Communicator::abort(int code) const { std::_Exit(code); }

#endif

}  // namespace qs
