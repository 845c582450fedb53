#include "renderer/output/image_files.h"

#include "scene/core/diagnostics.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <stdexcept>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace glint::renderer {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// Interleaves the beauty pass and the requested AOVs into one float buffer with EXR channel names.
struct Planes {
    std::vector<std::string> names;
    std::vector<float> pixels;
};

Planes exrPlanes(const RenderOutput& img, const ExrLayers& layers) {
    Planes p;
    p.names = {"R", "G", "B", "A"};
    if (layers.albedo) p.names.insert(p.names.end(), {"albedo.R", "albedo.G", "albedo.B"});
    if (layers.normal) p.names.insert(p.names.end(), {"N.X", "N.Y", "N.Z"});
    if (layers.depth) p.names.push_back("Z");
    if (layers.objectId) p.names.push_back("id");
    if (layers.variance) p.names.insert(p.names.end(), {"variance.R", "variance.G", "variance.B"});
    if (layers.bvhCost) p.names.push_back("bvh_cost");
    const std::size_t count = std::size_t(img.width) * std::size_t(img.height);
    if (layers.bvhCost && img.bvhCost.size() != count)
        throw std::invalid_argument("the bvh_cost AOV is available for stills and per-frame renders only");
    p.pixels.reserve(count * p.names.size());
    for (std::size_t i = 0; i < count; ++i) {
        p.pixels.insert(p.pixels.end(), img.radiance.begin() + std::ptrdiff_t(i * 4), img.radiance.begin() + std::ptrdiff_t(i * 4 + 4));
        if (layers.albedo) p.pixels.insert(p.pixels.end(), img.albedo.begin() + std::ptrdiff_t(i * 3), img.albedo.begin() + std::ptrdiff_t(i * 3 + 3));
        if (layers.normal) p.pixels.insert(p.pixels.end(), img.normal.begin() + std::ptrdiff_t(i * 3), img.normal.begin() + std::ptrdiff_t(i * 3 + 3));
        if (layers.depth) p.pixels.push_back(img.depth[i]);
        if (layers.objectId) p.pixels.push_back(img.objectId[i]);
        if (layers.variance) p.pixels.insert(p.pixels.end(), img.variance.begin() + std::ptrdiff_t(i * 3), img.variance.begin() + std::ptrdiff_t(i * 3 + 3));
        if (layers.bvhCost) p.pixels.push_back(img.bvhCost[i]);
    }
    return p;
}

void writeWithOiio(const std::filesystem::path& target, const std::filesystem::path& temp, const OIIO::ImageSpec& spec,
                   const void* pixels) {
    // OIIO picks the format from the name, so the temporary keeps the extension.
    auto out = OIIO::ImageOutput::create(target.string()); // by the final name's extension
    if (!out) throw FileError(target.string(), "image-format", "no writer for this format: " + OIIO::geterror());
    if (!out->open(temp.string(), spec) || !out->write_image(spec.format, pixels) || !out->close())
        throw FileError(target.string(), "write-failed", "cannot write image: " + out->geterror());
}

std::filesystem::path temporaryNameFor(const std::filesystem::path& file) {
    // A leading dot and a ".partial" infix: never matches a frame pattern or the final name. The
    // process id keeps two processes that render the same frame (overlapping shards) apart.
    std::string name = file.stem().string();
    name.insert(0, 1, '.');
    name.append(".partial-").append(std::to_string(::getpid())).append(file.extension().string());
    return file.parent_path() / name;
}

