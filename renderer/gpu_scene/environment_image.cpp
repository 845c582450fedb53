#include "renderer/gpu_scene/environment_image.h"

#include "renderer/gpu_scene/environment_cube.h"

#include "scene/core/diagnostics.h"
#include "scene/io/oiio/oiio_image_decoder.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <fstream>
#include <utility>

namespace glint::renderer {
namespace {

EnvironmentImage readEnvironment(OIIO::ImageInput& input, const std::string& name, const DecodeLimits& limits) {
    const OIIO::ImageSpec& spec = input.spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        throw FileError(name, "environment-empty", "the environment image has no pixels");
    // The declared size against the limits before anything is allocated: 3 floats per pixel.
    if (const std::string error = openedLimitError(spec, 3, sizeof(float), limits); !error.empty())
        throw FileError(name, spec.deep ? "environment-unreadable" : "environment-too-large", "cannot read the environment image: " + error);
    // Its importance-sampling table (renderer/cpu_twin/env_sampling.h) is max(width, height) + 1 by
    // height + 1 floats: quadratic in the height, so a tall, narrow image (7 x 38661 asked for 6 GB)
    // is refused too. A cube map becomes 4 x 2 faces first.
    std::int64_t width = spec.width, height = spec.height;
    if (const auto layout = cubeLayoutOf(spec.width, spec.height)) {
        const std::int64_t side = cubeFaceSide(*layout, spec.width);
        width = 4 * side;
        height = 2 * side;
    }
    const std::uint64_t table = static_cast<std::uint64_t>(std::max(width, height) + 1) * static_cast<std::uint64_t>(height + 1) * sizeof(float);
    if (table > limits.maxBytes)
        throw FileError(name, "environment-too-large",
                        "cannot read the environment image: its sampling table for " + std::to_string(width) + "x" + std::to_string(height) +
                            " pixels takes " + std::to_string((table + (1u << 20) - 1) >> 20) + " MiB, more than the limit of " +
                            std::to_string(limits.maxBytes >> 20) + " MiB (an equirectangular image is twice as wide as high)");
    EnvironmentImage image;
    image.width = spec.width;
    image.height = spec.height;
    const std::size_t pixels = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
    image.rgb.resize(pixels * 3);
    if (spec.nchannels >= 3) { // channels 0..2 straight into the image
        if (!readConvertedPixels(input, 3, OIIO::TypeDesc::FLOAT, image.rgb.data(), 3 * sizeof(float)))
            throw FileError(name, "environment-unreadable", "cannot decode the environment image: " + input.geterror());
    } else { // grey, or grey and alpha: the grey on all three
        std::vector<float> grey(pixels);
        if (!readConvertedPixels(input, 1, OIIO::TypeDesc::FLOAT, grey.data(), sizeof(float)))
            throw FileError(name, "environment-unreadable", "cannot decode the environment image: " + input.geterror());
        for (std::size_t i = 0; i < pixels; ++i) image.rgb[i * 3] = image.rgb[i * 3 + 1] = image.rgb[i * 3 + 2] = grey[i];
    }
    // A cube map (a cross or a strip of six faces, told by its shape) becomes a latitude-longitude map.
    if (const auto layout = cubeLayoutOf(image.width, image.height)) return equirectFromCube(image, *layout);
    return image;
}

// Glint's own header checks before OpenImageIO opens the file (libjpeg allocates a progressive
// JPEG's coefficients for the declared size on opening, OpenEXR an attribute's declared size).
void checkHeader(std::span<const std::uint8_t> header, std::uint64_t fileSize, const std::string& name, const DecodeLimits& limits) {
    if (const std::string error = headerLimitError(header, fileSize, 3, sizeof(float), limits); !error.empty())
        throw FileError(name, "environment-too-large", "cannot read the environment image: " + error);
}

} // namespace

EnvironmentImage loadEnvironmentImage(const std::filesystem::path& file, const DecodeLimits& limits) {
    const std::string name = file.string();
    std::ifstream in(file, std::ios::binary);
    std::vector<std::uint8_t> header(256 * 1024);
    in.read(reinterpret_cast<char*>(header.data()), static_cast<std::streamsize>(header.size()));
    header.resize(static_cast<std::size_t>(in.gcount()));
    std::error_code ec;
    const std::uint64_t size = std::filesystem::file_size(file, ec);
    const std::uint64_t fileSize = ec ? header.size() : size;
    const bool wholeFileRead = fileSize <= header.size();
    if (!memoryImageName(header)) { // a format Glint does not sniff (.tga, .dds, ...): OpenImageIO opens it by name
        checkHeader(header, fileSize, name, limits);
        auto input = OIIO::ImageInput::open(name);
        if (!input) throw FileError(name, "environment-unreadable", "cannot read the environment image: " + OIIO::geterror());
        return readEnvironment(*input, name, limits);
    }
    // The formats Glint knows are decoded from memory, as textures are, so the memory path checks the
    // whole header: an OpenEXR header may run past the first bytes (and declare a second, larger data
    // window there), and a JPEG is opened without its metadata (OpenImageIO 2.4 reads past the end
    // of a broken IPTC block: jpegWithoutMetadata). A bomb the first bytes show is refused before the
    // rest is read.
    std::vector<std::uint8_t> bytes = std::move(header);
    if (!wholeFileRead) {
        checkHeader(bytes, fileSize, name, limits);
        if (fileSize > 2 * limits.maxBytes)
            throw FileError(name, "environment-too-large",
                            "cannot read the environment image: the file holds " + std::to_string(fileSize) + " bytes, more than twice the " +
                                std::to_string(limits.maxBytes) + " bytes an environment may decode to");
        const std::size_t read = bytes.size();
        bytes.resize(fileSize);
        in.read(reinterpret_cast<char*>(bytes.data() + read), static_cast<std::streamsize>(fileSize - read));
        bytes.resize(read + static_cast<std::size_t>(in.gcount()));
    }
    return decodeEnvironmentImage(bytes, name, limits);
}

EnvironmentImage decodeEnvironmentImage(std::span<const std::uint8_t> encoded, const std::string& name, const DecodeLimits& limits) {
    checkHeader(encoded, encoded.size(), name, limits); // refuses bombs of the formats it knows, passes the rest
    const MemoryImage opened = openImageFromMemory(encoded);
    if (!opened.input) throw FileError(name, "environment-unreadable", "cannot read the environment image: " + opened.error);
    return readEnvironment(*opened.input, name, limits);
}

} // namespace glint::renderer
