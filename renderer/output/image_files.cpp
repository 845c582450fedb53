#include "renderer/output/image_files.h"

#include "scene/core/diagnostics.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
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

// The beauty pass and the requested AOVs interleaved into one float buffer, with EXR channel names.
struct Planes {
    std::vector<std::string> names;
    std::vector<float> pixels;
};

// The pixels written: the render's window (its region), or the whole image when it names none.
ImageWindow dataWindowOf(const RenderOutput& img) {
    const ImageWindow& w = img.window;
    if (w.width <= 0 || w.height <= 0) return {0, 0, img.width, img.height};
    return w;
}

// Appends pixel `i` (row-major over the whole image) of every plane in `p`'s channel order.
void appendPixel(Planes& p, const RenderOutput& img, const ExrLayers& layers, std::size_t i) {
    const auto append = [&p, i](const std::vector<float>& plane, std::size_t channels) {
        p.pixels.insert(p.pixels.end(), plane.begin() + std::ptrdiff_t(i * channels), plane.begin() + std::ptrdiff_t((i + 1) * channels));
    };
    append(img.radiance, 4);
    if (layers.albedo) append(img.albedo, 3);
    if (layers.normal) append(img.normal, 3);
    if (layers.depth) append(img.depth, 1);
    if (layers.objectId) append(img.objectId, 1);
    if (layers.variance) append(img.variance, 3);
    if (layers.bvhCost) append(img.bvhCost, 1);
    if (layers.samples) append(img.sampleCounts, 1);
    for (int k = 0; k < lightPassCount; ++k)
        if (layers.passes.light[std::size_t(k)]) append(img.lightPasses[std::size_t(k)], 3);
    if (layers.passes.vector) append(img.vectors, 2);
}

// The beauty pass and the requested AOVs of the data window, interleaved, with EXR channel names.
Planes exrPlanes(const RenderOutput& img, const ExrLayers& layers) {
    Planes p;
    p.names = {"R", "G", "B", "A"};
    if (layers.albedo) p.names.insert(p.names.end(), {"albedo.R", "albedo.G", "albedo.B"});
    if (layers.normal) p.names.insert(p.names.end(), {"N.X", "N.Y", "N.Z"});
    if (layers.depth) p.names.push_back("Z");
    if (layers.objectId) p.names.push_back("id");
    if (layers.variance) p.names.insert(p.names.end(), {"variance.R", "variance.G", "variance.B"});
    if (layers.bvhCost) p.names.push_back("bvh_cost");
    if (layers.samples) p.names.push_back("samples");
    for (int k = 0; k < lightPassCount; ++k)
        if (layers.passes.light[std::size_t(k)]) {
            const std::string layer = lightPassName(LightPass(k));
            p.names.insert(p.names.end(), {layer + ".R", layer + ".G", layer + ".B"});
        }
    if (layers.passes.vector) p.names.insert(p.names.end(), {"Vector.X", "Vector.Y"});
    const std::size_t count = std::size_t(img.width) * std::size_t(img.height);
    if (layers.bvhCost && img.bvhCost.size() != count)
        throw std::invalid_argument("the bvh_cost AOV is available for stills and per-frame renders only");
    if (layers.samples && img.sampleCounts.size() != count)
        throw std::invalid_argument("the samples AOV is available for the accumulate and reference configurations only");
    if (layers.passes.any() && (img.vectors.size() != count * 2 || img.lightPasses[0].size() != count * 3))
        throw std::invalid_argument("render passes are available for the accumulate and reference configurations only");
    const ImageWindow window = dataWindowOf(img);
    p.pixels.reserve(std::size_t(window.width) * std::size_t(window.height) * p.names.size());
    for (int y = window.y; y < window.y + window.height; ++y)
        for (int x = window.x; x < window.x + window.width; ++x)
            appendPixel(p, img, layers, std::size_t(y) * std::size_t(img.width) + std::size_t(x));
    return p;
}

// 8-bit images keep the full size: outside the window every byte is 0, so transparent where the
// format has alpha (PNG, TIFF) and black where it has none (JPEG).
std::vector<std::uint8_t> displayPixels(const RenderOutput& img) {
    const ImageWindow window = dataWindowOf(img);
    if (window == ImageWindow{0, 0, img.width, img.height}) return img.tonemapped;
    std::vector<std::uint8_t> pixels(img.tonemapped.size(), 0);
    for (int y = window.y; y < window.y + window.height; ++y) {
        const std::size_t row = (std::size_t(y) * std::size_t(img.width) + std::size_t(window.x)) * 4;
        std::copy_n(img.tonemapped.begin() + std::ptrdiff_t(row), std::size_t(window.width) * 4,
                    pixels.begin() + std::ptrdiff_t(row));
    }
    return pixels;
}

