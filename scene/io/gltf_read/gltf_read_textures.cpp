// Images, samplers and textures. Images keep their encoded bytes and their relative URI (or stay
// embedded); dimensions come from the header, so a header claiming more pixels than allowed is
// refused before anything decodes it, and a missing or unreadable image becomes a placeholder.
#include "gltf_read_json.h"
#include "gltf_read_uri.h"
#include "gltf_reader.h"
#include "scene/io/image_decoder.h"

namespace glint {

namespace {

std::string sniffMimeType(std::span<const std::uint8_t> b)
{
    if (b.size() >= 4 && b[0] == 0x89 && b[1] == 'P' && b[2] == 'N' && b[3] == 'G') return "image/png";
    if (b.size() >= 2 && b[0] == 0xFF && b[1] == 0xD8) return "image/jpeg";
    return {};
}

std::optional<ImageSize> imageSize(const GltfReadContext& ctx, std::span<const std::uint8_t> bytes)
{
    if (auto size = probeImageHeader(bytes)) return size;
    return ctx.options.images ? ctx.options.images->probe(bytes) : std::nullopt;
}

void markMissing(GltfReadContext& ctx, Image& image, std::size_t index, const std::string& why)
{
    image.missing = true;
    const std::string name = image.uri.empty() ? "embedded image " + std::to_string(index) : "'" + image.uri + "'";
    ctx.warn("missing-texture", "image " + std::to_string(index) + " (" + name + ") " + why + ": a placeholder is shown instead");
}

void setDimensions(GltfReadContext& ctx, Image& image, std::size_t index)
{
    const auto size = imageSize(ctx, image.encoded);
    if (!size) return markMissing(ctx, image, index, "cannot be decoded");
    const auto pixels = static_cast<std::uint64_t>(size->width) * static_cast<std::uint64_t>(size->height);
    if (pixels > ctx.options.maxImagePixels)
        ctx.fail("image-too-large", "image " + std::to_string(index) + " claims " + std::to_string(size->width) + "x" + std::to_string(size->height) +
                                        " pixels, more than the limit of " + std::to_string(ctx.options.maxImagePixels));
    image.width = size->width;
    image.height = size->height;
}

Image readImage(GltfReadContext& ctx, std::size_t index)
{
    const JsonReader json{ctx.file};
    const Json& source = ctx.doc["images"][index];
    const std::string where = "images[" + std::to_string(index) + "]";
    const tinygltf::Image& loaded = ctx.model.images.at(index);
    Image image;
    image.name = json.string(source, "name", where);
    const std::string uri = json.string(source, "uri", where);
    if (!isDataUri(uri)) image.uri = uri;
    image.encoded.assign(loaded.image.begin(), loaded.image.end());
    image.mimeType = json.string(source, "mimeType", where);
    if (image.mimeType.empty() && isDataUri(uri)) image.mimeType = parseDataUri(uri)->mimeType;
    if (image.mimeType.empty()) image.mimeType = sniffMimeType(image.encoded);
    image.unknown = unknownMembers(source);
    if (image.encoded.empty()) markMissing(ctx, image, index, "was not found");
    else setDimensions(ctx, image, index);
    return image;
}

Filter filterFrom(int value)
{
    switch (value) {
    case 9728: case 9729: case 9984: case 9985: case 9986: case 9987: return static_cast<Filter>(value);
    default: return Filter::Unset;
    }
}

Wrap wrapFrom(int value)
{
    return value == 33071 || value == 33648 ? static_cast<Wrap>(value) : Wrap::Repeat;
}

Sampler readSampler(const GltfReadContext& ctx, std::size_t index)
{
    const JsonReader json{ctx.file};
    const Json& source = ctx.doc["samplers"][index];
    const std::string where = "samplers[" + std::to_string(index) + "]";
    Sampler sampler;
    sampler.name = json.string(source, "name", where);
    sampler.magFilter = filterFrom(json.index(source, "magFilter", where));
    sampler.minFilter = filterFrom(json.index(source, "minFilter", where));
    sampler.wrapS = wrapFrom(json.index(source, "wrapS", where));
    sampler.wrapT = wrapFrom(json.index(source, "wrapT", where));
    sampler.unknown = unknownMembers(source);
    return sampler;
}

template <class IdT>
IdT idAt(const std::vector<IdT>& ids, int index)
{
    return index >= 0 && static_cast<std::size_t>(index) < ids.size() ? ids[static_cast<std::size_t>(index)] : IdT{};
}

Texture readTexture(const GltfReadContext& ctx, std::size_t index)
{
    const JsonReader json{ctx.file};
    const Json& source = ctx.doc["textures"][index];
    const std::string where = "textures[" + std::to_string(index) + "]";
    Texture texture;
    texture.name = json.string(source, "name", where);
    texture.image = idAt(ctx.imageIds, json.index(source, "source", where));
    texture.sampler = idAt(ctx.samplerIds, json.index(source, "sampler", where));
    texture.unknown = unknownMembers(source);
    return texture;
}

std::size_t countOf(const Json& doc, const char* key) { return doc.contains(key) ? doc[key].size() : 0; }

} // namespace

void readImagesAndTextures(GltfReadContext& ctx)
{
    for (std::size_t i = 0; i < countOf(ctx.doc, "images"); ++i) ctx.imageIds.push_back(ctx.scene.images.add(readImage(ctx, i)));
    for (std::size_t i = 0; i < countOf(ctx.doc, "samplers"); ++i) ctx.samplerIds.push_back(ctx.scene.samplers.add(readSampler(ctx, i)));
    for (std::size_t i = 0; i < countOf(ctx.doc, "textures"); ++i) ctx.textureIds.push_back(ctx.scene.textures.add(readTexture(ctx, i)));
}

} // namespace glint
