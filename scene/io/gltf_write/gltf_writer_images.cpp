// Images keep their original encoded bytes (never re-encoded). In a .gltf an image with a relative
// URI is written to that URI beside the glTF and an embedded one goes into the buffer; in a .glb every
// image goes into the BIN chunk.
#include "gltf_writer_context.h"

#include <algorithm>
#include <cctype>

namespace glint {

namespace {

bool startsWith(const std::vector<std::uint8_t>& bytes, std::initializer_list<std::uint8_t> magic)
{
    return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin());
}

// glTF requires a mimeType on buffer-view images; the file's own header decides when none is known.
std::string mimeTypeOf(const Image& image)
{
    if (!image.mimeType.empty()) return image.mimeType;
    if (startsWith(image.encoded, {0x89, 'P', 'N', 'G'})) return "image/png";
    if (startsWith(image.encoded, {0xFF, 0xD8, 0xFF})) return "image/jpeg";
    if (startsWith(image.encoded, {'R', 'I', 'F', 'F'})) return "image/webp";
    return "application/octet-stream";
}

std::string lowercase(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

int hexValue(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
}

// The file path a URI names ("a%20b.png" -> "a b.png"); empty when the escapes are malformed.
std::string decodedUriPath(const std::string& uri)
{
    std::string path;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] != '%') {
            path += uri[i];
            continue;
        }
        const int high = i + 2 < uri.size() ? hexValue(uri[i + 1]) : -1;
        const int low = i + 2 < uri.size() ? hexValue(uri[i + 2]) : -1;
        if (high < 0 || low < 0) return {};
        path += static_cast<char>(high * 16 + low);
        i += 2;
    }
    return path;
}

// Only plain relative paths inside the scene folder may become files of their own.
bool isSafeRelativePath(const std::string& path)
{
    if (path.empty() || path.front() == '/' || path.find(':') != std::string::npos ||
        path.find('\\') != std::string::npos || path.find('\0') != std::string::npos)
        return false;
    std::size_t start = 0;
    while (start <= path.size()) {
        const std::size_t end = std::min(path.find('/', start), path.size());
        const std::string part = path.substr(start, end - start);
        if (part.empty() || part == "." || part == "..") return false;
        start = end + 1;
    }
    return true;
}

bool isReserved(const GltfWriteContext& ctx, const std::string& uri)
{
    const std::string name = lowercase(decodedUriPath(uri));
    if (name.size() > 4 && name.ends_with(".bin") && name.rfind(lowercase(ctx.options.baseName) + ".", 0) == 0) return true;
    return std::any_of(ctx.options.reservedUris.begin(), ctx.options.reservedUris.end(),
                       [&](const std::string& reserved) { return lowercase(reserved) == name; });
}

// Returns false when the image has to be embedded instead (another image took the URI with other bytes).
bool addExternal(GltfWriteContext& ctx, const Image& image)
{
    for (const ExternalFile& file : ctx.externalImages)
        if (file.uri == image.uri) return file.bytes == image.encoded;
    ctx.externalImages.push_back({image.uri, decodedUriPath(image.uri), image.encoded});
    return true;
}

nlohmann::json imageJson(GltfWriteContext& ctx, ImageId id, const Image& image)
{
    const std::string what = "image " + std::to_string(id.value) + (image.uri.empty() ? "" : " (" + image.uri + ")");
    nlohmann::json out = nlohmann::json::object();
    if (!image.name.empty()) out["name"] = image.name;
    const bool text = ctx.options.container == GltfContainer::Text;
    if (image.encoded.empty()) {
        // Nothing to copy (the file was missing on load): keep the reference so the link survives.
        ctx.drop("image-bytes-missing", what + " has no bytes (it was missing when loaded): only its URI is written");
        out["uri"] = image.uri;
    } else if (text && !image.uri.empty() && !isSafeRelativePath(decodedUriPath(image.uri))) {
        ctx.drop("image-embedded", what + " has a URI outside the scene folder: embedded in the buffer instead");
    } else if (text && !image.uri.empty() && isReserved(ctx, image.uri)) {
        ctx.drop("image-embedded", what + " has the name of one of the scene's own files: embedded in the buffer instead");
    } else if (text && !image.uri.empty() && !addExternal(ctx, image)) {
        ctx.drop("image-embedded", what + " shares its URI with another image of different content: embedded instead");
    } else if (text && !image.uri.empty()) {
        out["uri"] = image.uri;
    }
    if (!out.contains("uri")) {
        out["bufferView"] = ctx.buffers.addBytesView(image.encoded);
        out["mimeType"] = mimeTypeOf(image);
    } else if (!image.mimeType.empty()) {
        out["mimeType"] = image.mimeType;
    }
    mergeUnknown(out, image.unknown);
    return out;
}

} // namespace

void writeImages(GltfWriteContext& ctx)
{
    for (const auto& [id, image] : ctx.scene.images) ctx.root["images"].push_back(imageJson(ctx, id, image));
}

} // namespace glint
