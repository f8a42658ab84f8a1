#pragma once
// Communicator: the MPI ranks a run is spread over, and the reductions the step needs.
//
//   MpiSession mpi(argc, argv);               // main(): MPI_Init_thread, MPI_Finalize
//   const Communicator& world = Communicator::world();
//   double flux = world.sum(localFlux);       // the same bits on every rank, run after run
//
// Built without MPI (QUICKSAND_WITH_MPI off, or MPI not found) or run without mpirun, world() is
// one rank and every reduction returns its argument: the serial code path is the parallel one
// at N = 1.
//
// Reductions are in a fixed order, not MPI_Allreduce's: every rank's values are gathered to rank
// 0, added in rank order, and broadcast. Floating-point addition is not associative, and
// MPI_Allreduce may add in any order (the order can change with the message sizes or the
// network), so two runs at the same N would differ in their last bits; issue 41 asks for the
// same bytes. A gather of one double per rank costs what an Allreduce does at the ranks a
// column run uses (latency-bound either way).
#include <string>
#include <vector>

namespace qs {

class Communicator {
public:
    /// All the processes of the run (MPI_COMM_WORLD), or the one process when MPI is absent or
    /// not initialised.
    static const Communicator& world();

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool parallel() const { return size_ > 1; }

    /// Sums over the ranks in rank order (the same bits on every rank and in every run).
    double sum(double local) const;
    long long sum(long long local) const;
    /// Element by element, in rank order; every rank's vector must have the same length.
    void sumInPlace(std::vector<double>& values) const;
    double max(double local) const;
    double min(double local) const;
    /// Whether any rank passes true (an error on one rank, a signal received by one).
    bool any(bool local) const;
    /// Element by element; max and min are exact in any order.
    void maxInPlace(std::vector<double>& values) const;
    void minInPlace(std::vector<double>& values) const;
    /// Every rank's value, in rank order, on every rank.
    std::vector<double> allGather(double local) const;
    /// As allGather, waiting at most `seconds` for the others (a non-blocking gather, polled):
    /// false if they have not all arrived by then (they may be held in a collective of someone
    /// else's, OpenFOAM's: the gather is on a communicator of its own, so it never matches one
    /// of theirs), `all` then undefined. Every rank must call it alike; after a false the run
    /// must end (Communicator::abort): the gather is left pending.
    bool allGatherWithin(double local, double seconds, std::vector<double>& all) const;
    /// Every rank's values, of any length, concatenated in rank order, on every rank.
    std::vector<double> allGatherv(const std::vector<double>& local) const;
    /// The same on rank `root` only (empty elsewhere): what rank 0 writes for all of them.
    std::vector<double> gatherv(const std::vector<double>& local, int root = 0) const;
    /// Rank `root`'s text on every rank.
    std::string broadcast(const std::string& text, int root = 0) const;
    void barrier() const;
    /// Point to point with the neighbours: send[k] goes to rank neighbours[k] while recv[k] comes
    /// from it, all at once. Each recv[k] must already have the size its sender sends (an
    /// exchange of the counts first, where the receiver cannot know it). Allocates nothing once
    /// it has run with as many neighbours.
    void exchange(const std::vector<int>& neighbours, const std::vector<std::vector<double>>& send,
                  std::vector<std::vector<double>>& recv) const;
    /// Ends every rank of the run at once (MPI_Abort), with `code` as mpirun's exit code: for a
    /// failure on one rank that the others cannot know of, which would otherwise wait forever in
    /// their next reduction.
    [[noreturn]] void abort(int code) const;

private:
    Communicator() = default;
    static Communicator& mutableWorld();
    int rank_ = 0, size_ = 1;
    mutable std::vector<unsigned char> requests_;  ///< exchange's MPI_Requests (mpi.h stays out of the header)
    friend class MpiSession;
};

/// Whether this build can run on MPI ranks (CMake's QUICKSAND_WITH_MPI found MPI).
bool builtWithMpi();
/// The MPI library's own version line ("Open MPI v4.1.4, ..."), or "none".
std::string mpiLibraryVersion();

/// Whether an MPI launcher started this process (mpirun, srun with PMIx or PMI-2, MPICH's
/// Hydra): the environment it sets (OMPI_COMM_WORLD_SIZE, PMIX_RANK, PMI_RANK, PMI_SIZE).
bool launchedByMpi();

/// MPI's lifetime in main(): when the build has MPI and a launcher started the process
/// (launchedByMpi), initialises MPI (threads funnelled: only the thread that calls MPI runs the
/// OpenMP regions' master) and finalises it at the end. Started without one, the process is one
/// rank and MPI is never initialised.
class MpiSession {
public:
    MpiSession(int& argc, char**& argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

private:
    bool initialized_ = false;
};

}  // namespace qs
