#pragma once
// agreeOnErrors: a stage of work that every rank runs and whose errors all ranks agree on.
//
//   agreeOnErrors(ranks, [&] { ... });   // throws SharedError on every rank if any rank threw
//
// For the openings (a case, a checkpoint, an OpenFOAM line's decomposition) that fail alike on
// every rank or on rank 0 alone (its files): a rank that went on would wait in the next
// collective for one that had stopped. Collective; each rank must enter the same stages in the
// same order, so a stage is entered only once the stage before it has been agreed. Stages may
// nest (an inner stage's SharedError is the outer's error, alike on every rank).
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "parallel/Communicator.hpp"

namespace qs {

/// Runs `f`; its error's message, or empty where it succeeded.
template <class F>
std::string failureOf(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("internal error: ") + e.what();
    }
    return {};
}

/// Runs `f` on every rank of `ranks` (or alone where ranks is null) and agrees on its errors: if
/// any rank's fails, every rank throws the lowest failing rank's message as a SharedError, said
/// once (by rank 0).
template <class F>
void agreeOnErrors(const Communicator* ranks, F&& f) {
    if (!ranks || !ranks->parallel()) return f();
    const std::string failure = failureOf(f);
    const std::vector<double> failed = ranks->allGather(failure.empty() ? 0.0 : 1.0);
    for (int r = 0; r < static_cast<int>(failed.size()); ++r)
        if (failed[r] != 0) throw SharedError(ranks->broadcast(failure, r));
}

/// agreeOnErrors for a stage whose own work is collective: OpenFOAM opening its part of a
/// decomposed case reads the mesh and fields with reductions over the ranks. A rank that fails
/// in it may leave the others waiting in one of those, where no agreement reaches them. So the
/// agreement waits at most `seconds`: a failing rank that has not heard from every rank by then
/// says its error, naming itself, once, and ends the run on every rank (Communicator::abort, exit
/// 1); a rank that succeeded waits as long as the stage takes. Where all arrive in time it is
/// agreeOnErrors.
template <class F>
void agreeOnErrorsWithin(const Communicator* ranks, double seconds, F&& f) {
    if (!ranks || !ranks->parallel()) return f();
    const std::string failure = failureOf(f);
    std::vector<double> failed;
    const bool heard = ranks->allGatherWithin(failure.empty() ? 0.0 : 1.0, failure.empty() ? 1e300 : seconds, failed);
    if (!heard) {
        std::cerr << "error: rank " << ranks->rank() << " of " << ranks->size() << ": " << failure
                  << "\n(the other ranks did not answer within " << seconds
                  << " s, held in OpenFOAM's own communication: the run is ended on every rank)" << std::endl;
        ranks->abort(1);
    }
    for (int r = 0; r < static_cast<int>(failed.size()); ++r)
        if (failed[r] != 0) throw SharedError(ranks->broadcast(failure, r));
}

}  // namespace qs
