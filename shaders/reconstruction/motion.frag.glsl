// Motion vectors: where each pixel's surface was in the previous frame, in pixels (previous minus
// current). Camera motion from depth and the previous camera; object motion from the previous
// world transform of the instance the pixel sees (by object id). Misses move with the camera's
// rotation only (the environment is at infinity).
uniform sampler2D uNormalDepth;
uniform sampler2D uObjectId;
uniform vec2 uResolution;
uniform mat4 uWorldFromCamera;
uniform vec2 uHalfExtent;
uniform int uOrthographic;
uniform mat4 uPreviousCameraFromWorld;
uniform vec2 uPreviousHalfExtent;
uniform int uPreviousOrthographic;

const int MAX_MOVED = 32; // more moving instances than this fall back to camera motion
uniform int uMovedCount;
uniform float uMovedIds[MAX_MOVED];
uniform mat4 uPreviousFromCurrent[MAX_MOVED];

out vec4 outMotion;

vec3 movedToPrevious(vec3 world, float id) {
    for (int i = 0; i < uMovedCount; ++i)
        if (abs(uMovedIds[i] - id) < 0.5) return (uPreviousFromCurrent[i] * vec4(world, 1.0)).xyz;
    return world;
}

vec2 previousFilm(vec3 previousCamera) {
    if (uPreviousOrthographic != 0) return previousCamera.xy / uPreviousHalfExtent;
    return previousCamera.xy / max(-previousCamera.z, 1.0e-6) / uPreviousHalfExtent;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec2 film = gl_FragCoord.xy / uResolution * 2.0 - 1.0;
    float depth = texelFetch(uNormalDepth, pixel, 0).w;
    vec3 direction = vec3(film * uHalfExtent, -1.0);
    vec2 film0;
    if (depth < 0.0) {
        vec3 world = mat3(uWorldFromCamera) * direction;
        vec3 previous = mat3(uPreviousCameraFromWorld) * world;
        film0 = previous.z < 0.0 ? previous.xy / -previous.z / uPreviousHalfExtent : vec2(1.0e4);
    } else {
        vec3 local = uOrthographic != 0 ? vec3(film * uHalfExtent, -depth) : direction * depth;
        vec3 world = movedToPrevious((uWorldFromCamera * vec4(local, 1.0)).xyz, texelFetch(uObjectId, pixel, 0).x);
        film0 = previousFilm((uPreviousCameraFromWorld * vec4(world, 1.0)).xyz);
    }
    vec2 previousPixel = (film0 * 0.5 + 0.5) * uResolution;
    outMotion = vec4(previousPixel - gl_FragCoord.xy, 0.0, 1.0);
}
