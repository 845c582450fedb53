// The environment seen by rays that leave the scene: a uniform colour, or an equirectangular map
// (docs/UNITS.md, "Environment") rotated about +Y and importance-sampled by its luminance with the
// CDF table of renderer/cpu_twin/env_sampling.h.
#include "sampling/environment_sampling.glsl"

uniform vec3 uEnvironmentColor; // radiance x intensity, used without a map
#ifdef HAS_ENV_MAP
uniform sampler2D uEnvironmentMap;   // row 0 = top of the image
uniform sampler2D uEnvironmentCdf;   // GL_R32F, one texel wider and taller than the map
uniform ivec2 uEnvironmentSize;
uniform float uEnvironmentIntensity;
uniform float uEnvironmentRotation;  // radians about +Y
#endif

vec3 rotateAboutY(vec3 d, float angle) {
    float c = cos(angle);
    float s = sin(angle);
    return vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
}

vec3 environmentRadiance(vec3 direction) {
#ifdef HAS_ENV_MAP
    vec2 uv = equirectFromDirection(rotateAboutY(direction, -uEnvironmentRotation));
    return uEnvironmentIntensity * textureLod(uEnvironmentMap, uv, 0.0).rgb;
#else
    return uEnvironmentColor;
#endif
}

// Whether next-event estimation samples the environment (only a map: a uniform colour is found as
// well by BSDF sampling alone).
bool environmentIsSampled() {
#ifdef HAS_ENV_MAP
    return true;
#else
    return false;
#endif
}

// A world direction towards the environment and its solid-angle pdf.
vec3 sampleEnvironment(vec2 u, OUT(float) pdf) {
#ifdef HAS_ENV_MAP
    vec3 mapDirection = sampleEnvironmentDirection(uEnvironmentCdf, uEnvironmentSize, u, pdf);
    return rotateAboutY(mapDirection, uEnvironmentRotation);
#else
    pdf = 0.0;
    return vec3(0.0, 1.0, 0.0);
#endif
}

float environmentPdf(vec3 direction) {
#ifdef HAS_ENV_MAP
    return environmentDirectionPdf(uEnvironmentCdf, uEnvironmentSize, rotateAboutY(direction, -uEnvironmentRotation));
#else
    return 0.0;
#endif
}
