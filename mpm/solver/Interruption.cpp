#include "solver/Interruption.hpp"

namespace qs {

namespace {
volatile std::sig_atomic_t requested = 0;

extern "C" void onSignal(int signal) {
    if (requested == 0) requested = signal;  // the first one counts
}
}  // namespace

InterruptionGuard::InterruptionGuard() {
    requested = 0;
    struct sigaction action{};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // a write in progress is not cut short
    sigaction(SIGINT, &action, &previousInt_);
    sigaction(SIGTERM, &action, &previousTerm_);
}

InterruptionGuard::~InterruptionGuard() {
    sigaction(SIGINT, &previousInt_, nullptr);
    sigaction(SIGTERM, &previousTerm_, nullptr);
}

int interruptionRequested() { return requested; }

std::string signalName(int signal) {
    switch (signal) {
        case SIGINT: return "SIGINT";
        case SIGTERM: return "SIGTERM";
        default: return "signal " + std::to_string(signal);
    }
}

}  // namespace qs
