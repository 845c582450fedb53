// The flattened two-level BVH: texture buffers and fetch helpers. Layout, texel by texel, in
// renderer/bvh/bvh_layout.h (the contract with renderer/bvh/flatten.cpp).
uniform usamplerBuffer uBvhNodes;             // RGBA32UI, 1 texel per node: grid box (lo | hi << 16), link
uniform usamplerBuffer uBvhLevels;            // RGBA32UI, 2 texels per level: (origin, root link), (scale, root)
uniform samplerBuffer uBvhTrianglePositions;  // RGBA32F, 3 texels per triangle slot
uniform usamplerBuffer uBvhTriangleVertices;  // RGBA32UI, 1 texel per slot: (v0, v1, v2, material)
uniform usamplerBuffer uBvhInstances;         // RGBA32UI, 4 texels per instance
uniform int uBvhTopLevel;                     // the top level's level index; -1: no instances

const int BVH_STACK_SIZE = 64;      // kStackSize: per level (the shared stack holds two levels)
const int BVH_MAX_STEPS = 8192;     // kMaxTraversalSteps: over both levels, so a NaN ray ends
const uint BVH_INSTANCE_MESH = 0u;
const uint BVH_INSTANCE_SHAPE = 1u;
const uint BVH_INSTANCE_MIRRORED = 1u;

// A level's grid (renderer/bvh/box_grid.h: a node's box corner is origin + float(q) * scale), its
// root's link and its root's node index.
struct BvhLevel {
    vec3 gridOrigin;
    vec3 gridScale;
    int root;
    int rootNode;
};

BvhLevel bvhLevel(int level) {
    uvec4 origin = texelFetch(uBvhLevels, 2 * level);
    uvec4 scale = texelFetch(uBvhLevels, 2 * level + 1);
    return BvhLevel(uintBitsToFloat(origin.xyz), uintBitsToFloat(scale.xyz), int(origin.w), int(scale.w));
}

// Links are packed into one int, (first << 4) | count (renderer/bvh/bvh_layout.h, kMaxLinkFirst).
int bvhLinkFirst(int link) { return link >> 4; }
int bvhLinkCount(int link) { return link & 15; }

vec3 bvhTrianglePosition(int slot, int k) { return texelFetch(uBvhTrianglePositions, 3 * slot + k).xyz; }

// The renderer's mark of a slot (bvh_layout.h): the w of its first position texel, which the
// triangle test has fetched already.
float bvhTriangleMark(int slot) { return texelFetch(uBvhTrianglePositions, 3 * slot).w; }

// (v0, v1, v2, material): vertex indices into the scene's vertex attribute buffers.
uvec4 bvhTriangleVertices(int slot) { return texelFetch(uBvhTriangleVertices, slot); }

// (kind, target, objectId, flags)
uvec4 bvhInstanceInfo(int instance) { return texelFetch(uBvhInstances, 4 * instance + 3); }

// Row r of the instance's localFromWorld.
vec4 bvhInstanceRow(int instance, int r) { return uintBitsToFloat(texelFetch(uBvhInstances, 4 * instance + r)); }

// A mesh-local normal in world space: the transpose of localFromWorld, then normalised.
vec3 bvhNormalToWorld(int instance, vec3 localNormal) {
    vec3 world = localNormal.x * bvhInstanceRow(instance, 0).xyz + localNormal.y * bvhInstanceRow(instance, 1).xyz +
                 localNormal.z * bvhInstanceRow(instance, 2).xyz;
    return normalize(world);
}
