#include "memory_estimate.h"

namespace glint {
namespace {

template <class T>
std::size_t bytesOf(const std::vector<T>& values) {
    return values.size() * sizeof(T);
}

} // namespace

std::size_t approxBytes(const Node& node) {
    std::size_t bytes = sizeof(Node) + node.name.size() + bytesOf(node.children);
    if (const auto* camera = node.get<Camera>()) bytes += bytesOf(camera->path.keys);
    return bytes;
}

std::size_t approxBytes(const Mesh& mesh) {
    std::size_t bytes = sizeof(Mesh) + mesh.name.size();
    for (const Primitive& p : mesh.primitives)
        bytes += sizeof(Primitive) + bytesOf(p.positions.vector()) + bytesOf(p.normals.vector()) + bytesOf(p.tangents.vector()) +
                 bytesOf(p.uv0.vector()) + bytesOf(p.uv1.vector()) + bytesOf(p.colors.vector()) + bytesOf(p.indices.vector());
    return bytes;
}

std::size_t approxBytes(const Image& image) {
    return sizeof(Image) + image.name.size() + image.uri.size() + image.encoded.size();
}

std::size_t approxBytes(const Material& material) { return sizeof(Material) + material.name.size(); }
std::size_t approxBytes(const Texture& texture) { return sizeof(Texture) + texture.name.size(); }
std::size_t approxBytes(const Sampler& sampler) { return sizeof(Sampler) + sampler.name.size(); }

std::size_t approxBytes(const Animation& animation) {
    std::size_t bytes = sizeof(Animation) + animation.name.size();
    for (const AnimationChannel& c : animation.channels) bytes += sizeof(c) + (c.times.size() + c.values.size()) * sizeof(float);
    return bytes;
}

} // namespace glint
