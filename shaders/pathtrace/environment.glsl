// The environment seen by rays that leave the scene: a uniform colour, or an equirectangular map
// oriented as CONTRACTS.md "Environment" says: u = 0.5 + atan2(z, x) / 2pi, v = acos(y) / pi from
// the top row, rotated about +Y.
uniform vec3 uEnvironmentColor; // radiance x intensity, used without a map
#ifdef HAS_ENV_MAP
uniform sampler2D uEnvironmentMap; // row 0 = top of the image
uniform float uEnvironmentIntensity;
uniform float uEnvironmentRotation; // radians about +Y
#endif

vec2 environmentUv(vec3 d) {
    return vec2(0.5 + atan(d.z, d.x) * (0.5 * INV_PI), acos(clamp(d.y, -1.0, 1.0)) * INV_PI);
}

vec3 rotateAboutY(vec3 d, float angle) {
    float c = cos(angle);
    float s = sin(angle);
    return vec3(c * d.x + s * d.z, d.y, -s * d.x + c * d.z);
}

vec3 environmentRadiance(vec3 direction) {
#ifdef HAS_ENV_MAP
    vec2 uv = environmentUv(rotateAboutY(direction, -uEnvironmentRotation));
    return uEnvironmentIntensity * textureLod(uEnvironmentMap, uv, 0.0).rgb;
#else
    return uEnvironmentColor;
#endif
}
