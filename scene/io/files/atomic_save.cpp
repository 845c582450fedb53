#include "atomic_save.h"

#include "scene/core/diagnostics.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <set>
#include <string>

namespace glint {

namespace {

const std::string kTemporaryMarker = ".glint-tmp";

// ".<name>.glint-tmp<n>" (n < 0: the prefix without a number). Built by appending, which also keeps
// GCC 12 from a false -Wrestrict on chained operator+.
std::string temporaryName(const std::filesystem::path& final, int n)
{
    std::string name = ".";
    name += final.filename().string();
    name += kTemporaryMarker;
    if (n >= 0) name += std::to_string(n);
    return name;
}

std::string errnoText() { return std::strerror(errno); }

struct Temporary {
    std::filesystem::path temporary;
    std::filesystem::path final;
};

// Removes every temporary it still owns when the save fails part-way.
class TemporaryFiles {
public:
    ~TemporaryFiles()
    {
        for (const Temporary& t : pending_) ::unlink(t.temporary.c_str());
    }
    void add(Temporary t) { pending_.push_back(std::move(t)); }
    Temporary take(const std::filesystem::path& final)
    {
        auto it = std::find_if(pending_.begin(), pending_.end(), [&](const Temporary& t) { return t.final == final; });
        Temporary t = *it;
        pending_.erase(it);
        return t;
    }

private:
    std::vector<Temporary> pending_;
};

void writeAll(int fd, const std::vector<std::uint8_t>& bytes, const std::filesystem::path& final)
{
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw FileError(final.string(), "write-failed", "cannot write: " + errnoText());
        done += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0) throw FileError(final.string(), "write-failed", "cannot flush to disk: " + errnoText());
}

// Creates ".<name>.glint-tmp<N>" exclusively, with N the first number that is free and no final name.
int createTemporary(const std::filesystem::path& final, const std::set<std::filesystem::path>& finals,
                    std::filesystem::path& temporary)
{
    for (int n = 0; n < 1000; ++n) {
        temporary = final.parent_path() / temporaryName(final, n);
        if (finals.count(temporary)) continue;
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) return fd;
        if (errno != EEXIST)
            throw FileError(final.string(), "write-failed", "cannot create a temporary file in its folder: " + errnoText());
    }
    throw FileError(final.string(), "write-failed", "too many leftover temporary files in its folder");
}

void writeTemporary(const PendingFile& file, const std::set<std::filesystem::path>& finals, TemporaryFiles& temporaries)
{
    std::error_code ec;
    std::filesystem::create_directories(file.path.parent_path(), ec);
    if (ec) throw FileError(file.path.string(), "write-failed", "cannot create its folder: " + ec.message());
    std::filesystem::path temporary;
    const int fd = createTemporary(file.path, finals, temporary);
    temporaries.add({temporary, file.path});
    try {
        writeAll(fd, file.bytes, file.path);
    } catch (...) {
        ::close(fd);
        throw;
    }
    if (::close(fd) != 0) throw FileError(file.path.string(), "write-failed", "cannot close: " + errnoText());
}

void syncFolder(const std::filesystem::path& folder)
{
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) throw FileError(folder.string(), "sync-failed", "cannot open the folder to sync it: " + errnoText());
    const int result = ::fsync(fd);
    const std::string error = result != 0 ? errnoText() : "";
    ::close(fd);
    if (result != 0) throw FileError(folder.string(), "sync-failed", "cannot sync the folder: " + error);
}

// Leftovers of an interrupted earlier save of these same files.
void removeStaleTemporaries(const std::filesystem::path& final)
{
    std::error_code ec;
    const std::string prefix = temporaryName(final, -1);
    for (const auto& entry : std::filesystem::directory_iterator(final.parent_path(), ec)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(prefix, 0) == 0 && isTemporaryName(entry.path())) std::filesystem::remove(entry.path(), ec);
    }
}

} // namespace

bool isTemporaryName(const std::filesystem::path& file)
{
    const std::string name = file.filename().string();
    const std::size_t marker = name.rfind(kTemporaryMarker);
    if (name.empty() || name.front() != '.' || marker == std::string::npos) return false;
    const std::string number = name.substr(marker + kTemporaryMarker.size());
    return !number.empty() && std::all_of(number.begin(), number.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::string finalNameOfTemporary(const std::filesystem::path& file)
{
    if (!isTemporaryName(file)) return {};
    const std::string name = file.filename().string();
    return name.substr(1, name.rfind(kTemporaryMarker) - 1);
}

std::vector<std::filesystem::path> saveFilesAtomically(const std::vector<std::vector<PendingFile>>& stages)
{
    std::set<std::filesystem::path> finals;
    for (const auto& stage : stages)
        for (const PendingFile& file : stage) finals.insert(file.path);
    for (const auto& final : finals) removeStaleTemporaries(final);

    TemporaryFiles temporaries;
    for (const auto& stage : stages)
        for (const PendingFile& file : stage) writeTemporary(file, finals, temporaries);

    std::vector<std::filesystem::path> written;
    for (const auto& stage : stages) {
        std::set<std::filesystem::path> folders;
        for (const PendingFile& file : stage) {
            const Temporary t = temporaries.take(file.path);
            if (::rename(t.temporary.c_str(), t.final.c_str()) != 0) {
                const std::string error = errnoText();
                ::unlink(t.temporary.c_str());
                throw FileError(t.final.string(), "write-failed", "cannot move the new file into place: " + error);
            }
            written.push_back(file.path);
            folders.insert(file.path.parent_path());
        }
        for (const auto& folder : folders) syncFolder(folder);
    }
    return written;
}

} // namespace glint
