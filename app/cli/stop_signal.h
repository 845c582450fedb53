#pragma once
// SIGINT/SIGTERM (Ctrl-C, Slurm pre-emption, Kubernetes eviction) ask a render to stop after
// the current frame is finished or discarded (docs/CLI.md, "Signals"). The handler only
// records the signal; renders poll it between samples and frames.
#include <signal.h>

namespace glint::cli {

class StopSignal {
public:
    // Installs the handlers for SIGINT and SIGTERM; the previous ones come back on destruction.
    StopSignal();
    ~StopSignal();
    StopSignal(const StopSignal&) = delete;
    StopSignal& operator=(const StopSignal&) = delete;

    bool requested() const;
    int signalNumber() const; // 0 when none arrived
    int exitCode() const { return 128 + signalNumber(); } // the shell's convention

private:
    struct sigaction previousInt_ = {};
    struct sigaction previousTerm_ = {};
};

} // namespace glint::cli
