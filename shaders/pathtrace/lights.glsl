// Next-event estimation to the sun, point and spot lights. Light buffer texels: 0 type, radius
// (metres, point/spot; 0: a delta light); 1 rgb intensity (W/m^2 sun, W/sr point/spot), cos of the
// sun's angular radius; 2 position, cos outer cone; 3 direction the light shines along, cos inner cone.
// - A sun with an angular diameter is a disk of uniform radiance E / (solid angle) that camera and
//   BSDF-sampled rays see (sunDiskRadiance), weighted against light sampling by MIS.
// - A point or spot light with a radius is a sphere of uniform radiance I / (pi r^2) (the same
//   intensity far away), sampled by the cone it subtends: soft shadows. Rays do not hit the sphere
//   (no highlight of its shape in mirrors), as for delta lights.
const int LIGHT_SUN = 0;
const int LIGHT_POINT = 1;
const int LIGHT_SPOT = 2;

struct LightSample {
    vec3 direction; // towards the light
    float distance;
    vec3 irradiance; // at a surface facing the light (before cos)
    float pdf;       // solid angle, for MIS with BSDF sampling; 0: nothing else finds this light
};

// 1 - cos(asin(sqrt(sin2))) without cancellation for small sin2.
float oneMinusCosFromSin2(float sin2) { return sin2 / (1.0 + sqrt(max(1.0 - sin2, 0.0))); }

// KHR_lights_punctual's recommended smooth spot falloff.
float spotFalloff(vec3 shineDirection, vec3 toSurface, float cosOuter, float cosInner) {
    float scale = 1.0 / max(0.001, cosInner - cosOuter);
    float attenuation = clamp(dot(shineDirection, toSurface) * scale - cosOuter * scale, 0.0, 1.0);
    return attenuation * attenuation;
}

LightSample sampleLight(int light, vec3 p, vec2 u) {
    int type = int(lightTexel(light, 0).x);
    vec4 intensity = lightTexel(light, 1);
    vec4 position = lightTexel(light, 2);
    vec4 shine = lightTexel(light, 3);
    if (type == LIGHT_SUN) {
        if (!(intensity.w < 1.0)) return LightSample(-shine.xyz, RAY_MAX, intensity.rgb, 0.0);
        vec3 towardsSun = worldFromLocal(frameFromNormal(-shine.xyz), uniformCone(u, intensity.w));
        return LightSample(towardsSun, RAY_MAX, intensity.rgb, uniformConePdf(intensity.w));
    }
    vec3 offset = position.xyz - p;
    float distance2 = max(dot(offset, offset), 1e-12);
    float distance = sqrt(distance2);
    vec3 direction = offset / distance;
    float falloff = type == LIGHT_SPOT ? spotFalloff(shine.xyz, -direction, position.w, shine.w) : 1.0;
    float radius = lightTexel(light, 0).y;
    if (!(radius > 0.0) || distance2 <= radius * radius) return LightSample(direction, distance, falloff * intensity.rgb / distance2, 0.0);
    // The sphere's cone: irradiance = L x solid angle, L = I / (pi r^2).
    float sin2 = radius * radius / distance2;
    float oneMinusCos = oneMinusCosFromSin2(sin2);
    vec3 towards = worldFromLocal(frameFromNormal(direction), uniformCone(u, 1.0 - oneMinusCos));
    float along = dot(towards, offset);
    float t = along - sqrt(max(radius * radius - (distance2 - along * along), 0.0));
    vec3 radiance = falloff * intensity.rgb / (PI * radius * radius);
    return LightSample(towards, max(t, 0.0), radiance * (TWO_PI * oneMinusCos), 0.0);
}

// Radiance of the suns' disks in `direction` for a ray that leaves the scene. A finite sun is an
// area light in direction space: a ray that left a surface by sampling a non-delta lobe with
// `bsdfPdf` (solid angle) is weighted against the sun's cone sampling by the power heuristic, as NEE
// is against it (punctualCandidate); bsdfPdf 0 (a camera ray, or a delta lobe of a mirror or smooth
// glass, which NEE cannot produce) sees the disk with weight 1. A delta sun has no disk: no ray finds it.
vec3 sunDiskRadiance(vec3 direction, float bsdfPdf) {
    vec3 sum = vec3(0.0);
    for (int light = 0; light < uLightCount; ++light) {
        vec4 intensity = lightTexel(light, 1);
        if (int(lightTexel(light, 0).x) != LIGHT_SUN || !(intensity.w < 1.0)) continue;
        if (dot(direction, -lightTexel(light, 3).xyz) < intensity.w) continue;
        float pdf = uniformConePdf(intensity.w);
        sum += intensity.rgb * pdf * (bsdfPdf > 0.0 ? powerHeuristic(bsdfPdf, pdf) : 1.0);
    }
    return sum;
}
