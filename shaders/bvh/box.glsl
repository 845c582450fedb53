// Ray/box slab test for BVH nodes; twin of boxEntry() in renderer/bvh/traverse.cpp.

// The far distance grows by 2 gamma(3) so rounding never culls a box the ray touches (Ize,
// "Robust BVH Ray Traversal", JCGT 2013).
const float BVH_FAR_WIDENING = 1.00000071525573730469;

// Where the ray enters the node's box within [0, tMax], or -1.0 on a miss; `link`: the node's packed
// link, which its texel carries beside the box. The box is on the level's grid (gridOrigin,
// gridScale); its corners are computed as renderer/bvh/box_grid.cpp computes them, where the
// power-of-two scale leaves the sum the only rounding. Selections instead of min/max: a NaN slab
// (origin on the plane, zero direction) constrains nothing.
float bvhBoxEntry(int node, vec3 gridOrigin, vec3 gridScale, vec3 origin, vec3 inverseDirection, float tMax, out int link) {
    uvec4 texel = texelFetch(uBvhNodes, node);
    link = int(texel.w);
    precise vec3 lo = gridOrigin + vec3(texel.xyz & 0xFFFFu) * gridScale;
    precise vec3 hi = gridOrigin + vec3(texel.xyz >> 16u) * gridScale;
    precise vec3 t0 = (lo - origin) * inverseDirection;
    precise vec3 t1 = (hi - origin) * inverseDirection;
    vec3 enter = mix(t1, t0, lessThan(t0, t1));
    vec3 leave = mix(t1, t0, greaterThan(t0, t1));
    float nearT = 0.0;
    float farT = tMax;
    for (int axis = 0; axis < 3; ++axis) {
        if (enter[axis] > nearT) nearT = enter[axis];
        if (leave[axis] < farT) farT = leave[axis];
    }
    return nearT <= farT * BVH_FAR_WIDENING ? nearT : -1.0;
}
