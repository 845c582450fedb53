#include "trace_state.glsl"

// The BVH's triangle filter (BVH_TRIANGLE_FILTER in bvh/traverse.glsl): which triangle hits count.
// - Alpha (HAS_ALPHA): MASK drops a hit whose alpha (base colour factor x texture x COLOR_0) is below
//   the cutoff; BLEND keeps it with probability alpha (stochastic transparency: unbiased on
//   average, for camera, bounce and shadow rays alike, so shadows respect alpha).
// - Single-sided materials (HAS_SINGLE_SIDED): camera rays pass through their back faces, as glTF's
//   back-face culling shows them. Secondary rays see both sides (a closed single-sided object still
//   casts shadows and refracts). Emitters are never culled; a single-sided one emits from its front
//   face only (emissionSeen, material.glsl), so its back face shows as an unlit surface.
float surfaceAlpha(int material, int slot, int instance, vec3 tuv, vec3 localDirection) {
    float alpha = materialTexel(material, 0).w;
#ifdef HAS_TEXTURES
    mat3 worldFromLocal = inverse(meshLocalFromWorld(instance));
    vec3 p0 = bvhTrianglePosition(slot, 0);
    vec3 normal = bvhNormalToWorld(instance, cross(bvhTrianglePosition(slot, 1) - p0, bvhTrianglePosition(slot, 2) - p0));
    TexturedSurface s = meshSurface(slot, instance, tuv.yz, normalize(worldFromLocal * localDirection), normal,
                                    coneWidthAt(gFilterCone, tuv.x));
    alpha *= s.color.a;
    TextureRef r = fetchTextureRef(material, TEXREF_BASE_COLOR);
    if (hasTexture(r)) alpha *= sampleSurfaceTexture(s, r).a;
#endif
    return alpha;
}

// Single-sided, the triangle's mark (renderer/gpu_scene/mesh_data.h, markCulledTriangles) says
// whether its material culls: the filter reads no material for it, only texels the triangle test
// fetched already (llvmpipe pays for every fetch a filter holds, at every triangle test).
bool bvhAcceptTriangle(int instance, int slot, vec3 tuv, vec3 localDirection) {
#ifdef HAS_SINGLE_SIDED
    if (gCullBackFaces && bvhTriangleMark(slot) > 0.0) {
        vec3 p0 = bvhTrianglePosition(slot, 0);
        if (dot(cross(bvhTrianglePosition(slot, 1) - p0, bvhTrianglePosition(slot, 2) - p0), localDirection) > 0.0) return false;
    }
#endif
#ifdef HAS_ALPHA
    int material = int(bvhTriangleVertices(slot).w);
    vec4 mode = materialTexel(material, 5); // alpha mode, cutoff, double-sided
    if (mode.x == 0.0) return true;
    float alpha = surfaceAlpha(material, slot, instance, tuv, localDirection);
    if (mode.x == 1.0) return alpha >= mode.y;
    uvec4 bits = pcg4d(gAlphaKey + uvec4(uint(slot), uint(instance), 0u, 0u));
    return unitFloatFromBits(bits.x) < alpha;
#else
    return true;
#endif
}
