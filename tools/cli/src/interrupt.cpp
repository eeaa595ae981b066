#include "interrupt.h"

#include "cli_error.h"

#include <csignal>

namespace ffxdof::cli {
namespace {

volatile std::sig_atomic_t gSignal = 0;

extern "C" void onSignal(int signal) {
    if (gSignal == 0) gSignal = signal;
}

}  // namespace

void installInterruptHandlers() {
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // reads and writes in progress go on; the flag is checked after them
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
}

int interruptSignal() { return gSignal; }

void throwIfInterrupted(const std::string& what) {
    const int signal = gSignal;
    if (signal == 0) return;
    const bool terminated = signal == SIGTERM;
    throw CliError(
        terminated ? ExitCode::Terminated : ExitCode::Interrupted,
        std::string("interrupted by ") + (terminated ? "SIGTERM" : "SIGINT") + (what.empty() ? "" : "; ") + what);
}

}  // namespace ffxdof::cli
