// Origin for a spawned ray: off the surface by a few ULPs along the geometric normal, so it neither
// re-hits its own triangle nor starts behind a neighbour, at any coordinate magnitude (Wächter and
// Binder, Ray Tracing Gems ch. 6). Twin of renderer/bvh/ray_offset.cpp. `n`: unit geometric
// normal on the side the new ray leaves from.
vec3 bvhOffsetRayOrigin(vec3 p, vec3 n) {
    const float nearOrigin = 1.0 / 32.0;
    const float floatScale = 1.0 / 65536.0;
    const float intScale = 256.0;
    ivec3 ulps = ivec3(intScale * n);
    vec3 moved = intBitsToFloat(floatBitsToInt(p) + ivec3(p.x < 0.0 ? -ulps.x : ulps.x,
                                                          p.y < 0.0 ? -ulps.y : ulps.y,
                                                          p.z < 0.0 ? -ulps.z : ulps.z));
    return vec3(abs(p.x) < nearOrigin ? p.x + floatScale * n.x : moved.x,
                abs(p.y) < nearOrigin ? p.y + floatScale * n.y : moved.y,
                abs(p.z) < nearOrigin ? p.z + floatScale * n.z : moved.z);
}
