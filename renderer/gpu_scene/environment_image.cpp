#include "renderer/gpu_scene/environment_image.h"

#include "renderer/gpu_scene/environment_cube.h"

#include "scene/core/diagnostics.h"

#include <OpenImageIO/imageio.h>

namespace glint::renderer {

EnvironmentImage loadEnvironmentImage(const std::filesystem::path& file) {
    auto input = OIIO::ImageInput::open(file.string());
    if (!input) throw FileError(file.string(), "environment-unreadable", "cannot read the environment image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        throw FileError(file.string(), "environment-empty", "the environment image has no pixels");
    EnvironmentImage image;
    image.width = spec.width;
    image.height = spec.height;
    image.rgb.resize(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) * 3);
    // Read channels 0..2 (a one-channel image is repeated into grey below).
    const int channels = std::min(spec.nchannels, 3);
    std::vector<float> pixels(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) * static_cast<std::size_t>(channels));
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
        throw FileError(file.string(), "environment-unreadable", "cannot decode the environment image: " + input->geterror());
    for (std::size_t i = 0; i < image.rgb.size() / 3; ++i)
        for (std::size_t c = 0; c < 3; ++c)
            image.rgb[i * 3 + c] = pixels[i * static_cast<std::size_t>(channels) + std::min<std::size_t>(c, static_cast<std::size_t>(channels) - 1)];
    // A cube map (a cross or a strip of six faces, told by its shape) becomes a latitude-longitude map.
    if (const auto layout = cubeLayoutOf(image.width, image.height)) return equirectFromCube(image, *layout);
    return image;
}

} // namespace glint::renderer
