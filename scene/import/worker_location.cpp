#include "import.h"

#include <system_error>

namespace glint {

namespace {
constexpr const char* kWorkerName = "glint-import-worker";

bool isExecutableFile(const std::filesystem::path& p) {
    std::error_code ec;
    auto status = std::filesystem::status(p, ec);
    return !ec && std::filesystem::is_regular_file(status) &&
           (status.permissions() & std::filesystem::perms::owner_exec) != std::filesystem::perms::none;
}
} // namespace

// Next to the running executable (the build tree and relocatable bundles), then the installed
// layout <prefix>/bin/glint -> <prefix>/libexec/glint/glint-import-worker.
std::filesystem::path findImportWorker() {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    const std::filesystem::path dir = self.parent_path();
    for (const auto& candidate : {dir / kWorkerName, dir / ".." / "libexec" / "glint" / kWorkerName})
        if (isExecutableFile(candidate)) return candidate.lexically_normal();
    return {};
}

} // namespace glint
