#include "renderer/bvh/ray_offset.h"

#include <bit>
#include <cmath>
#include <cstdint>

namespace glint::bvh {
namespace {

// Constants from the chapter: below 1/32 a fixed step, elsewhere a step of 256 * n ULPs.
constexpr float kNearOrigin = 1.0f / 32.0f;
constexpr float kFloatScale = 1.0f / 65536.0f;
constexpr float kIntScale = 256.0f;

float offsetAxis(float p, float n)
{
    if (std::fabs(p) < kNearOrigin) return p + kFloatScale * n;
    const auto ulps = static_cast<std::int32_t>(kIntScale * n);
    const std::uint32_t step = static_cast<std::uint32_t>(p < 0.0f ? -ulps : ulps);
    return std::bit_cast<float>(std::bit_cast<std::uint32_t>(p) + step);
}

} // namespace

glm::vec3 offsetRayOrigin(const glm::vec3& p, const glm::vec3& n)
{
    return {offsetAxis(p.x, n.x), offsetAxis(p.y, n.y), offsetAxis(p.z, n.z)};
}

} // namespace glint::bvh
