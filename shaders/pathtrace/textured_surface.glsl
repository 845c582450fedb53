// What texturing needs at a hit (HAS_TEXTURES), on a mesh (mesh_surface.glsl) or an analytic shape
// (shape_surface.glsl): UV sets, COLOR_0, the tangent frame for normal maps, the ray-cone LOD per UV
// set, and a curvature estimate for the cone's next spread.
#include "textures/texture_sample.glsl"

struct TexturedSurface {
    vec2 uv0;
    vec2 uv1;
    vec4 color;     // COLOR_0 (1 where there is none)
    vec3 tangent;   // world space, along +u, not normalised; zero where there is none
    float handedness;
    float lambda0;  // ray-cone LOD of UV set 0 before the texture's size (ray_cone.glsl)
    float lambda1;
    float curvature; // 1/m
};

vec2 surfaceUv(TexturedSurface s, TextureRef r) { return transformUv(r, r.texCoord == 1 ? s.uv1 : s.uv0); }

// A texture reference sampled at the surface, at the cone's LOD.
vec4 sampleSurfaceTexture(TexturedSurface s, TextureRef r) {
    return sampleTextureRef(r, surfaceUv(s, r), textureRefLod(r, r.texCoord == 1 ? s.lambda1 : s.lambda0));
}
