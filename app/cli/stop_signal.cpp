#include "stop_signal.h"

#include <csignal>

namespace glint::cli {

namespace {

// A signal handler can reach nothing but static storage, and may only store to a
// volatile sig_atomic_t: this is the one file-scope variable the command line needs.
volatile std::sig_atomic_t receivedSignal = 0;

void recordSignal(int number) { receivedSignal = number; }

} // namespace

StopSignal::StopSignal() {
    receivedSignal = 0;
    struct sigaction action = {};
    action.sa_handler = recordSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART; // file writes carry on; the flag is polled between samples
    sigaction(SIGINT, &action, &previousInt_);
    sigaction(SIGTERM, &action, &previousTerm_);
}

StopSignal::~StopSignal() {
    sigaction(SIGINT, &previousInt_, nullptr);
    sigaction(SIGTERM, &previousTerm_, nullptr);
}

bool StopSignal::requested() const { return receivedSignal != 0; }

int StopSignal::signalNumber() const { return receivedSignal; }

} // namespace glint::cli
