#pragma once
// KHR_lights_punctual photometric intensities to the radiometric quantities the path tracer uses.
// Blender mode (default) reads them as Blender 3.4's glTF importer does: a sun of E lux gives an
// irradiance of E/683 W/m^2, a point or spot light of I cd a radiant intensity of I/683 W/sr.
// Raw mode uses the intensity as is (three.js, the Khronos sample viewer). Emission is never scaled.
#include "scene/core/components.h"
#include "scene/core/settings.h"

#include <glm/glm.hpp>

namespace glint::renderer {

inline constexpr float lumensPerWatt = 683.0f;

// Irradiance (sun) or radiant intensity (point, spot), per colour channel.
inline glm::vec3 radiometricIntensity(const Light& light, LightUnits units) {
    const float scale = units == LightUnits::Raw ? 1.0f : 1.0f / lumensPerWatt;
    return light.color * (light.intensity * scale);
}

} // namespace glint::renderer
