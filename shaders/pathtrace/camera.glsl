// Primary rays: a sub-pixel position from the path's first draw (common/rng.glsl: in the
// low-discrepancy stream, dimensions 0 and 1 of the pixel's Owen-scrambled Sobol' sequence, so the
// first 2^k samples cover the pixel as a (0,k,2)-net), a box pixel filter, and a thin lens for depth
// of field from the second draw (sampling/warp.glsl). uIndependentSampler picks the stream (main.frag.glsl).
uniform mat4 uWorldFromCamera;
uniform int uOrthographic;   // 0: perspective, 1: orthographic
uniform vec2 uHalfExtent;    // tan(fov/2) per axis (perspective) or half extents in metres (orthographic)
uniform float uLensRadius;   // metres; 0: pinhole
uniform float uFocusDistance;
uniform vec2 uResolution;
uniform int uIndependentSampler;

Ray cameraRay(uvec2 pixel, INOUT(Rng) rng) {
    vec2 film = (vec2(pixel) + rand2(rng)) / uResolution * 2.0 - 1.0;
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
