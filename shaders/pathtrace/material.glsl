// A hit's material, unpacked from the material buffer (layout: renderer/gpu_scene/packed_scene.cpp)
// into the shared BSDF's SurfaceMaterial, plus its emission.
#include "bsdf/material.glsl"

SurfaceMaterial fetchSurfaceMaterial(int material) {
    vec4 base = materialTexel(material, 0);
    vec4 emissionRoughness = materialTexel(material, 1);
    vec4 metallicSpecularTransmissionIor = materialTexel(material, 2);
    vec4 specularColorThickness = materialTexel(material, 3);
    vec4 attenuation = materialTexel(material, 4);
    return SurfaceMaterial(base.rgb, metallicSpecularTransmissionIor.x, emissionRoughness.w,
                           metallicSpecularTransmissionIor.y, specularColorThickness.rgb,
                           metallicSpecularTransmissionIor.z, metallicSpecularTransmissionIor.w,
                           specularColorThickness.w <= 0.0, attenuation.rgb, attenuation.w, specularColorThickness.w);
}

// Radiance emitted: emissiveFactor x emissiveStrength, 1:1 (no photometric scale).
vec3 fetchEmission(int material) {
    return materialTexel(material, 1).rgb;
}

// Material texel 5 w (renderer/gpu_scene/packed_scene.cpp): an area light's material emits from
// its front face only; an index-matched boundary is crossed without a vertex (media.glsl).
const float MATERIAL_FRONT_ONLY = 1.0;
const float MATERIAL_INDEX_MATCHED = 2.0;

// Whether a ray along `rayDirection` sees the emission of what it hit. A mesh triangle of a
// single-sided material (glTF doubleSided false: its back face is culled) emits from its front face
// only, the side its normal points to; double-sided materials and analytic shapes emit from both,
// except an area light's shape (its material's texel 5 w = 1: front face only, the outside of a
// sphere). Next-event estimation samples the same sides (emissive_lights.glsl, shape_lights.glsl).
bool emissionSeen(Hit hit, vec3 rayDirection) {
    vec4 sides = materialTexel(hit.material, 5);
    bool frontOnly = hit.onMesh ? sides.z == 0.0 : sides.w == MATERIAL_FRONT_ONLY;
    return !frontOnly || dot(hit.geometricNormal, rayDirection) < 0.0;
}

// A hit's material after textures, and the normal it shades with.
struct SurfaceShading {
    SurfaceMaterial material;
    vec3 emission;        // radiance leaving the surface
    vec3 sampledEmission; // what light sampling of emissive triangles assumes here (0: not light-sampled)
    vec3 normal;          // shading normal, on the geometric normal's side
    float curvature;      // 1/m, for the ray cone's spread
};

#ifdef HAS_TEXTURES
#include "shape_surface.glsl"

TexturedSurface texturedSurface(Hit hit, vec3 rayDirection, float coneWidth) {
#ifdef HAS_MESHES
    if (hit.onMesh)
        return meshSurface(hit.triangle.x, hit.triangle.y, hit.barycentric, rayDirection, hit.geometricNormal, coneWidth);
#endif
    return shapeSurface(hit.triangle.y, hit.barycentric, rayDirection, hit.geometricNormal, coneWidth);
}

// Tangent-space normal mapping with the MikkTSpace frame: the tangent made orthogonal to the
// interpolated normal, bitangent = cross(n, t) x handedness. A mapped normal that would face away
// from the geometric normal (or a surface without tangents) keeps the interpolated normal.
vec3 mappedNormal(vec3 n, vec3 geometricNormal, TexturedSurface m, TextureRef r) {
    vec3 t = m.tangent - dot(m.tangent, n) * n;
    if (!(dot(t, t) > 1e-12) || !isFiniteVec3(t)) return n;
    t = normalize(t);
    vec3 b = cross(n, t) * m.handedness;
    vec3 c = sampleSurfaceTexture(m, r).xyz * 2.0 - 1.0;
    vec3 mapped = normalize(t * (c.x * r.scale) + b * (c.y * r.scale) + n * c.z);
    return isFiniteVec3(mapped) && dot(mapped, geometricNormal) > 0.0 ? mapped : n;
}

