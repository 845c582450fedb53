#pragma once
// Saving a set of files so that a crash never leaves a half-written file under a final name.
//
// Every file is first written in full to a temporary name in its own folder and fsynced; the
// temporary name, ".<final name>.glint-tmp<N>", is checked against every final name of the set, so
// it never matches one. Then the stages are renamed into place in order, each followed by an fsync of
// the folders it touched, which makes the order durable across power loss too. Glint saves a scene
// in three stages: (1) the buffer and the images, (2) the .gltf/.glb, (3) the project file.
//
// What a crash (or SIGKILL) at each step leaves behind:
//  - while temporaries are written: the previous file set, untouched, plus hidden temporaries that
//    the next save of the same files removes;
//  - after stage 1: the previous set is still complete and consistent: the new buffer has a new,
//    content-derived name (<basename>.<hash>.bin) beside the old one, which the old glTF still
//    names. An image rewritten under the same name already has its new content (still loadable);
//  - after stage 2: the new glTF set is complete; the project file is still the previous one, and
//    the new one waits whole under its temporary name: loading reads that one (scene_load.cpp,
//    interruptedProjectFile), so the pair on disk still loads as one save;
//  - after stage 3: the new set is complete; the old buffer is removed after the final folder
//    sync, and one a crash left behind is removed by the next save.
// On a failure (disk full, read-only folder) every temporary is removed and FileError is thrown;
// files already renamed stay (by the order above, the result is still a loadable set).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace glint {

struct PendingFile {
    std::filesystem::path path; // the final name
    std::vector<std::uint8_t> bytes;
};

// Returns the final paths in the order they were renamed into place. Throws FileError.
std::vector<std::filesystem::path> saveFilesAtomically(const std::vector<std::vector<PendingFile>>& stages);

// The temporary-name pattern above, for tests and for clean-up.
bool isTemporaryName(const std::filesystem::path& file);
// The final name a temporary stands for (".a.bin.glint-tmp3" -> "a.bin"); empty for other names.
std::string finalNameOfTemporary(const std::filesystem::path& file);

} // namespace glint
