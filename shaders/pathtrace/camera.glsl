// Primary rays: one sub-pixel jitter per sample from the R2 low-discrepancy sequence, rotated per
// pixel (Cranley-Patterson) so neighbouring pixels do not share a pattern; a box pixel filter; a thin
// lens for depth of field (sampling/warp.glsl). The independent sampler mode replaces R2 by plain hashed uniforms.
uniform mat4 uWorldFromCamera;
uniform int uOrthographic;   // 0: perspective, 1: orthographic
uniform vec2 uHalfExtent;    // tan(fov/2) per axis (perspective) or half extents in metres (orthographic)
uniform float uLensRadius;   // metres; 0: pinhole
uniform float uFocusDistance;
uniform vec2 uResolution;
uniform int uIndependentSampler;

// R2 in 0.32 fixed point: exact for any sample index (floats would lose the fraction).
vec2 r2Jitter(uint sampleIndex, uvec2 rotation) {
    uvec2 point = uvec2(3242174889u, 2447445413u) * sampleIndex + rotation;
    return vec2(unitFloatFromBits(point.x), unitFloatFromBits(point.y));
}

// The rotation is keyed on the pixel and seed only (sample index 0xffffffff is never rendered).
vec2 pixelJitter(uvec2 pixel, uint sampleIndex, uint seed, INOUT(Rng) rng) {
    if (uIndependentSampler != 0) return rand2(rng);
    Rng pixelStream = rngStart(pixel, 0xffffffffu, seed);
    return r2Jitter(sampleIndex, rngBits(pixelStream.key, 0u).xy);
}

Ray cameraRay(uvec2 pixel, uint sampleIndex, uint seed, INOUT(Rng) rng) {
    vec2 film = (vec2(pixel) + pixelJitter(pixel, sampleIndex, seed, rng)) / uResolution * 2.0 - 1.0;
    vec3 origin = vec3(0.0);
    vec3 direction = vec3(film * uHalfExtent, -1.0);
    if (uOrthographic != 0) {
        origin = vec3(film * uHalfExtent, 0.0);
        direction = vec3(0.0, 0.0, -1.0);
    }
    vec2 lens = rand2(rng);
    if (uLensRadius > 0.0) {
        vec3 focus = origin + direction * (uFocusDistance / -direction.z);
        origin += vec3(uLensRadius * concentricDisk(lens), 0.0);
        direction = focus - origin;
    }
    return Ray((uWorldFromCamera * vec4(origin, 1.0)).xyz, normalize(mat3(uWorldFromCamera) * direction));
}

vec3 cameraForward() { return normalize(-uWorldFromCamera[2].xyz); }

// The ray cone of a camera ray (textures/ray_cone.glsl): a perspective pixel subtends
// 2 tan(fov/2) / height radians; an orthographic one is a pixel wide and does not spread.
RayCone cameraCone() {
    float pixel = 2.0 * uHalfExtent.y / uResolution.y;
    return uOrthographic != 0 ? RayCone(pixel, 0.0) : RayCone(0.0, pixel);
}
