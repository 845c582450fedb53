#include "renderer/gpu_scene/texture_set.h"

#include "renderer/gpu_scene/visibility.h"

#include <algorithm>
#include <stdexcept>

namespace glint::renderer {
namespace {

using Use = std::pair<ImageId, bool>; // image, sRGB

TextureLevel placeholderChecker() {
    TextureLevel level{8, 8, std::vector<std::uint8_t>(8 * 8 * 4)};
    for (int i = 0; i < 64; ++i) {
        const bool on = ((i % 8) / 4 + (i / 8) / 4) % 2 == 0;
        const std::uint8_t rgba[4] = {static_cast<std::uint8_t>(on ? 255 : 0), 0, static_cast<std::uint8_t>(on ? 255 : 0), 255};
        std::copy(rgba, rgba + 4, level.rgba.begin() + i * 4);
    }
    return level;
}

std::string imageName(const Scene& scene, ImageId id) {
    const Image& image = scene.images.at(id);
    return !image.uri.empty() ? image.uri : !image.name.empty() ? image.name : "image " + std::to_string(id.value);
}

using Chain = std::shared_ptr<const MipChain>;

// The mip chain of an image in one colour space (from `cache` when it holds it), or an error message.
std::pair<Chain, std::string> decodeChain(const Scene& scene, Use use, const ImageDecoder& decoder, int maxSize, TextureCache* cache) {
    const ImageId id = use.first;
    if (!scene.images.contains(id)) return {nullptr, "a texture names no image"};
    const Image& image = scene.images.at(id);
    if (image.missing || image.encoded.empty()) return {nullptr, imageName(scene, id) + ": missing"};
    if (cache)
        if (Chain hit = cache->find(image.encoded, use.second, maxSize)) return {std::move(hit), {}};
    DecodedMipChain decoded = decodeMipChain(decoder, image.encoded, use.second, maxSize);
    if (!decoded.error.empty()) return {nullptr, imageName(scene, id) + ": " + decoded.error};
    Chain chain = std::make_shared<const MipChain>(std::move(decoded.levels));
    if (cache) cache->insert(image.encoded, use.second, maxSize, chain);
    return {std::move(chain), {}};
}

struct Group {
    bool srgb;
    int width, height;
    std::vector<std::pair<Use, Chain>> images;
    long long area() const { return static_cast<long long>(width) * height; }
};

// Merges the smallest group of a colour space that has several into the next larger of that space.
void mergeOnce(std::vector<Group>& groups, std::vector<std::string>& warnings) {
    std::size_t smallest = groups.size();
    for (std::size_t i = 0; i < groups.size(); ++i) {
        const auto sameSpace = std::count_if(groups.begin(), groups.end(), [&](const Group& g) { return g.srgb == groups[i].srgb; });
        if (sameSpace > 1 && (smallest == groups.size() || groups[i].area() < groups[smallest].area())) smallest = i;
    }
    if (smallest == groups.size()) throw std::runtime_error("the scene's textures need more sampler units than the path tracer has");
    std::size_t target = groups.size();
    for (std::size_t i = 0; i < groups.size(); ++i)
        if (i != smallest && groups[i].srgb == groups[smallest].srgb &&
            (target == groups.size() || groups[i].area() < groups[target].area()))
            target = i;
    Group& from = groups[smallest];
    Group& to = groups[target];
    warnings.push_back("textures of " + std::to_string(from.width) + "x" + std::to_string(from.height) + " resampled to " +
                       std::to_string(to.width) + "x" + std::to_string(to.height) + " (too many texture sizes for the sampler units)");
    for (auto& [use, chain] : from.images)
        to.images.emplace_back(use, std::make_shared<const MipChain>(
                                            buildMipChain(resampleLevel(chain->front(), to.width, to.height, from.srgb), from.srgb)));
    std::sort(to.images.begin(), to.images.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    groups.erase(groups.begin() + static_cast<std::ptrdiff_t>(smallest));
}

// The colour of a 1x1 level, in linear light.
glm::vec3 meanColor(const TextureLevel& level, bool srgb) {
    if (level.rgba.size() < 3) return glm::vec3(0.0f);
    const auto channel = [&](int c) { return srgb ? srgbToLinear(level.rgba[c]) : level.rgba[c] / 255.0f; };
    return {channel(0), channel(1), channel(2)};
}

} // namespace

TextureSlot TextureSet::find(ImageId image, bool srgb) const {
    const auto it = slotOf.find({image, srgb});
    return it == slotOf.end() ? TextureSlot{} : it->second;
}

std::set<MaterialId> meshMaterials(const Scene& scene) {
    std::set<MaterialId> used;
    for (const NodeId id : scene.depthFirst()) {
        const Node& node = scene.at(id);
        const auto* instance = node.get<MeshInstance>();
        if (!instance || !visibleInWorld(scene, node) || !scene.meshes.contains(instance->mesh)) continue;
        for (const Primitive& p : scene.meshes.at(instance->mesh).primitives) used.insert(p.material);
    }
    return used;
}

std::set<MaterialId> texturedMaterials(const Scene& scene) {
    std::set<MaterialId> used = meshMaterials(scene);
    for (const NodeId id : scene.depthFirst()) {
        const Node& node = scene.at(id);
        if (const auto* shape = node.get<Shape>(); shape && visibleInWorld(scene, node)) used.insert(shape->material);
    }
    return used;
}

std::set<std::pair<ImageId, bool>> texturesUsed(const Scene& scene, const std::set<MaterialId>& materials) {
    std::set<Use> uses;
    const auto add = [&](const TextureRef& ref, bool srgb) {
        if (ref.valid() && scene.textures.contains(ref.texture)) uses.insert({scene.textures.at(ref.texture).image, srgb});
    };
    for (const MaterialId id : materials) {
        if (!scene.materials.contains(id)) continue;
        const Material& m = scene.materials.at(id);
        add(m.baseColorTexture, true);
        add(m.emissiveTexture, true);
        add(m.metallicRoughnessTexture, false);
        add(m.normalTexture, false);
        add(m.specularTexture, false);
        add(m.specularColorTexture, true);
        add(m.transmissionTexture, false);
        add(m.thicknessTexture, false);
    }
    return uses;
}

TextureSet buildTextureSet(const Scene& scene, const std::set<MaterialId>& materials, const ImageDecoder& decoder,
                           const TextureLimits& limits, TextureCache* cache) {
    TextureSet set;
    std::vector<Group> groups;
    for (const Use& use : texturesUsed(scene, materials)) {
        auto [chain, problem] = decodeChain(scene, use, decoder, limits.maxSize, cache);
        if (!problem.empty()) {
            set.warnings.push_back("texture " + problem + (use.second ? " (shown as a checker)" : " (ignored)"));
            if (!use.second) continue;
            chain = std::make_shared<const MipChain>(buildMipChain(placeholderChecker(), true));
        }
        const TextureLevel& level = chain->front();
        auto group = std::find_if(groups.begin(), groups.end(), [&](const Group& g) {
            return g.srgb == use.second && g.width == level.width && g.height == level.height;
        });
        if (group == groups.end()) group = groups.insert(groups.end(), Group{use.second, level.width, level.height, {}});
        group->images.emplace_back(use, std::move(chain));
    }
    while (static_cast<int>(groups.size()) > limits.maxBuckets) mergeOnce(groups, set.warnings);
    for (Group& group : groups) {
        if (static_cast<int>(group.images.size()) > limits.maxLayers)
            throw std::runtime_error(std::to_string(group.images.size()) + " textures of " + std::to_string(group.width) + "x" +
                                     std::to_string(group.height) + " exceed the driver's limit of " +
                                     std::to_string(limits.maxLayers) + " texture array layers");
        TextureBucket bucket{group.srgb, group.width, group.height, {}};
        for (auto& [use, chain] : group.images) {
            set.slotOf[use] = TextureSlot{static_cast<int>(set.buckets.size()), static_cast<int>(bucket.layers.size())};
            set.meanOf[use] = meanColor(chain->back(), use.second);
            bucket.layers.push_back(std::move(chain));
        }
        set.buckets.push_back(std::move(bucket));
    }
    return set;
}

} // namespace glint::renderer
