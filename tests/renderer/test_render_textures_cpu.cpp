// The CPU side of material textures, without a GL context: mip chains (box filter, sRGB-correct),
// bucketing by colour space and size, merging when sampler units run out, limits, placeholders,
// and the packed texture references (sampler flags, transform matrix).
#include "renderer/gpu_scene/packed_scene.h"
#include "renderer/gpu_scene/texture_refs.h"
#include "renderer/gpu_scene/texture_set.h"

#include <QTest>

#include <cmath>
#include <stdexcept>

using namespace glint;
using namespace glint::renderer;

namespace {

// Decodes "images" whose encoded bytes are (width, height, value): a constant RGBA image.
class FakeDecoder final : public ImageDecoder {
public:
    std::optional<ImageSize> probe(std::span<const std::uint8_t> e) const override { return ImageSize{e[0], e[1]}; }
    DecodedImage<float> decodeFloat(std::span<const std::uint8_t>, const DecodeLimits&) const override { return {}; }
    DecodedImage<std::uint8_t> decode8(std::span<const std::uint8_t> e, const DecodeLimits&) const override {
        DecodedImage<std::uint8_t> d;
        if (e.size() < 3) {
            d.error = "broken";
            return d;
        }
        d.width = e[0];
        d.height = e[1];
        d.rgba.assign(static_cast<std::size_t>(e[0]) * e[1] * 4, e[2]);
        return d;
    }
};

TextureRef addImage(Scene& scene, int width, int height, std::uint8_t value) {
    Image image;
    image.encoded = {static_cast<std::uint8_t>(width), static_cast<std::uint8_t>(height), value};
    Texture texture;
    texture.image = scene.images.add(std::move(image));
    TextureRef ref;
    ref.texture = scene.textures.add(std::move(texture));
    return ref;
}

// A scene whose one visible mesh uses `m`.
Scene withMeshMaterial(Scene scene, const Material& m) {
    Primitive p;
    p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    p.indices = {0, 1, 2};
    p.material = scene.materials.add(m);
    Mesh mesh;
    mesh.primitives.push_back(p);
    Node node;
    node.component = MeshInstance{scene.meshes.add(std::move(mesh))};
    scene.addNode(std::move(node));
    return scene;
}

} // namespace

class TestRenderTexturesCpu : public QObject {
    Q_OBJECT
private slots:
    // sRGB 0 and 255 average to linear 0.5, encoded 188 (not the 128 of averaging bytes); linear
    // data and alpha average as stored (128); odd sizes fold the last column in; the chain ends at 1x1.
    void mipChainsAverageInLinearLight() {
        TextureLevel base{3, 2, std::vector<std::uint8_t>(3 * 2 * 4)};
        for (std::size_t i = 0; i < base.rgba.size(); ++i) base.rgba[i] = (i / 4) % 2 ? 255 : 0;
        const auto srgb = buildMipChain(base, true);
        QCOMPARE(int(srgb.size()), 2);
        QCOMPARE(srgb[1].width, 1);
        QCOMPARE(srgb[1].height, 1);
        QCOMPARE(int(srgb[1].rgba[0]), 188);
        QCOMPARE(int(srgb[1].rgba[3]), 128);
        QCOMPARE(int(buildMipChain(base, false)[1].rgba[0]), 128);
        QCOMPARE(int(linearToSrgb8(0.5f)), 188);
        QVERIFY(std::abs(srgbToLinear(188) - 0.5029) < 1e-4);
        QCOMPARE(int(buildMipChain(TextureLevel{64, 16, std::vector<std::uint8_t>(64 * 16 * 4, 7)}, true).size()), 7);
    }