// The KHR_materials_* textures, each family only in the variant of a scene that samples it:
// specular x A, specular colour x RGB, transmission x R, thickness x G. A thickness of 0 makes the
// surface thin-walled where a ray enters; leaving, it stays a volume boundary, so the integrator
// always stops the absorption of a volume it entered (docs/MATERIALS.md).
void applyExtensionTextures(Hit hit, vec3 rayDirection, TexturedSurface m, INOUT(SurfaceShading) s) {
#ifdef HAS_SPECULAR_TEXTURES
    TextureRef r = fetchTextureRef(hit.material, TEXREF_SPECULAR);
    if (hasTexture(r)) s.material.specularFactor *= sampleSurfaceTexture(m, r).a;
    r = fetchTextureRef(hit.material, TEXREF_SPECULAR_COLOR);
    if (hasTexture(r)) s.material.specularColor *= sampleSurfaceTexture(m, r).rgb;
#endif
#ifdef HAS_TRANSMISSION_TEXTURES
    TextureRef t = fetchTextureRef(hit.material, TEXREF_TRANSMISSION);
    if (hasTexture(t)) s.material.transmission *= sampleSurfaceTexture(m, t).r;
#endif
#ifdef HAS_THICKNESS_TEXTURES
    TextureRef d = fetchTextureRef(hit.material, TEXREF_THICKNESS);
    if (hasTexture(d) && !s.material.thinWalled) {
        s.material.thickness *= sampleSurfaceTexture(m, d).g;
        s.material.thinWalled = !(s.material.thickness > 0.0) && dot(rayDirection, hit.geometricNormal) < 0.0;
    }
#endif
}

// glTF's texture semantics: base colour x texture x COLOR_0; roughness x G, metallic x B;
// emission x texture. Emissive-textured triangles are light-sampled by their material's mean
// emission, whose luminance the emissive reference holds (emissive_lights.glsl); emissive-textured
// shapes are not (their light samples would need the shape's UV), so BSDF sampling alone finds
// them, unweighted. Meshes and analytic shapes alike (shape_uv.glsl). The occlusion texture is
// not read: a path tracer computes occlusion itself (docs/MATERIALS.md).
void applyTextures(Hit hit, vec3 rayDirection, float coneWidth, INOUT(SurfaceShading) s) {
    TexturedSurface m = texturedSurface(hit, rayDirection, coneWidth);
    s.curvature = m.curvature;
    s.material.baseColor *= m.color.rgb;
    TextureRef r = fetchTextureRef(hit.material, TEXREF_BASE_COLOR);
    if (hasTexture(r)) s.material.baseColor *= sampleSurfaceTexture(m, r).rgb;
    r = fetchTextureRef(hit.material, TEXREF_METALLIC_ROUGHNESS);
    if (hasTexture(r)) {
        vec4 metallicRoughness = sampleSurfaceTexture(m, r);
        s.material.roughness *= metallicRoughness.g;
        s.material.metallic *= metallicRoughness.b;
    }
    r = fetchTextureRef(hit.material, TEXREF_EMISSIVE);
    if (hasTexture(r)) {
        s.emission *= sampleSurfaceTexture(m, r).rgb;
        s.sampledEmission = hit.onMesh ? vec3(emissiveTextureLightLuminance(hit.material)) : vec3(0.0);
    }
    r = fetchTextureRef(hit.material, TEXREF_NORMAL);
    if (hasTexture(r)) s.normal = mappedNormal(s.normal, hit.geometricNormal, m, r);
#if defined(HAS_SPECULAR_TEXTURES) || defined(HAS_TRANSMISSION_TEXTURES) || defined(HAS_THICKNESS_TEXTURES)
    applyExtensionTextures(hit, rayDirection, m, s);
#endif
}
#endif

// `coneWidth`: the ray cone's width at the hit, for the textures' level of detail.
SurfaceShading shadeSurface(Hit hit, vec3 rayDirection, float coneWidth) {
    vec3 emission = emissionSeen(hit, rayDirection) ? fetchEmission(hit.material) : vec3(0.0);
    SurfaceShading s = SurfaceShading(fetchSurfaceMaterial(hit.material), emission, emission, hit.shadingNormal, 0.0);
#ifdef HAS_TEXTURES
    if (hit.triangle.y >= 0) applyTextures(hit, rayDirection, coneWidth, s); // a mesh or a shape
#endif
    return s;
}
