// A material's texture references (renderer/gpu_scene/texture_refs.h): where the image lives, its
// sampler's wrap and filter modes, the UV set and the KHR_texture_transform matrix. They follow the
// material's MATERIAL_BASE_TEXELS factor texels, TEXTURE_REF_TEXELS each.
const int MATERIAL_BASE_TEXELS = 7;
const int TEXTURE_REF_TEXELS = 3;
const int TEXREF_BASE_COLOR = 0;
const int TEXREF_METALLIC_ROUGHNESS = 1;
const int TEXREF_NORMAL = 2;
const int TEXREF_EMISSIVE = 3;
const int TEXREF_SPECULAR = 4;       // KHR_materials_specular: strength in A (linear)
const int TEXREF_SPECULAR_COLOR = 5; // KHR_materials_specular: colour in RGB (sRGB)
const int TEXREF_TRANSMISSION = 6;   // KHR_materials_transmission: R (linear)
const int TEXREF_THICKNESS = 7;      // KHR_materials_volume: G (linear)

const int WRAP_REPEAT = 0;
const int WRAP_CLAMP = 1;
const int WRAP_MIRROR = 2;

struct TextureRef {
    int bucket;   // -1: no texture
    int layer;
    int flags;    // wrapS + 3 wrapT + 9 nearest mag + 18 nearest min + 36 mipmapped
    int texCoord; // 0: TEXCOORD_0, 1: TEXCOORD_1
    vec4 matrix;  // uv' = (a u + b v, c u + d v) + offset
    vec2 offset;
    float scale;  // normalTexture.scale; 1 elsewhere
};

TextureRef fetchTextureRef(int material, int ref) {
    int first = MATERIAL_BASE_TEXELS + TEXTURE_REF_TEXELS * ref;
    vec4 a = materialTexel(material, first);
    vec4 c = materialTexel(material, first + 2);
    return TextureRef(int(a.x), int(a.y), int(a.z), int(a.w), materialTexel(material, first + 1), c.xy, c.z);
}

bool hasTexture(TextureRef r) { return r.bucket >= 0; }

// The luminance light sampling assumes for a material's emissive-textured triangles: the factor
// times the texture's mean (renderer/gpu_scene/packed_scene.cpp), in the emissive reference's last w.
float emissiveTextureLightLuminance(int material) {
    return materialTexel(material, MATERIAL_BASE_TEXELS + TEXTURE_REF_TEXELS * TEXREF_EMISSIVE + 2).w;
}

vec2 transformUv(TextureRef r, vec2 uv) {
    return vec2(r.matrix.x * uv.x + r.matrix.y * uv.y, r.matrix.z * uv.x + r.matrix.w * uv.y) + r.offset;
}

// log2 of how much the transform magnifies UV areas (halved: a length scale), for the LOD.
float transformLodBias(TextureRef r) {
    float det = abs(r.matrix.x * r.matrix.w - r.matrix.y * r.matrix.z);
    return 0.5 * log2(max(det, 1e-20));
}
