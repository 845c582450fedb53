// Exact intersection of analytic shapes in their local space (see scene/core/components.h).
// Local rays are world rays under an affine map, so t is the same in both spaces. Sphere lamps
// (sphere_lamps.glsl) are no shapes, but they block shadow rays like one.
#include "sphere_lamps.glsl"

const int SHAPE_SPHERE = 0;
const int SHAPE_QUAD = 1;
const int SHAPE_DISK = 2;
const int SHAPE_BOX = 3;
const int SHAPE_CYLINDER = 4;
const int SHAPE_GROUND_PLANE = 5;
#ifdef HAS_TEXTURES
#include "shape_uv.glsl"
#endif

// Nearest root of |o + t d|^2 = r^2 in (0, tMax), with the cancellation-free quadratic
// ("Precision Improvements for Ray/Sphere Intersection", Ray Tracing Gems ch. 7).
bool hitSphere(vec3 o, vec3 d, float radius, float tMax, out float t, out vec3 normal) {
    precise float a = dot(d, d);
    precise float b = -dot(o, d);
    precise vec3 l = o + (b / a) * d;
    precise float discriminant = radius * radius - dot(l, l);
    if (discriminant < 0.0) return false;
    precise float c = dot(o, o) - radius * radius;
    precise float q = b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(a * discriminant);
    float t0 = c / q;
    float t1 = q / a;
    float near = min(t0, t1);
    float far = max(t0, t1);
    t = near > 0.0 ? near : far;
    if (!(t > 0.0 && t < tMax)) return false;
    normal = (o + t * d) / radius;
    return true;
}

// The plane y = 0 of local space, within `inside` (half extents for a quad, radius for a disk).
bool hitPlane(vec3 o, vec3 d, int kind, vec3 size, float radius, float tMax, out float t, out vec3 normal) {
    if (d.y == 0.0) return false;
    t = -o.y / d.y;
    if (!(t > 0.0 && t < tMax)) return false;
    vec3 p = o + t * d;
    if (kind == SHAPE_QUAD && (abs(p.x) > 0.5 * size.x || abs(p.z) > 0.5 * size.z)) return false;
    if (kind == SHAPE_DISK && dot(p.xz, p.xz) > radius * radius) return false;
    normal = vec3(0.0, 1.0, 0.0);
    return true;
}

bool hitBox(vec3 o, vec3 d, vec3 size, float tMax, out float t, out vec3 normal) {
    vec3 halfSize = 0.5 * size;
    vec3 inverse = 1.0 / d;
    vec3 t0 = (-halfSize - o) * inverse;
    vec3 t1 = (halfSize - o) * inverse;
    vec3 tNear3 = min(t0, t1);
    vec3 tFar3 = max(t0, t1);
    float tNear = max(tNear3.x, max(tNear3.y, tNear3.z));
    float tFar = min(tFar3.x, min(tFar3.y, tFar3.z));
    if (tNear > tFar) return false;
    t = tNear > 0.0 ? tNear : tFar;
    if (!(t > 0.0 && t < tMax)) return false;
    vec3 relative = (o + t * d) / halfSize;
    vec3 magnitude = abs(relative);
    if (magnitude.x >= magnitude.y && magnitude.x >= magnitude.z) normal = vec3(sign(relative.x), 0.0, 0.0);
    else if (magnitude.y >= magnitude.z) normal = vec3(0.0, sign(relative.y), 0.0);
    else normal = vec3(0.0, 0.0, sign(relative.z));
    return true;
}

