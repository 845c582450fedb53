// tinygltf loads the buffers and images of an already validated document, through Glint's confined
// file callbacks. Its image callback decodes nothing: it keeps the encoded bytes, so that saving
// never re-encodes and decoding can wait until (and unless) a renderer needs the pixels.
#include "gltf_reader.h"
#include "scene/io/files/confined_fs.h"

namespace glint {

namespace {

bool keepEncodedBytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*)
{
    image->image.assign(bytes, bytes + size);
    image->width = -1;
    image->height = -1;
    return true;
}

std::string firstLine(const std::string& text)
{
    const std::string line = text.substr(0, text.find('\n'));
    return line.empty() ? "tinygltf refused the file" : line;
}

} // namespace

tinygltf::Model loadWithTinygltf(std::span<const std::uint8_t> bytes, const GltfSource& source, ConfinedFolder& folder, const std::string& file)
{
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(confinedFsCallbacks(&folder));
    loader.SetImageLoader(&keepEncodedBytes, nullptr);
    tinygltf::Model model;
    std::string error;
    std::string warning;
    const std::string baseDir = folder.root.string();
    const bool ok = source.glb
        ? loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(), static_cast<unsigned int>(bytes.size()), baseDir)
        : loader.LoadASCIIFromString(&model, &error, &warning, source.json.data(), static_cast<unsigned int>(source.json.size()), baseDir);
    if (!ok) throw FileError(file, "invalid-gltf", "tinygltf: " + firstLine(error));
    return model;
}

} // namespace glint
