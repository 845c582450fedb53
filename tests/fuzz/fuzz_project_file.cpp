// Fuzzes the project-file parser. Exceptions are clean rejections; anything else is a bug.
#include "scene/io/project/project_file.h"

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    glint::Warnings warnings;
    try {
        glint::ProjectFile project =
            glint::parseProjectFile(std::string(reinterpret_cast<const char*>(data), size), "fuzz.glint.json", warnings);
        // What parses must also write and parse again.
        glint::parseProjectFile(glint::writeProjectFileText(project), "fuzz.glint.json", warnings);
    } catch (const std::exception&) {
    }
    return 0;
}