// OpenImageIO encodes into memory and Glint writes the bytes itself (writeFile), checking every
// write: OpenImageIO's file writers go through stdio and not all of them see a failed flush (a PNG
// written to a full disk came out empty, and was published).
std::vector<unsigned char> encodeWithOiio(const std::filesystem::path& target, const OIIO::ImageSpec& spec, const void* pixels) {
    auto out = OIIO::ImageOutput::create(target.string()); // by the final name's extension
    if (!out) throw FileError(target.string(), "image-format", "no writer for this format: " + OIIO::geterror());
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    if (!out->set_ioproxy(&memory)) throw FileError(target.string(), "image-format", "this format cannot be written to memory");
    if (!out->open(target.string(), spec) || !out->write_image(spec.format, pixels) || !out->close())
        throw FileError(target.string(), "write-failed", "cannot encode the image: " + out->geterror());
    return bytes;
}

// Writes `bytes` to `temp` and makes them durable: the data reaches the disk before the name does,
// so after a crash or power loss the final name holds either nothing or the whole image. Errors
// name the final file and say why (a full disk: "No space left on device").
void writeFile(const std::filesystem::path& temp, const std::vector<unsigned char>& bytes, const std::filesystem::path& file) {
    const auto fail = [&](const std::string& what, int error) {
        throw FileError(file.string(), "write-failed", what + ": " + std::strerror(error));
    };
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) fail("cannot create the image in its folder", errno);
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const int error = n < 0 ? errno : ENOSPC;
            ::close(fd);
            fail("cannot write the image", error);
        }
        done += static_cast<std::size_t>(n);
    }
    if (::fsync(fd) != 0) {
        const int error = errno;
        ::close(fd);
        fail("cannot flush the image to disk", error);
    }
    if (::close(fd) != 0) fail("cannot close the image", errno);
}

std::filesystem::path temporaryNameFor(const std::filesystem::path& file) {
    // A leading dot and a ".partial" infix: never matches a frame pattern or the final name. The
    // process id keeps two processes that render the same frame (overlapping shards) apart.
    std::string name = file.stem().string();
    name.insert(0, 1, '.');
    name.append(".partial-").append(std::to_string(::getpid())).append(file.extension().string());
    return file.parent_path() / name;
}

void publish(const std::filesystem::path& temp, const std::filesystem::path& file) {
    std::error_code ec;
    std::filesystem::rename(temp, file, ec);
    if (ec) {
        const std::string why = ec.message();
        std::filesystem::remove(temp, ec);
        throw FileError(file.string(), "write-failed", "cannot move the finished image into place: " + why);
    }
}

