// The BVH heat map (DEBUG_VIEW_BVH_COST): the camera ray's closest-hit walk, counted instead of
// shaded. radiance = (nodes + primitives, nodes, primitives): nodes visited over both BVH levels
// and triangle (or shape) tests; 0 where the ray misses the scene's bounds or the scene has no
// meshes (analytic shapes are tested in a plain loop, outside the BVH). Depth and object id of
// the first hit come along, so the view lines up with the others. Included by main.frag.glsl
// only in this variant: traverse.glsl then compiles its counters in (BVH_COUNT_COST).
PathResult bvhCost(Ray ray, vec3 viewAxis, INOUT(Rng) rng) {
    PathResult result = PathResult(vec3(0.0), vec3(0.0), vec3(0.0), -1.0, 0.0, vec4(0.0, 1.0, 0.0, 0.0));
#ifdef HAS_MESHES
    bvhCostNodes = 0;
    bvhCostPrimitives = 0;
#endif
    setTraceState(true, alphaKey(rng, 2u), cameraCone());
    Hit hit = traceClosest(ray);
#ifdef HAS_MESHES
    result.radiance = vec3(float(bvhCostNodes + bvhCostPrimitives), float(bvhCostNodes), float(bvhCostPrimitives));
#endif
    if (hit.material >= 0) {
        result.depth = hit.t * dot(ray.direction, viewAxis);
        result.objectId = hit.objectId;
    }
    return result;
}