// The data reaches the disk before the name does: after a crash or power loss the final name
// holds either nothing or the whole image.
bool flushToDisk(const std::filesystem::path& temp) {
    const int fd = ::open(temp.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool synced = ::fsync(fd) == 0;
    return ::close(fd) == 0 && synced;
}

void publish(const std::filesystem::path& temp, const std::filesystem::path& file) {
    std::error_code ec;
    if (!flushToDisk(temp)) {
        std::filesystem::remove(temp, ec);
        throw FileError(file.string(), "write-failed", "cannot flush the image to disk");
    }
    std::filesystem::rename(temp, file, ec);
    if (ec) {
        std::filesystem::remove(temp, ec);
        throw FileError(file.string(), "write-failed", "cannot move the finished image into place");
    }
}

OIIO::ImageSpec specFor(const RenderOutput& img, ImageFormat format, const Planes* planes) {
    if (format == ImageFormat::Exr) {
        OIIO::ImageSpec spec(img.width, img.height, int(planes->names.size()), OIIO::TypeDesc::FLOAT);
        spec.channelnames = planes->names;
        spec.alpha_channel = 3;
        spec.z_channel = -1;
        spec.attribute("compression", "zip");
        return spec;
    }
    OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::UINT8);
    spec.alpha_channel = 3;
    if (format == ImageFormat::Jpeg) spec.attribute("Compression", "jpeg:95");
    spec.attribute("oiio:ColorSpace", "sRGB");
    return spec;
}

} // namespace

ImageFormat imageFormatFor(const std::filesystem::path& file) {
    const std::string ext = lower(file.extension().string());
    if (ext == ".exr") return ImageFormat::Exr;
    if (ext == ".png") return ImageFormat::Png;
    if (ext == ".jpg" || ext == ".jpeg") return ImageFormat::Jpeg;
    if (ext == ".tif" || ext == ".tiff") return ImageFormat::Tiff;
    throw std::invalid_argument("unsupported image format '" + ext + "' (use .exr, .png, .jpg or .tif)");
}

ExrLayers parseAovList(const std::string& list) {
    const std::string l = lower(list);
    if (l == "all") return {};
    ExrLayers none{false, false, false, false};
    if (l == "none") return none;
    std::size_t start = 0;
    while (start <= l.size()) {
        std::size_t comma = std::min(l.find(',', start), l.size());
        const std::string item = l.substr(start, comma - start);
        if (item == "albedo") none.albedo = true;
        else if (item == "normal") none.normal = true;
        else if (item == "depth") none.depth = true;
        else if (item == "id") none.objectId = true;
        else if (item == "variance") none.variance = true;
        else if (item == "bvh_cost") none.bvhCost = true;
        else throw std::invalid_argument("unknown AOV '" + item + "' (use all, none or a list of albedo, normal, depth, id, variance, bvh_cost)");
        start = comma + 1;
    }
    return none;
}

void checkOutputWritable(const std::filesystem::path& file) {
    const std::filesystem::path folder = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec))
        throw FileError(file.string(), "no-folder", "the output folder does not exist");
    if (::access(folder.c_str(), W_OK) != 0)
        throw FileError(file.string(), "not-writable", "the output folder is not writable");
}

void writeRenderImage(const std::filesystem::path& file, const RenderOutput& img, const ExrLayers& layers,
                      const ImageMetadata& metadata) {
    const ImageFormat format = imageFormatFor(file);
    const std::filesystem::path temp = temporaryNameFor(file);
    Planes planes;
    if (format == ImageFormat::Exr) planes = exrPlanes(img, layers);
    OIIO::ImageSpec spec = specFor(img, format, &planes);
    for (const auto& [key, value] : metadata) {
        // The render time is the one thing that differs between identical renders; CONTRACTS.md
        // allows it in EXR headers only, so 8-bit files of the same render are the same bytes.
        if (key == "renderTimeMs" && format != ImageFormat::Exr) continue;
        spec.attribute("glint:" + key, value);
    }
    // PNG keeps the glint: attributes, TIFF and JPEG only standard ones: the description carries
    // the settings hash in every format, so --resume works alike for all of them.
    if (auto hash = metadata.find("settingsHash"); hash != metadata.end())
        spec.attribute("ImageDescription", kSettingsHashPrefix + hash->second);
    // OpenImageIO stamps the wall-clock time into an EXR that names none (capDate), which would make
    // two identical renders differ; the render time is recorded, and allowed to differ, on its own.
    if (format == ImageFormat::Exr) spec.attribute("DateTime", "");
    try {
        writeWithOiio(file, temp, spec, format == ImageFormat::Exr ? static_cast<const void*>(planes.pixels.data())
                                                                     : static_cast<const void*>(img.tonemapped.data()));
    } catch (...) {
        std::error_code ec;
        std::filesystem::remove(temp, ec);
        throw;
    }
    publish(temp, file);
}

} // namespace glint::renderer
