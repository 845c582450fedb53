#include "child_process.h"

#include <cerrno>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace glint {

namespace {

using Clock = std::chrono::steady_clock;

// Owns a file descriptor; closes it once.
class Fd {
public:
    explicit Fd(int fd = -1) : fd_(fd) {}
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    ~Fd() { reset(); }
    int get() const { return fd_; }
    void reset() {
        if (fd_ >= 0) ::close(fd_);
        fd_ = -1;
    }

private:
    int fd_;
};

// With a cancel flag the wait is cut into short slices, so a cancel is seen within one of them.
int millisecondsUntil(Clock::time_point deadline, const std::atomic<bool>* cancel) {
    auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    return left <= 0 ? 0 : static_cast<int>(std::min<long long>(left, cancel ? 50 : 60'000));
}

bool cancelled(const std::atomic<bool>* cancel) { return cancel && cancel->load(); }

// The child starts with an empty signal mask and default handlers, whatever the caller's threads
// block or ignore (Qt, for one, changes SIGPIPE).
int spawnWithStdout(const std::vector<std::string>& argv, int stdoutFd, pid_t& pid) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, stdoutFd, 1);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);

    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t none;
    sigset_t all;
    sigemptyset(&none);
    sigfillset(&all);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setsigdefault(&attributes, &all);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);

    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    int error = posix_spawn(&pid, argv.front().c_str(), &actions, &attributes, args.data(), environ);

    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    return error;
}

enum class ReadEnd { EndOfFile, TimedOut, TooLarge, Cancelled };

ReadEnd readUntilEnd(int fd, Clock::time_point deadline, const ChildLimits& limits, std::vector<std::uint8_t>& out) {
    std::vector<std::uint8_t> chunk(1 << 16);
    for (;;) {
        if (cancelled(limits.cancel)) return ReadEnd::Cancelled;
        pollfd p{fd, POLLIN, 0};
        int ready = ::poll(&p, 1, millisecondsUntil(deadline, limits.cancel));
        if (ready < 0 && errno == EINTR) continue;
        if (ready == 0) {
            if (Clock::now() >= deadline) return ReadEnd::TimedOut;
            continue;
        }
        ssize_t n = ::read(fd, chunk.data(), chunk.size());
        if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
        if (n <= 0) return ReadEnd::EndOfFile;
        if (out.size() + static_cast<std::uint64_t>(n) > limits.maxOutputBytes) return ReadEnd::TooLarge;
        out.insert(out.end(), chunk.begin(), chunk.begin() + n);
    }
}

// The child may close its output and still linger: give it until the deadline to exit.
bool reapBefore(pid_t pid, Clock::time_point deadline, const std::atomic<bool>* cancel, int& status) {
    for (;;) {
        pid_t done = ::waitpid(pid, &status, WNOHANG);
        if (done == pid) return true;
        if (done < 0 && errno != EINTR) return true; // already reaped elsewhere: nothing left to wait for
        if (Clock::now() >= deadline || cancelled(cancel)) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
}

void killAndReap(pid_t pid) {
    ::kill(pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
}

ChildOutcome outcomeFromStatus(int status, std::vector<std::uint8_t> output) {
    ChildOutcome outcome;
    if (WIFSIGNALED(status)) {
        outcome.kind = ChildOutcome::Kind::Signalled;
        outcome.code = WTERMSIG(status);
        return outcome;
    }
    outcome.kind = ChildOutcome::Kind::Exited;
    outcome.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    outcome.output = std::move(output);
    return outcome;
}

} // namespace

ChildOutcome runChild(const std::vector<std::string>& argv, const ChildLimits& limits) {
    const Clock::time_point deadline = Clock::now() + limits.timeout;
    int fds[2];
    if (argv.empty() || ::pipe2(fds, O_CLOEXEC) != 0) return {ChildOutcome::Kind::SpawnFailed, errno, {}};
    Fd readEnd(fds[0]);
    Fd writeEnd(fds[1]);

    pid_t pid = 0;
    if (int error = spawnWithStdout(argv, writeEnd.get(), pid); error != 0)
        return {ChildOutcome::Kind::SpawnFailed, error, {}};
    writeEnd.reset(); // so that the child's exit ends our read with EOF

    std::vector<std::uint8_t> output;
    ReadEnd end = readUntilEnd(readEnd.get(), deadline, limits, output);
    if (end != ReadEnd::EndOfFile) {
        killAndReap(pid);
        if (end == ReadEnd::Cancelled) return {ChildOutcome::Kind::Cancelled, 0, {}};
        return {end == ReadEnd::TimedOut ? ChildOutcome::Kind::TimedOut : ChildOutcome::Kind::OutputTooLarge, 0, {}};
    }
    int status = 0;
    if (!reapBefore(pid, deadline, limits.cancel, status)) {
        killAndReap(pid);
        return {cancelled(limits.cancel) ? ChildOutcome::Kind::Cancelled : ChildOutcome::Kind::TimedOut, 0, {}};
    }
    return outcomeFromStatus(status, std::move(output));
}

} // namespace glint
