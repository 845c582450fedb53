#pragma once
// Runs a helper executable with posix_spawn (never fork: the caller may have threads) and collects
// its standard output with a size cap and a deadline. stdin and stderr go to /dev/null.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace glint {

struct ChildLimits {
    std::chrono::milliseconds timeout{120'000};
    std::uint64_t maxOutputBytes = 1ull << 30;
    // Set by another thread to stop waiting: the child is killed and reaped within ~50 ms.
    const std::atomic<bool>* cancel = nullptr;
};

struct ChildOutcome {
    enum class Kind { Exited, Signalled, TimedOut, OutputTooLarge, SpawnFailed, Cancelled };
    Kind kind = Kind::SpawnFailed;
    int code = 0;                   // exit status, signal number, or errno of a failed spawn
    std::vector<std::uint8_t> output; // stdout, complete only when kind == Exited
};

// argv[0] is the executable's path. Blocks until the child has exited or was killed (SIGKILL on
// timeout, oversize output or cancel); always reaps it.
ChildOutcome runChild(const std::vector<std::string>& argv, const ChildLimits& limits);

} // namespace glint
