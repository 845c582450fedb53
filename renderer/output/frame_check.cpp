#include "renderer/output/frame_check.h"

#include "renderer/output/image_files.h"

#include <OpenImageIO/imageio.h>

#include <vector>

namespace glint::renderer {

namespace {

std::optional<std::string> recordedHash(const OIIO::ImageSpec& spec) {
    const std::string own = spec.get_string_attribute("glint:settingsHash");
    if (!own.empty()) return own;
    const std::string description = spec.get_string_attribute("ImageDescription");
    const std::string prefix = kSettingsHashPrefix;
    if (description.compare(0, prefix.size(), prefix) == 0) return description.substr(prefix.size());
    return std::nullopt;
}

} // namespace

std::optional<std::string> completeFrameSettingsHash(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) return std::nullopt;
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) {
        (void)OIIO::geterror(); // consumed, so it does not leak into a later message
        return std::nullopt;
    }
    const OIIO::ImageSpec spec = in->spec();
    const auto hash = recordedHash(spec);
    // Decoding every pixel is what proves the file complete: headers survive truncation.
    std::vector<float> pixels(spec.image_pixels() * std::size_t(spec.nchannels));
    const bool decoded = hash && in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data());
    if (!decoded) (void)in->geterror();
    in->close();
    return decoded ? hash : std::nullopt;
}

std::map<std::string, std::string> readGlintMetadata(const std::filesystem::path& file) {
    std::map<std::string, std::string> out;
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) {
        (void)OIIO::geterror();
        return out;
    }
    for (const auto& attribute : in->spec().extra_attribs) {
        const std::string name = attribute.name().string();
        if (name.rfind("glint:", 0) == 0 && attribute.type() == OIIO::TypeDesc::STRING)
            out[name.substr(6)] = attribute.get_string();
    }
    return out;
}

} // namespace glint::renderer
