#include "renderer/output/video_frame_image.h"

#include "renderer/output/frame_check.h"
#include "renderer/output/tonemap_cpu.h"
#include "scene/core/diagnostics.h"
#include "scene/core/tonemapper_names.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <charconv>

namespace glint::video {

namespace {

Tonemapper tonemapperNamed(const std::string& name) { return parseTonemapper(name).value_or(Tonemapper::AcesFitted); }

float numberOr(const std::string& text, float fallback) {
    float value = fallback;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size() ? value : fallback;
}

// The colour channels and alpha as RGBA in `format`; a missing alpha becomes opaque.
template <class T>
std::vector<T> readRgba(OIIO::ImageInput& in, const std::filesystem::path& file, OIIO::TypeDesc format, T opaque) {
    const OIIO::ImageSpec& spec = in.spec();
    if (spec.nchannels < 3) throw FileError(file.string(), "read-failed", "a video frame needs RGB channels");
    const std::size_t channels = spec.nchannels >= 4 ? 4 : 3;
    const std::size_t count = std::size_t(spec.width) * std::size_t(spec.height);
    std::vector<T> stored(count * channels);
    if (!in.read_image(0, 0, 0, int(channels), format, stored.data()))
        throw FileError(file.string(), "read-failed", "cannot read the frame: " + in.geterror());
    std::vector<T> rgba(count * 4, opaque);
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t c = 0; c < channels; ++c) rgba[i * 4 + c] = stored[i * channels + c];
    return rgba;
}

// A frame whose data window is only part of its display window (glint render --region) is placed
// where it belongs, black and transparent around it.
std::vector<float> inDisplayWindow(const std::vector<float>& rgba, const OIIO::ImageSpec& spec) {
    if (spec.x == spec.full_x && spec.y == spec.full_y && spec.width == spec.full_width && spec.height == spec.full_height)
        return rgba;
    std::vector<float> full(std::size_t(spec.full_width) * std::size_t(spec.full_height) * 4, 0.0f);
    for (int y = 0; y < spec.height; ++y)
        for (int x = 0; x < spec.width; ++x) {
            const int fx = spec.x - spec.full_x + x, fy = spec.y - spec.full_y + y;
            if (fx < 0 || fy < 0 || fx >= spec.full_width || fy >= spec.full_height) continue;
            const std::size_t from = (std::size_t(y) * std::size_t(spec.width) + std::size_t(x)) * 4;
            const std::size_t to = (std::size_t(fy) * std::size_t(spec.full_width) + std::size_t(fx)) * 4;
            std::copy_n(rgba.begin() + std::ptrdiff_t(from), 4, full.begin() + std::ptrdiff_t(to));
        }
    return full;
}

} // namespace

Rgba8Image loadFrameForVideo(const std::filesystem::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) throw FileError(file.string(), "read-failed", "cannot open the frame: " + OIIO::geterror());
    Rgba8Image image;
    image.width = in->spec().width;
    image.height = in->spec().height;
    const bool linear = in->format_name() == std::string("openexr");
    if (!linear) {
        image.pixels = readRgba<std::uint8_t>(*in, file, OIIO::TypeDesc::UINT8, 255);
        return image;
    }
    const OIIO::ImageSpec spec = in->spec();
    const std::vector<float> radiance = inDisplayWindow(readRgba<float>(*in, file, OIIO::TypeDesc::FLOAT, 1.0f), spec);
    image.width = spec.full_width;
    image.height = spec.full_height;
    in->close();
    const auto metadata = renderer::readGlintMetadata(file);
    const auto get = [&](const char* key) { auto it = metadata.find(key); return it == metadata.end() ? std::string() : it->second; };
    image.pixels = tonemapToSrgb8(radiance, numberOr(get("exposureEv"), 0.0f), tonemapperNamed(get("tonemap")));
    return image;
}

} // namespace glint::video
