// glint-import-worker: reads one file with Assimp in a process of its own, converts it to a glint
// scene and writes a WorkerReply (worker_reply.h) to standard output. importScene() runs it.
//
//   glint-import-worker [--max-memory BYTES] [--max-triangles N] FILE
//
// For tests of the isolation, GLINT_IMPORT_WORKER_TEST makes it misbehave instead:
// crash (abort), hang, flood (endless output), garbage (an unreadable reply), exit (status 3).
#include "assimp_read.h"
#include "worker_reply.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <new>
#include <optional>
#include <string>

namespace {

struct WorkerArguments {
    std::string file;
    std::uint64_t maxMemoryBytes = 0;
    std::uint64_t maxTriangles = 64'000'000;
};

std::optional<std::uint64_t> parseCount(const char* text) {
    char* end = nullptr;
    errno = 0;
    unsigned long long value = std::strtoull(text, &end, 10);
    if (errno != 0 || end == text || *end != '\0' || text[0] == '-') return std::nullopt;
    return value;
}

std::optional<WorkerArguments> parseArguments(int argc, char** argv) {
    WorkerArguments args;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if ((flag == "--max-memory" || flag == "--max-triangles") && i + 1 < argc) {
            auto value = parseCount(argv[++i]);
            if (!value) return std::nullopt;
            (flag == "--max-memory" ? args.maxMemoryBytes : args.maxTriangles) = *value;
        } else if (args.file.empty() && !flag.starts_with("--")) {
            args.file = flag;
        } else {
            return std::nullopt;
        }
    }
    if (args.file.empty()) return std::nullopt;
    return args;
}

bool writeAll(int fd, const std::vector<std::uint8_t>& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

void misbehaveIfAsked() {
    const char* mode = std::getenv("GLINT_IMPORT_WORKER_TEST");
    if (!mode) return;
    const std::string m = mode;
    if (m == "crash") std::abort();
    if (m == "hang")
        for (;;) ::pause();
    if (m == "flood") {
        const std::vector<std::uint8_t> block(1 << 20, 0x55);
        while (writeAll(1, block)) {
        }
        std::_Exit(0);
    }
    if (m == "garbage") {
        writeAll(1, {'n', 'o', 't', ' ', 'a', ' ', 'r', 'e', 'p', 'l', 'y'});
        std::_Exit(0);
    }
    if (m == "exit") std::_Exit(3);
}

// Sanitizer runtimes reserve terabytes of address space up front, so the cap only applies to
// ordinary builds.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
constexpr bool kAddressSanitizer = __has_feature(address_sanitizer);
#else
constexpr bool kAddressSanitizer = false;
#endif

void limitAddressSpace(std::uint64_t bytes) {
    if (bytes == 0 || kAddressSanitizer) return;
    rlimit limit{bytes, bytes};
    ::setrlimit(RLIMIT_AS, &limit);
}

// A crash on a hostile file is expected and reported by the parent; it must not leave a core file
// in the user's working folder.
void disableCoreDumps() {
    rlimit none{0, 0};
    ::setrlimit(RLIMIT_CORE, &none);
}

// Some importers print to stdout; the reply gets a descriptor of its own so nothing else lands in it.
int takeStdoutForReply() {
    const int replyFd = ::dup(1);
    ::dup2(2, 1);
    return replyFd;
}

glint::WorkerReply importToReply(const WorkerArguments& args) {
    glint::WorkerReply reply;
    try {
        glint::ConvertOptions options;
        options.sourceFile = args.file;
        options.maxTriangles = args.maxTriangles;
        glint::LoadResult result = glint::readWithAssimp(args.file, options);
        glint::SaveReport report;
        reply.glb = glint::writeGlb(result.scene, &report);
        reply.warnings = std::move(result.warnings);
        // A missing texture was named by the importer already; that the transfer GLB then holds only
        // its URI says nothing more to the user.
        for (glint::Warning& w : report.dropped)
            if (w.code != "image-bytes-missing") reply.warnings.push_back(std::move(w));
    } catch (const glint::FileError& e) {
        reply.errorCode = e.code();
        reply.errorMessage = e.message();
    } catch (const std::bad_alloc&) {
        reply.errorCode = "out-of-memory";
        reply.errorMessage = "the importer ran out of memory (limit " + std::to_string(args.maxMemoryBytes) + " bytes)";
    } catch (const std::exception& e) {
        reply.errorCode = "import-failed";
        reply.errorMessage = e.what();
    }
    return reply;
}

} // namespace

int main(int argc, char** argv) {
    disableCoreDumps();
    misbehaveIfAsked();
    const std::optional<WorkerArguments> args = parseArguments(argc, argv);
    if (!args) {
        std::cerr << "usage: glint-import-worker [--max-memory BYTES] [--max-triangles N] FILE\n";
        return 2;
    }
    const int replyFd = takeStdoutForReply();
    if (replyFd < 0) return 4;
    limitAddressSpace(args->maxMemoryBytes);
    const glint::WorkerReply reply = importToReply(*args);
    if (!writeAll(replyFd, glint::encodeWorkerReply(reply))) return 4;
    return reply.errorCode.empty() ? 0 : 1;
}
