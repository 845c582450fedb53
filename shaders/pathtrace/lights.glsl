// Next-event estimation to the sun, point and spot lights. Light buffer texels: 0 type, radius
// (metres, point/spot; 0: a delta light); 1 rgb intensity (W/m^2 sun, W/sr point/spot), cos of the
// sun's angular radius; 2 position, cos outer cone; 3 direction the light shines along, cos inner cone.
// - A sun with an angular diameter is a disk of uniform radiance E / (solid angle) that camera and
//   BSDF-sampled rays see (sunDiskRadiance), weighted against light sampling by MIS.
// - A point or spot light with a radius is a sphere of uniform radiance I / (pi r^2) (the same
//   intensity far away), sampled by the cone it subtends: soft shadows. Camera and BSDF-sampled rays
//   hit the sphere (sphereLampEmission), weighted against the cone sampling by MIS.
const int LIGHT_SUN = 0;
const int LIGHT_POINT = 1;
const int LIGHT_SPOT = 2;

struct LightSample {
    vec3 direction; // towards the light
    float distance;
    vec3 irradiance; // at a surface facing the light (before cos)
    float pdf;       // solid angle, for MIS with BSDF sampling; 0: nothing else finds this light
    vec4 target;     // w = 1: the shadow ray ends at xyz (the light's position, or just off a lamp's
                     // surface on the side of the shading point); w = 0: a sun, in `direction`
};

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
        if (!(intensity.w < 1.0)) return LightSample(-shine.xyz, RAY_MAX, intensity.rgb, 0.0, vec4(0.0));
        vec3 towardsSun = worldFromLocal(frameFromNormal(-shine.xyz), uniformCone(u, intensity.w));
        return LightSample(towardsSun, RAY_MAX, intensity.rgb, uniformConePdf(intensity.w), vec4(0.0));
    }
    vec3 offset = position.xyz - p;
    float distance2 = max(dot(offset, offset), 1e-12);
    float distance = sqrt(distance2);
    vec3 direction = offset / distance;
    float falloff = type == LIGHT_SPOT ? spotFalloff(shine.xyz, -direction, position.w, shine.w) : 1.0;
    float radius = lightTexel(light, 0).y;
    if (!(radius > 0.0) || distance2 <= radius * radius)
        return LightSample(direction, distance, falloff * intensity.rgb / distance2, 0.0, vec4(position.xyz, 1.0));
    // The sphere's cone: irradiance = L x solid angle, L = I / (pi r^2).
    float oneMinusCos = sphereConeOneMinusCos(radius, distance2);
    vec3 towards = worldFromLocal(frameFromNormal(direction), uniformCone(u, 1.0 - oneMinusCos));
    float along = dot(towards, offset);
    vec3 perpendicular = offset - along * towards; // no cancellation of distance2 - along^2 far away
    float t = along - sqrt(max(radius * radius - dot(perpendicular, perpendicular), 0.0));
    vec3 radiance = falloff * sphereLampRadiance(intensity.rgb, radius);
    // Rays hit the sphere only where the variant has them (sphere_lamps.glsl): there the sample is
    // weighted against BSDF sampling, elsewhere it is the only way to the lamp.
#ifdef HAS_SPHERE_LAMPS
    float pdf = conePdfFromOneMinusCos(oneMinusCos);
#else
    float pdf = 0.0;
#endif
    // The shadow ray ends just outside the sampled point of the sphere (ray_offset.glsl), so that it
    // finds neither this lamp nor, however close the shading point is, the lamp's far side.
    vec3 onSphere = p + max(t, 0.0) * towards;
    vec4 target = vec4(bvhOffsetRayOrigin(onSphere, normalize(onSphere - position.xyz)), 1.0);
    return LightSample(towards, max(t, 0.0), radiance * (TWO_PI * oneMinusCos), pdf, target);
}

// Emission of the nearest sphere lamp that a ray from `ray.origin` hits before tMax (its distance in
// `t`; RAY_MAX where none is), for a ray sampled with `bsdfPdf` (solid angle; 0 for camera rays and
// delta lobes: weight 1), weighted against the lamp's cone sampling by the power heuristic. A spot's
// cone applies by the direction from the lamp's centre to the ray's origin, as next-event estimation
// applies it to the shading point: both strategies estimate the same integrand.
// t: the distance to the nearest sphere lamp before tMax (RAY_MAX: none); objectId: its node id.
vec3 sphereLampEmission(Ray ray, float tMax, float bsdfPdf, OUT(float) t, OUT(float) objectId) {
    int light;
    t = closestLamp(ray.origin, ray.direction, tMax, light);
    objectId = 0.0;
    if (light < 0) {
        t = RAY_MAX;
        return vec3(0.0);
    }
    objectId = lightTexel(light, 0).z;
    vec3 offset = lightTexel(light, 2).xyz - ray.origin;
    float distance2 = dot(offset, offset);
    float radius = lampRadius(light);
    vec4 shine = lightTexel(light, 3);
    float falloff = int(lightTexel(light, 0).x) == LIGHT_SPOT
                        ? spotFalloff(shine.xyz, -offset * inversesqrt(distance2), lightTexel(light, 2).w, shine.w) : 1.0;
    vec3 radiance = falloff * sphereLampRadiance(lightTexel(light, 1).rgb, radius);
    if (!(bsdfPdf > 0.0)) return radiance;
    return radiance * powerHeuristic(bsdfPdf, conePdfFromOneMinusCos(sphereConeOneMinusCos(radius, distance2)));
}

// Radiance of the suns' disks in `direction` for a ray that leaves the scene. A finite sun is an
// area light in direction space: a ray that left a surface by sampling a non-delta lobe with
// `bsdfPdf` (solid angle) is weighted against the sun's cone sampling by the power heuristic, as NEE
// is against it (punctualCandidate); bsdfPdf 0 (a camera ray, or a delta lobe of a mirror or smooth
// glass, which NEE cannot produce) sees the disk with weight 1. A delta sun has no disk: no ray finds it.
vec3 sunDiskRadiance(vec3 direction, float bsdfPdf) {
    vec3 sum = vec3(0.0);
#ifdef HAS_PUNCTUAL_LIGHTS
    for (int light = 0; light < uLightCount; ++light) {
        vec4 intensity = lightTexel(light, 1);
        if (int(lightTexel(light, 0).x) != LIGHT_SUN || !(intensity.w < 1.0)) continue;
        if (dot(direction, -lightTexel(light, 3).xyz) < intensity.w) continue;
        float pdf = uniformConePdf(intensity.w);
        sum += intensity.rgb * pdf * (bsdfPdf > 0.0 ? powerHeuristic(bsdfPdf, pdf) : 1.0);
    }
#endif
    return sum;
}
