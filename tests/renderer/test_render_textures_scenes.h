#pragma once
// Textured scenes built in code for the texture tests: PNG images encoded through OpenImageIO, a
// square mesh with UVs and MikkTSpace-style tangents, and an orthographic camera looking straight
// down at it so that image pixels map to UVs exactly (image right = +X = +u, image down = +Z = +v).
#include "render_scene.h"
#include "scene_builder.h"

#include "renderer/offline_render.h"

#include <OpenImageIO/imageio.h>
#include <QTemporaryDir>

#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>
#include <stdexcept>

namespace glint::test {

struct Texels {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba; // rows top-down
    glm::u8vec4 at(int x, int y) const {
        const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4;
        return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
    }
};

inline std::vector<std::uint8_t> encodePng(const Texels& t) {
    QTemporaryDir dir;
    const std::string file = dir.filePath("t.png").toStdString();
    auto out = OIIO::ImageOutput::create(file);
    if (!out || !out->open(file, OIIO::ImageSpec(t.width, t.height, 4, OIIO::TypeDesc::UINT8)) ||
        !out->write_image(OIIO::TypeDesc::UINT8, t.rgba.data()) || !out->close())
        throw std::runtime_error("cannot write a test PNG");
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline TextureId addTexture(Scene& scene, const Texels& texels, Sampler sampler) {
    Image image;
    image.mimeType = "image/png";
    image.encoded = encodePng(texels);
    image.width = texels.width;
    image.height = texels.height;
    const ImageId imageId = scene.images.add(std::move(image));
    Texture texture;
    texture.image = imageId;
    texture.sampler = scene.samplers.add(std::move(sampler));
    return scene.textures.add(std::move(texture));
}

inline Sampler sampler(Filter filter, Wrap wrapS = Wrap::Repeat, Wrap wrapT = Wrap::Repeat) {
    Sampler s;
    s.magFilter = filter;
    s.minFilter = filter == Filter::Nearest ? Filter::NearestMipmapNearest : Filter::LinearMipmapLinear;
    s.wrapS = wrapS;
    s.wrapT = wrapT;
    return s;
}

inline TextureRef ref(TextureId texture) {
    TextureRef r;
    r.texture = texture;
    return r;
}

// A square of side `size` in the XZ plane facing +Y; uv0 runs from uvMin (at -X, -Z) to uvMax
// (at +X, +Z), uv1 is uv0 mirrored in u; tangent +X (the direction of +u), handedness +1: the
// bitangent cross(N, T) = -Z points towards -v, "up" in the image as glTF normal maps expect.
inline Mesh texturedQuad(float size, MaterialId material, glm::vec2 uvMin = glm::vec2(0.0f), glm::vec2 uvMax = glm::vec2(1.0f)) {
    const float s = 0.5f * size;
    Primitive p;
    p.positions = {{-s, 0.0f, -s}, {-s, 0.0f, s}, {s, 0.0f, s}, {s, 0.0f, -s}};
    p.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
    p.tangents.assign(4, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    p.uv0 = {{uvMin.x, uvMin.y}, {uvMin.x, uvMax.y}, {uvMax.x, uvMax.y}, {uvMax.x, uvMin.y}};
    for (const glm::vec2 uv : p.uv0) p.uv1.push_back({uvMin.x + uvMax.x - uv.x, uv.y});
    p.indices = {0, 1, 2, 0, 2, 3};
    p.material = material;
    Mesh mesh;
    mesh.primitives.push_back(std::move(p));
    return mesh;
}

inline NodeId addQuad(Scene& scene, const Mesh& mesh, glm::vec3 position = glm::vec3(0.0f)) {
    return addNode(scene, "quad", MeshInstance{scene.meshes.add(mesh)}, position);
}

// Looking down -Y from above, `halfSize` metres from the centre to each image edge.
inline void addTopCamera(Scene& scene, float halfSize, float height = 1.0f) {
    addOrthographicCamera(scene, {0.0f, height, 0.0f}, {0.0f, -1.0f, 0.0f}, halfSize);
}

// The value that nearest sampling must give over the whole of pixel (x, y), or nothing when the
// pixel straddles a texel edge. `texelAt` maps a UV to the texel it selects; `uvAt` an image
// position (pixels, top-left origin) to the UV the renderer uses there.
inline std::optional<glm::ivec2> wholePixelTexel(int x, int y, const std::function<glm::vec2(glm::vec2)>& uvAt,
                                                 const std::function<glm::ivec2(glm::vec2)>& texelAt) {
    const glm::ivec2 centre = texelAt(uvAt({x + 0.5f, y + 0.5f}));
    for (const float dx : {0.02f, 0.98f})
        for (const float dy : {0.02f, 0.98f})
            if (texelAt(uvAt({x + dx, y + dy})) != centre) return std::nullopt;
    return centre;
}

} // namespace glint::test
