// Watertight ray/triangle intersection (Woop, Benthin, Wald, JCGT 2013); twin of
// renderer/bvh/triangle_intersect.cpp. `precise` keeps the edge functions free of fused
// multiply-adds: neighbouring triangles then compute exactly opposite values on a shared edge.
// Define BVH_NO_DOUBLE to drop the double-precision tie-break on drivers without fp64.

struct BvhWatertightRay {
    vec3 origin;
    int kx;
    int ky;
    int kz;
    vec3 shear; // (sx, sy, sz)
};

BvhWatertightRay bvhPrepareWatertight(vec3 origin, vec3 direction) {
    vec3 a = abs(direction);
    int kz = a.x >= a.y ? (a.x >= a.z ? 0 : 2) : (a.y >= a.z ? 1 : 2);
    int kx = kz == 2 ? 0 : kz + 1;
    int ky = kx == 2 ? 0 : kx + 1;
    if (direction[kz] < 0.0) {
        int swap = kx;
        kx = ky;
        ky = swap;
    }
    precise vec3 shear = vec3(direction[kx] / direction[kz], direction[ky] / direction[kz], 1.0 / direction[kz]);
    return BvhWatertightRay(origin, kx, ky, kz, shear);
}

// On a hit with 0 < t < tMax: true and tuv = (t, weight of p1, weight of p2).
bool bvhIntersectTriangle(BvhWatertightRay ray, vec3 p0, vec3 p1, vec3 p2, float tMax, out vec3 tuv) {
    tuv = vec3(0.0);
    precise vec3 a = p0 - ray.origin;
    precise vec3 b = p1 - ray.origin;
    precise vec3 c = p2 - ray.origin;
    precise float ax = a[ray.kx] - ray.shear.x * a[ray.kz];
    precise float ay = a[ray.ky] - ray.shear.y * a[ray.kz];
    precise float bx = b[ray.kx] - ray.shear.x * b[ray.kz];
    precise float by = b[ray.ky] - ray.shear.y * b[ray.kz];
    precise float cx = c[ray.kx] - ray.shear.x * c[ray.kz];
    precise float cy = c[ray.ky] - ray.shear.y * c[ray.kz];
    precise float u = cx * by - cy * bx;
    precise float v = ax * cy - ay * cx;
    precise float w = bx * ay - by * ax;
#ifndef BVH_NO_DOUBLE
    if (u == 0.0 || v == 0.0 || w == 0.0) {
        u = float(double(cx) * double(by) - double(cy) * double(bx));
        v = float(double(ax) * double(cy) - double(ay) * double(cx));
        w = float(double(bx) * double(ay) - double(by) * double(ax));
    }
#endif
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
    precise float det = u + v + w;
    if (det == 0.0) return false;
    precise float az = ray.shear.z * a[ray.kz];
    precise float bz = ray.shear.z * b[ray.kz];
    precise float cz = ray.shear.z * c[ray.kz];
    precise float t = (u * az + v * bz + w * cz) / det;
    if (!(t > 0.0 && t < tMax)) return false;
    tuv = vec3(t, v / det, w / det);
    return true;
}
