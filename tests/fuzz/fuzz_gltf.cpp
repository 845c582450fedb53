// Fuzzes the glTF/GLB loader from memory. Any exception is a clean rejection; a crash, a hang, an
// unbounded allocation or a sanitizer report is a bug.
#include "scene/io/scene_io.h"

#include <cstddef>
#include <cstdint>
#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    glint::LoadOptions options;
    options.loadProjectFile = false;
    options.maxBufferBytes = 64u << 20;
    options.maxImagePixels = 4096u * 4096u;
    try {
        // A folder that does not exist: external URIs must fail cleanly, never escape.
        glint::loadGltfFromMemory({data, size}, "/nonexistent-glint-fuzz-folder", "fuzz.glb", options);
    } catch (const std::exception&) {
    }
    return 0;
}