OIIO::ImageSpec specFor(const RenderOutput& img, ImageFormat format, const Planes* planes) {
    if (format == ImageFormat::Exr) {
        // A region is the data window inside the whole image's display window (OpenEXR's own
        // way to store part of an image): readers place it where it belongs.
        const ImageWindow window = dataWindowOf(img);
        OIIO::ImageSpec spec(window.width, window.height, int(planes->names.size()), OIIO::TypeDesc::FLOAT);
        spec.x = window.x;
        spec.y = window.y;
        spec.full_x = 0;
        spec.full_y = 0;
        spec.full_width = img.width;
        spec.full_height = img.height;
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

namespace {

// Calls `use(lowered, asGiven)` for each item of a comma-separated list (an empty item too).
template <typename Use>
void forEachListItem(const std::string& list, Use use) {
    const std::string l = lower(list);
    std::size_t start = 0;
    while (start <= l.size()) {
        const std::size_t comma = std::min(l.find(',', start), l.size());
        use(l.substr(start, comma - start), list.substr(start, comma - start));
        start = comma + 1;
    }
}

} // namespace

ExrLayers parseAovList(const std::string& list) {
    const std::string l = lower(list);
    if (l == "all") return {};
    ExrLayers none;
    none.albedo = none.normal = none.depth = none.objectId = false;
    if (l == "none") return none;
    forEachListItem(list, [&](const std::string& item, const std::string&) {
        if (item == "albedo") none.albedo = true;
        else if (item == "normal") none.normal = true;
        else if (item == "depth") none.depth = true;
        else if (item == "id") none.objectId = true;
        else if (item == "variance") none.variance = true;
        else if (item == "bvh_cost") none.bvhCost = true;
        else if (item == "samples") none.samples = true;
        else throw std::invalid_argument("unknown AOV '" + item + "' (use all, none or a list of albedo, normal, depth, id, variance, bvh_cost, samples)");
    });
    return none;
}

bool RenderPasses::any() const {
    return vector || std::find(light.begin(), light.end(), true) != light.end();
}

const char* lightPassName(LightPass pass) {
    static constexpr const char* names[lightPassCount] = {"DiffDir", "DiffInd", "GlossDir", "GlossInd", "Emit", "Env"};
    return names[std::size_t(pass)];
}

RenderPasses parsePassList(const std::string& list) {
    const std::string l = lower(list);
    RenderPasses passes;
    if (l.empty() || l == "none") return passes;
    if (l == "all") {
        passes.light.fill(true);
        passes.vector = true;
        return passes;
    }
    forEachListItem(list, [&](const std::string& item, const std::string& asGiven) {
        bool known = false;
        for (int k = 0; k < lightPassCount; ++k)
            if (item == lower(lightPassName(LightPass(k)))) known = passes.light[std::size_t(k)] = true;
        if (item == "light") known = true, passes.light.fill(true);
        if (item == "vector") known = passes.vector = true;
        if (!known)
            throw std::invalid_argument("unknown render pass '" + asGiven +
                                        "' (use all, none, light or a list of DiffDir, DiffInd, GlossDir, GlossInd, Emit, Env, Vector)");
    });
    return passes;
}

std::string passListName(const RenderPasses& passes) {
    std::string name;
    for (int k = 0; k < lightPassCount; ++k)
        if (passes.light[std::size_t(k)]) name += std::string(name.empty() ? "" : ",") + lightPassName(LightPass(k));
    if (passes.vector) name += name.empty() ? "Vector" : ",Vector";
    return name;
}

void prepareOutputFolder(const std::filesystem::path& file) {
    const std::filesystem::path folder = file.parent_path().empty() ? std::filesystem::path(".") : file.parent_path();
    std::error_code ec;
    // The first part of the path that exists must be a folder: name it when it is a file.
    for (std::filesystem::path part = folder; !part.empty(); part = part.parent_path()) {
        if (std::filesystem::exists(part, ec)) {
            if (!std::filesystem::is_directory(part, ec))
                throw FileError(file.string(), "no-folder", "'" + part.string() + "' is a file, not a folder");
            break;
        }
        if (part == part.parent_path()) break;
    }
    if (!std::filesystem::is_directory(folder, ec) && !std::filesystem::create_directories(folder, ec))
        throw FileError(file.string(), "no-folder", "cannot create the output folder '" + folder.string() + "': " + ec.message());
    if (::access(folder.c_str(), W_OK) != 0)
        throw FileError(file.string(), "not-writable", "the output folder '" + folder.string() + "' is not writable: " + std::strerror(errno));
}

void writeRenderImage(const std::filesystem::path& file, const RenderOutput& img, const ExrLayers& layers,
                      const ImageMetadata& metadata) {
    const ImageFormat format = imageFormatFor(file);
    const std::filesystem::path temp = temporaryNameFor(file);
    Planes planes;
    if (format == ImageFormat::Exr) planes = exrPlanes(img, layers);
    OIIO::ImageSpec spec = specFor(img, format, &planes);
    for (const auto& [key, value] : metadata) {
        // The render time is the one thing that differs between identical renders; docs/CLI.md
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
    std::vector<unsigned char> bytes;
    {
        const std::vector<std::uint8_t> display = format == ImageFormat::Exr ? std::vector<std::uint8_t>() : displayPixels(img);
        bytes = encodeWithOiio(file, spec, format == ImageFormat::Exr ? static_cast<const void*>(planes.pixels.data())
                                                                       : static_cast<const void*>(display.data()));
    }
    try {
        writeFile(temp, bytes, file);
    } catch (...) {
        std::error_code ec;
        std::filesystem::remove(temp, ec);
        throw;
    }
    publish(temp, file);
}

} // namespace glint::renderer
