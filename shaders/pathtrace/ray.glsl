// Rays and hit records in world space.
struct Ray {
    vec3 origin;
    vec3 direction; // unit length
};

struct Hit {
    float t;
    vec3 geometricNormal; // unit, world space, not yet faced towards the ray
    vec3 shadingNormal;   // unit, world space, on the same side as geometricNormal
    int material;         // index into the material buffer; -1: no hit
    float objectId;       // node id of what was hit
};

Hit noHit() {
    return Hit(RAY_MAX, vec3(0.0, 1.0, 0.0), vec3(0.0, 1.0, 0.0), -1, 0.0);
}

// Spawns a secondary ray from p without self-intersection at any coordinate magnitude:
// offsets in integer ULPs away from the surface on the side of `n` ("A Fast and Robust Method for
// Avoiding Self-Intersection", Ray Tracing Gems ch. 6).
vec3 offsetRayOrigin(vec3 p, vec3 n) {
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

Ray spawnRay(vec3 p, vec3 faceNormal, vec3 direction) {
    vec3 side = dot(direction, faceNormal) >= 0.0 ? faceNormal : -faceNormal;
    return Ray(offsetRayOrigin(p, side), direction);
}