    // Base colour (sRGB) and normal (linear) of one size are two buckets; a second size of sRGB is a
    // third; with two units the smaller sRGB bucket is resampled into the larger, with a warning.
    void bucketsByColourSpaceAndSize() {
        Scene scene;
        Material a, b;
        a.baseColorTexture = addImage(scene, 4, 4, 200);
        a.normalTexture = addImage(scene, 4, 4, 128);
        b.emissiveTexture = addImage(scene, 8, 4, 50);
        scene = withMeshMaterial(withMeshMaterial(scene, a), b);
        FakeDecoder decoder;
        const TextureSet three = buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{3, 16, 64});
        QCOMPARE(int(three.buckets.size()), 3);
        QVERIFY(three.warnings.empty());
        const auto baseSlot = three.find(scene.textures.at(a.baseColorTexture.texture).image, true);
        QVERIFY(baseSlot.bucket >= 0 && three.buckets[std::size_t(baseSlot.bucket)].srgb);
        QCOMPARE(three.find(scene.textures.at(a.baseColorTexture.texture).image, false).bucket, -1);
        const TextureSet two = buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{2, 16, 64});
        QCOMPARE(int(two.buckets.size()), 2);
        QCOMPARE(int(two.warnings.size()), 1);
        const auto merged = two.find(scene.textures.at(a.baseColorTexture.texture).image, true);
        QCOMPARE(two.buckets[std::size_t(merged.bucket)].width, 8);
        QCOMPARE(int(two.buckets[std::size_t(merged.bucket)].layers.size()), 2);
        QVERIFY_THROWS_EXCEPTION(std::runtime_error, buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{1, 16, 64}));
    }

    // Too many layers fail with a message naming the limit; oversized images use a mip level that
    // fits; a broken colour image becomes the 8x8 checker, a broken linear one is dropped.
    void limitsAndPlaceholders() {
        Scene scene;
        Material a, b;
        a.baseColorTexture = addImage(scene, 32, 32, 1);
        b.baseColorTexture = addImage(scene, 32, 32, 2);
        scene = withMeshMaterial(withMeshMaterial(scene, a), b);
        FakeDecoder decoder;
        try {
            buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{3, 1, 64});
            QFAIL("no error for too many layers");
        } catch (const std::runtime_error& e) {
            QVERIFY2(std::string(e.what()).find("limit of 1 texture array layers") != std::string::npos, e.what());
        }
        QCOMPARE(buildTextureSet(scene, meshMaterials(scene), decoder, TextureLimits{3, 16, 8}).buckets[0].width, 8);

        Scene broken;
        Material c;
        c.baseColorTexture = addImage(broken, 4, 4, 9);
        c.normalTexture = addImage(broken, 4, 4, 9);
        broken.images.at(broken.textures.at(c.baseColorTexture.texture).image).encoded.resize(2);
        broken.images.at(broken.textures.at(c.normalTexture.texture).image).missing = true;
        broken = withMeshMaterial(broken, c);
        const TextureSet set = buildTextureSet(broken, meshMaterials(broken), decoder, TextureLimits{});
        QCOMPARE(int(set.buckets.size()), 1);
        QCOMPARE(set.buckets[0].width, 8);
        QCOMPARE(int(set.warnings.size()), 2);
    }

    // Sampler flags and the KHR_texture_transform matrix as the shader reads them.
    void textureReferencesPackSamplerAndTransform() {
        Sampler s;
        s.wrapS = Wrap::ClampToEdge;
        s.wrapT = Wrap::MirroredRepeat;
        s.magFilter = Filter::Nearest;
        s.minFilter = Filter::LinearMipmapNearest;
        QCOMPARE(samplerFlags(s), 1.0f + 3.0f * 2.0f + 9.0f + 36.0f);
        TextureRef ref;
        ref.texCoord = 0;
        ref.transform.rotation = 0.5f;
        ref.transform.scale = {2.0f, 3.0f};
        ref.transform.offset = {0.25f, 0.5f};
        ref.transform.texCoord = 1;
        std::vector<glm::vec4> texels;
        appendTextureRef(texels, ref, TextureSlot{2, 5}, s);
        QCOMPARE(int(texels.size()), textureRefTexels);
        QCOMPARE(texels[0], glm::vec4(2.0f, 5.0f, samplerFlags(s), 1.0f));
        // u' = a u + b v + tx must equal the extension's translation * rotation * scale.
        const float c = std::cos(0.5f), sn = std::sin(0.5f);
        QVERIFY(std::abs(texels[1].x - c * 2.0f) < 1e-6f && std::abs(texels[1].y - sn * 3.0f) < 1e-6f);
        QVERIFY(std::abs(texels[1].z + sn * 2.0f) < 1e-6f && std::abs(texels[1].w - c * 3.0f) < 1e-6f);
        QCOMPARE(texels[2], glm::vec4(0.25f, 0.5f, 1.0f, 0.0f));
        QCOMPARE(int(packMaterial(Material{}).size()), materialTexels);
    }
};

QTEST_APPLESS_MAIN(TestRenderTexturesCpu)
#include "test_render_textures_cpu.moc"
