#include "renderer/bvh/triangle_intersect.h"

#include <cmath>
#include <utility>

namespace glint::bvh {

WatertightRay prepareWatertight(const Ray& ray)
{
    WatertightRay w;
    w.origin = ray.origin;
    const glm::vec3 a = glm::abs(ray.direction);
    w.kz = a.x >= a.y ? (a.x >= a.z ? 0 : 2) : (a.y >= a.z ? 1 : 2);
    w.kx = (w.kz + 1) % 3;
    w.ky = (w.kx + 1) % 3;
    // Keep the winding of the projected triangle: swap when the dominant component is negative.
    if (ray.direction[w.kz] < 0.0f) std::swap(w.kx, w.ky);
    w.sx = ray.direction[w.kx] / ray.direction[w.kz];
    w.sy = ray.direction[w.ky] / ray.direction[w.kz];
    w.sz = 1.0f / ray.direction[w.kz];
    return w;
}

bool intersectTriangle(const WatertightRay& ray, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                       float tMin, float tMax, TriangleHit& hit)
{
    const glm::vec3 a = p0 - ray.origin;
    const glm::vec3 b = p1 - ray.origin;
    const glm::vec3 c = p2 - ray.origin;
    const float ax = a[ray.kx] - ray.sx * a[ray.kz];
    const float ay = a[ray.ky] - ray.sy * a[ray.kz];
    const float bx = b[ray.kx] - ray.sx * b[ray.kz];
    const float by = b[ray.ky] - ray.sy * b[ray.kz];
    const float cx = c[ray.kx] - ray.sx * c[ray.kz];
    const float cy = c[ray.ky] - ray.sy * c[ray.kz];
    float u = cx * by - cy * bx;
    float v = ax * cy - ay * cx;
    float w = bx * ay - by * ax;
    // An edge exactly through the ray: decide it in double, as the paper does.
    if (u == 0.0f || v == 0.0f || w == 0.0f) {
        u = static_cast<float>(double(cx) * double(by) - double(cy) * double(bx));
        v = static_cast<float>(double(ax) * double(cy) - double(ay) * double(cx));
        w = static_cast<float>(double(bx) * double(ay) - double(by) * double(ax));
    }
    if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return false;
    const float det = u + v + w;
    if (det == 0.0f || !std::isfinite(det)) return false;
    const float az = ray.sz * a[ray.kz];
    const float bz = ray.sz * b[ray.kz];
    const float cz = ray.sz * c[ray.kz];
    const float t = (u * az + v * bz + w * cz) / det;
    if (!(t > tMin && t < tMax)) return false;
    hit = TriangleHit{t, v / det, w / det};
    return true;
}

} // namespace glint::bvh
