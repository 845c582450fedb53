// Next-event estimation to the sun, point and spot lights (delta lights: no MIS partner). Light
// buffer texels: 0 type; 1 rgb intensity (W/m^2 sun, W/sr point/spot), cos of the sun's angular
// radius; 2 position, cos outer cone; 3 direction the light shines along, cos inner cone.
const int LIGHT_SUN = 0;
const int LIGHT_POINT = 1;
const int LIGHT_SPOT = 2;

struct LightSample {
    vec3 direction; // towards the light
    float distance;
    vec3 irradiance; // at a surface facing the light (before cos)
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
        vec3 towardsSun = intensity.w < 1.0 ? worldFromLocal(frameFromNormal(-shine.xyz), uniformCone(u, intensity.w)) : -shine.xyz;
        return LightSample(towardsSun, RAY_MAX, intensity.rgb);
    }
    vec3 offset = position.xyz - p;
    float distance2 = max(dot(offset, offset), 1e-12);
    float distance = sqrt(distance2);
    vec3 direction = offset / distance;
    vec3 irradiance = intensity.rgb / distance2;
    if (type == LIGHT_SPOT) irradiance *= spotFalloff(shine.xyz, -direction, position.w, shine.w);
    return LightSample(direction, distance, irradiance);
}
