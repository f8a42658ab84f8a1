#pragma once
// Interruption: SIGINT (Ctrl-C) and SIGTERM end a run cleanly instead of killing it. While a
// run is on, the handlers only raise a flag; the time loop finishes the step it is in, writes a
// checkpoint and throws Interrupted, which the quicksand command turns into a message saying how
// to resume and the exit code 128 + signal (130 for SIGINT, 143 for SIGTERM). A second signal
// while the checkpoint is being written is ignored: the checkpoint is written through a
// temporary file and a rename, so it is never half there.
//
// Usage (solver/Run.cpp):
//   InterruptionGuard guard;           // installs the handlers, restores the old ones on exit
//   ... if (interruptionRequested()) { checkpoint(); throw Interrupted(...); }
#include <csignal>
#include <string>

#include "core/Error.hpp"

namespace qs {

/// The run was stopped by a signal after writing its checkpoint.
class Interrupted : public Error {
public:
    Interrupted(int signal, const std::string& what) : Error(what), signal_(signal) {}
    int signal() const { return signal_; }
    int exitCode() const { return 128 + signal_; }

private:
    int signal_;
};

/// Installs the SIGINT and SIGTERM handlers for its lifetime (and clears the flag).
class InterruptionGuard {
public:
    InterruptionGuard();
    ~InterruptionGuard();
    InterruptionGuard(const InterruptionGuard&) = delete;
    InterruptionGuard& operator=(const InterruptionGuard&) = delete;

private:
    struct sigaction previousInt_{}, previousTerm_{};
};

/// The signal that asked the run to stop (SIGINT or SIGTERM), 0 if none.
int interruptionRequested();
/// "SIGINT" or "SIGTERM".
std::string signalName(int signal);

}  // namespace qs
