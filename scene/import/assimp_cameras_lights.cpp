#include "assimp_cameras_lights.h"

#include <assimp/camera.h>
#include <assimp/light.h>

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

glm::vec3 toGlm(const aiVector3D& v) { return {v.x, v.y, v.z}; }

// A frame at `position` whose -Z is `forward` and whose +Y is as close to `up` as it can be.
glm::mat4 frameLookingAlong(glm::vec3 position, glm::vec3 forward, glm::vec3 up)
{
    const float length = glm::length(forward);
    forward = length > 0.0f && std::isfinite(length) ? forward / length : glm::vec3(0, 0, -1);
    if (!(glm::length(glm::cross(forward, up)) > 1e-6f))
        up = std::abs(forward.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 right = glm::normalize(glm::cross(forward, up));
    const glm::vec3 trueUp = glm::cross(right, forward);
    glm::mat4 frame{1.0f};
    frame[0] = glm::vec4(right, 0.0f);
    frame[1] = glm::vec4(trueUp, 0.0f);
    frame[2] = glm::vec4(-forward, 0.0f);
    frame[3] = glm::vec4(position, 1.0f);
    return frame;
}

float positiveOr(float value, float fallback) { return value > 0.0f && std::isfinite(value) ? value : fallback; }

} // namespace

ImportedComponent convertCamera(const aiCamera& source)
{
    Camera camera;
    camera.znear = positiveOr(source.mClipPlaneNear, camera.znear);
    camera.zfar = source.mClipPlaneFar > camera.znear ? source.mClipPlaneFar : 0.0f;
    camera.aspectRatio = positiveOr(source.mAspect, 0.0f);
    if (source.mOrthographicWidth > 0.0f) {
        camera.projection = Projection::Orthographic;
        camera.xmag = source.mOrthographicWidth; // Assimp's is already the half width
        camera.ymag = camera.xmag / positiveOr(source.mAspect, 1.0f);
    } else {
        // Assimp gives half the horizontal angle; glTF wants the whole vertical one.
        const float halfWidth = std::tan(std::clamp(source.mHorizontalFOV, 1e-4f, 1.5f));
        camera.yfov = 2.0f * std::atan(halfWidth / positiveOr(source.mAspect, 1.0f));
    }
    const glm::vec3 position = toGlm(source.mPosition);
    return {camera, frameLookingAlong(position, toGlm(source.mLookAt), toGlm(source.mUp))};
}

std::optional<ImportedComponent> convertLight(const aiLight& source)
{
    Light light;
    switch (source.mType) {
    case aiLightSource_DIRECTIONAL: light.type = LightType::Sun; break;
    case aiLightSource_POINT: light.type = LightType::Point; break;
    case aiLightSource_SPOT: light.type = LightType::Spot; break;
    default: return std::nullopt;
    }
    // Assimp folds the intensity into the colour: split it back so the colour's largest channel is 1.
    const glm::vec3 diffuse = glm::max(glm::vec3(source.mColorDiffuse.r, source.mColorDiffuse.g, source.mColorDiffuse.b), glm::vec3(0.0f));
    const float peak = std::max({diffuse.x, diffuse.y, diffuse.z});
    light.intensity = std::isfinite(peak) ? peak : 0.0f;
    light.color = peak > 0.0f && std::isfinite(peak) ? diffuse / peak : glm::vec3(1.0f);
    if (light.type == LightType::Spot) {
        const float outer = std::clamp(source.mAngleOuterCone, 1e-3f, 1.5707963f);
        light.outerConeAngle = outer;
        light.innerConeAngle = std::clamp(source.mAngleInnerCone, 0.0f, outer);
    }
    const glm::vec3 position = light.type == LightType::Sun ? glm::vec3(0.0f) : toGlm(source.mPosition);
    const glm::vec3 direction = light.type == LightType::Point ? glm::vec3(0, 0, -1) : toGlm(source.mDirection);
    return ImportedComponent{light, frameLookingAlong(position, direction, toGlm(source.mUp))};
}

} // namespace glint