// A closed cylinder along +Y: the side x^2 + z^2 = r^2 for |y| <= h/2, and two cap disks.
bool hitCylinder(vec3 o, vec3 d, float radius, float height, float tMax, out float t, out vec3 normal) {
    bool found = false;
    t = tMax;
    precise float a = dot(d.xz, d.xz);
    if (a > 0.0) {
        precise float b = -dot(o.xz, d.xz);
        precise vec2 l = o.xz + (b / a) * d.xz;
        precise float discriminant = radius * radius - dot(l, l);
        if (discriminant >= 0.0) {
            precise float c = dot(o.xz, o.xz) - radius * radius;
            precise float q = b + (b >= 0.0 ? 1.0 : -1.0) * sqrt(a * discriminant);
            float roots[2] = float[2](min(c / q, q / a), max(c / q, q / a));
            for (int i = 0; i < 2; ++i) {
                float y = o.y + roots[i] * d.y;
                if (roots[i] > 0.0 && roots[i] < t && abs(y) <= 0.5 * height) {
                    t = roots[i];
                    normal = vec3((o.xz + t * d.xz).x, 0.0, (o.xz + t * d.xz).y) / radius;
                    found = true;
                    break;
                }
            }
        }
    }
    for (int cap = 0; cap < 2; ++cap) {
        float y = cap == 0 ? 0.5 * height : -0.5 * height;
        if (d.y == 0.0) break;
        float tCap = (y - o.y) / d.y;
        vec2 p = o.xz + tCap * d.xz;
        if (tCap > 0.0 && tCap < t && dot(p, p) <= radius * radius) {
            t = tCap;
            normal = vec3(0.0, cap == 0 ? 1.0 : -1.0, 0.0);
            found = true;
        }
    }
    return found;
}

bool hitShapeLocal(int kind, vec3 o, vec3 d, vec4 params, float height, float tMax, out float t, out vec3 normal) {
    float radius = params.x;
    vec3 size = params.yzw;
    if (kind == SHAPE_SPHERE) return hitSphere(o, d, radius, tMax, t, normal);
    if (kind == SHAPE_BOX) return hitBox(o, d, size, tMax, t, normal);
    if (kind == SHAPE_CYLINDER) return hitCylinder(o, d, radius, height, tMax, t, normal);
    if (kind == SHAPE_GROUND_PLANE) return hitPlane(o, d, kind, size, radius, tMax, t, normal);
    return hitPlane(o, d, kind, size, radius, tMax, t, normal);
}

// Closest hit over every shape; `hit` keeps the nearer of what it held and what is found. Compiled
// in only for scenes with shapes (HAS_SHAPES): llvmpipe runs a loop's body at least once, masked,
// even when it has nothing to do, so an empty shape list would still cost one shape test per ray.
void intersectShapes(Ray ray, INOUT(Hit) hit) {
#ifdef HAS_SHAPES
    for (int shape = 0; shape < uShapeCount; ++shape) {
        vec4 header = shapeTexel(shape, 0); // kind, material, object id, cylinder height
        vec4 row0 = shapeTexel(shape, 1);   // localFromWorld, rows 0..2 of a 3x4 matrix
        vec4 row1 = shapeTexel(shape, 2);
        vec4 row2 = shapeTexel(shape, 3);
        vec3 o = vec3(dot(row0, vec4(ray.origin, 1.0)), dot(row1, vec4(ray.origin, 1.0)), dot(row2, vec4(ray.origin, 1.0)));
        vec3 d = vec3(dot(row0.xyz, ray.direction), dot(row1.xyz, ray.direction), dot(row2.xyz, ray.direction));
        float t;
        vec3 localNormal;
        if (!hitShapeLocal(int(header.x), o, d, shapeTexel(shape, 4), header.w, hit.t, t, localNormal)) continue;
        // Normals transform by the transpose of localFromWorld.
        vec3 n = normalize(row0.xyz * localNormal.x + row1.xyz * localNormal.y + row2.xyz * localNormal.z);
        vec2 uv = vec2(0.0);
#ifdef HAS_TEXTURES
        uv = shapeUv(int(header.x), o + t * d, localNormal, shapeTexel(shape, 4), header.w);
#endif
        hit = Hit(t, n, n, int(header.y), header.z, false, ivec2(-1, shape), uv);
    }
#endif
}

bool occludedByShapes(Ray ray, float distance) {
    if (occludedByLamps(ray.origin, ray.direction, distance)) return true;
#ifdef HAS_SHAPES
    Hit hit = noHit();
    hit.t = distance;
    intersectShapes(ray, hit);
    return hit.material >= 0;
#else
    return false;
#endif
}
