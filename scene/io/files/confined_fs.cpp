#include "confined_fs.h"

#include "scene/core/diagnostics.h"

#include <fstream>
#include <iterator>
#include <system_error>

namespace glint {

namespace fs = std::filesystem;

namespace {

bool isInside(const fs::path& root, const fs::path& candidate)
{
    auto r = root.begin();
    auto c = candidate.begin();
    for (; r != root.end(); ++r, ++c) {
        if (r->empty()) continue; // a trailing separator on the root
        if (c == candidate.end() || *r != *c) return false;
    }
    return true;
}

fs::path canonicalRoot(const ConfinedFolder& folder)
{
    std::error_code error;
    fs::path root = fs::weakly_canonical(folder.root.empty() ? fs::path(".") : folder.root, error);
    return error ? folder.root.lexically_normal() : root;
}

// tinygltf joins its base directory and the URI; the callbacks see that joined path.
std::optional<std::string> absoluteProblem(const ConfinedFolder& folder, const fs::path& path)
{
    std::error_code error;
    const fs::path resolved = fs::weakly_canonical(path, error);
    if (error) return "cannot resolve '" + path.filename().string() + "': " + error.message();
    if (!isInside(canonicalRoot(folder), resolved))
        return "'" + path.filename().string() + "' resolves (through '..' or a symlink) to a place outside the scene's folder: refused";
    return std::nullopt;
}

bool fileExists(const std::string& path, void* user)
{
    const auto* folder = static_cast<const ConfinedFolder*>(user);
    std::error_code error;
    return !absoluteProblem(*folder, path) && fs::is_regular_file(path, error);
}

// No `~` or shell expansion (tinygltf's default would run wordexp on the URI).
std::string expandFilePath(const std::string& path, void*) { return path; }

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user)
{
    const auto* folder = static_cast<const ConfinedFolder*>(user);
    if (auto problem = absoluteProblem(*folder, path)) {
        if (err) *err += *problem + "\n";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        if (err) *err += "cannot open '" + fs::path(path).filename().string() + "'\n";
        return false;
    }
    out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return true;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*)
{
    if (err) *err += "the glTF reader never writes files\n";
    return false;
}

} // namespace

std::optional<std::string> confinementProblem(const ConfinedFolder& folder, const std::string& relative)
{
    const fs::path path(relative);
    if (relative.empty()) return std::string("an empty path");
    if (path.is_absolute() || path.has_root_name() || path.has_root_directory())
        return "'" + relative + "' is an absolute path: only paths inside the scene's folder are allowed";
    const fs::path normal = path.lexically_normal();
    if (!normal.empty() && *normal.begin() == "..")
        return "'" + relative + "' leads out of the scene's folder ('..'): refused";
    if (auto problem = absoluteProblem(folder, folder.root / path))
        return "'" + relative + "' resolves through a symlink to a place outside the scene's folder: refused";
    return std::nullopt;
}

fs::path confinedPath(const ConfinedFolder& folder, const std::string& relative, const std::string& file)
{
    if (auto problem = confinementProblem(folder, relative)) throw FileError(file, "uri-escapes-folder", *problem);
    return folder.root / relative;
}

tinygltf::FsCallbacks confinedFsCallbacks(ConfinedFolder* folder)
{
    return tinygltf::FsCallbacks{&fileExists, &expandFilePath, &readWholeFile, &refuseWrite, folder};
}

} // namespace glint
