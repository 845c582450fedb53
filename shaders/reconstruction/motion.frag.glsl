// Motion vectors: where each pixel's surface was in the previous frame, in pixels (previous minus
// current). Camera motion from depth and the previous camera; object motion from the previous
// world transform of the instance the pixel sees (by object id). Misses move with the camera's
// rotation only (the environment is at infinity).
// zw: virtual motion, for SVGF's specular lobe. A reflection in a mirror moves like the reflected
// point's virtual image, which lies behind the mirror along the camera ray, at the primary hit plus
// the reflected ray's length (the path tracer's reflection distance, G-buffer specular radiance a).
// That image is projected with the previous camera like any point. Exact for a still planar mirror.
// A curved mirror forms its image nearer (convex) or farther (concave): the distance is corrected by
// the thin-mirror equation, 1/image = 1/distance + 2 curvature (as NRD does), with the curvature
// measured in screen space from the G-buffer's normals and depths (the path tracer knows none for
// analytic shapes). That is paraxial: off-axis, at grazing angles and near a concave mirror's focus
// (where the image flips; there zw = xy) it is an approximation, so SVGF still tests what it fetches.
// Where the pixel's object moved, or no sample near it saw a reflection, zw = xy (surface motion).
// Meaningful only where the G-buffer carries the lobe split (SVGF's configurations; elsewhere the
// distance reads 1 and nothing reads zw).
#include "common/sorted_ids.glsl"

uniform sampler2D uNormalDepth;
uniform sampler2D uObjectId;
uniform sampler2D uSpecularRadiance; // a: reflection distance, 0 where the sample saw no reflection
uniform vec2 uResolution;
uniform mat4 uWorldFromCamera;
uniform vec2 uHalfExtent;
uniform int uOrthographic;
uniform mat4 uPreviousCameraFromWorld;
uniform vec2 uPreviousHalfExtent;
uniform int uPreviousOrthographic;

// The instances that moved since the previous frame, sorted by id, MOVED_TEXELS texels each: the
// id in the first's x, then the columns of previousFromCurrent. A binary search finds an id, so any
// number of moving instances gets its own motion (motion_pass.cpp).
const int MOVED_TEXELS = 5;
uniform samplerBuffer uMoved;
uniform int uMovedCount;

out vec4 outMotion;

// The record of `id` among the moved instances, or -1.
int movedIndex(float id) { return sortedIdIndex(uMoved, uMovedCount, MOVED_TEXELS, id); }

bool moved(float id) { return movedIndex(id) >= 0; }

vec3 movedToPrevious(vec3 world, float id) {
    int i = movedIndex(id);
    if (i < 0) return world;
    int first = i * MOVED_TEXELS + 1;
    mat4 previousFromCurrent = mat4(texelFetch(uMoved, first), texelFetch(uMoved, first + 1), texelFetch(uMoved, first + 2),
                                    texelFetch(uMoved, first + 3));
    return (previousFromCurrent * vec4(world, 1.0)).xyz;
}

vec2 previousFilm(vec3 previousCamera) {
    if (uPreviousOrthographic != 0) return previousCamera.xy / uPreviousHalfExtent;
    return previousCamera.xy / max(-previousCamera.z, 1.0e-6) / uPreviousHalfExtent;
}

const float REFLECTION_AT_INFINITY = 1.0e20; // as the path tracer writes it (lobe_radiance.glsl)

// The camera ray's direction through pixel p, not normalised (z = -1), and its point at `depth`
// along the view axis, in camera space.
vec3 rayDirection(vec2 p) {
    vec2 film = p / uResolution * 2.0 - 1.0;
    return uOrthographic != 0 ? vec3(0.0, 0.0, -1.0) : vec3(film * uHalfExtent, -1.0);
}

vec3 pointAt(vec2 p, float depth) {
    vec2 film = p / uResolution * 2.0 - 1.0;
    return uOrthographic != 0 ? vec3(film * uHalfExtent, -depth) : rayDirection(p) * depth;
}

// World-space position of the surface at pixel p (depth along the view axis).
vec3 worldAt(ivec2 p, float depth) { return (uWorldFromCamera * vec4(pointAt(vec2(p) + 0.5, depth), 1.0)).xyz; }

// Signed curvature (1/m, positive where the surface bulges towards the camera) from how the normal
// turns towards the 4 neighbours on the same object: dot(dn, dp) / |dp|^2, exactly 1/R on a sphere.
float screenCurvature(ivec2 pixel, float id, vec4 normalDepth) {
    ivec2 size = ivec2(uResolution);
    vec3 p0 = worldAt(pixel, normalDepth.w);
    float sum = 0.0;
    int count = 0;
    for (int k = 0; k < 4; ++k) {
        ivec2 q = pixel + (k == 0 ? ivec2(1, 0) : k == 1 ? ivec2(-1, 0) : k == 2 ? ivec2(0, 1) : ivec2(0, -1));
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
        vec4 nd = texelFetch(uNormalDepth, q, 0);
        if (nd.w < 0.0 || abs(texelFetch(uObjectId, q, 0).x - id) > 0.5) continue;
        vec3 dp = worldAt(q, nd.w) - p0;
        float dp2 = dot(dp, dp);
        if (!(dp2 > 0.0)) continue;
        sum += dot(normalize(nd.xyz) - normalize(normalDepth.xyz), dp) / dp2;
        ++count;
    }
    return count > 0 ? sum / float(count) : 0.0;
}

// The reflected image's distance behind a mirror of signed curvature k for an object at distance d
// (thin-mirror equation); 0 near a concave mirror's focus and beyond (the image flips: no estimate).
float virtualImageDistance(float d, float k) {
    float inverse = 1.0 / d + 2.0 * k;
    return inverse > 0.1 / d ? 1.0 / inverse : 0.0;
}

// Reflection distance at `pixel`; where its sample saw none, from the samples of the same object in
// the 5x5 neighbourhood that did (a dielectric layer's reflection is sampled by few pixels), averaged
// as the inverse distance to the virtual image (parallax's measure; an image at infinity counts 0).
// 0: none nearby.
float reflectionDistance(ivec2 pixel, float id, float rayLength) {
    float own = texelFetch(uSpecularRadiance, pixel, 0).a;
    if (own > 0.0) return own;
    ivec2 size = ivec2(uResolution);
    float inverseSum = 0.0;
    int count = 0;
    for (int y = -2; y <= 2; ++y)
        for (int x = -2; x <= 2; ++x) {
            ivec2 q = pixel + ivec2(x, y);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
            float d = texelFetch(uSpecularRadiance, q, 0).a;
            float depth = texelFetch(uNormalDepth, q, 0).w;
            if (d <= 0.0 || depth < 0.0 || abs(texelFetch(uObjectId, q, 0).x - id) > 0.5) continue;
            inverseSum += 1.0 / (depth * length(rayDirection(vec2(q) + 0.5)) + d);
            ++count;
        }
    if (count == 0) return 0.0;
    return inverseSum > 0.0 ? max(float(count) / inverseSum - rayLength, 0.0) : REFLECTION_AT_INFINITY;
}

vec2 previousPixelOf(vec3 previousCamera) { return (previousFilm(previousCamera) * 0.5 + 0.5) * uResolution; }

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(uNormalDepth, pixel, 0).w;
    vec3 direction = rayDirection(gl_FragCoord.xy);
    vec2 previousPixel;
    vec2 virtualPixel;
    if (depth < 0.0) {
        vec3 world = mat3(uWorldFromCamera) * direction;
        vec3 previous = mat3(uPreviousCameraFromWorld) * world;
        vec2 film0 = previous.z < 0.0 ? previous.xy / -previous.z / uPreviousHalfExtent : vec2(1.0e4);
        previousPixel = virtualPixel = (film0 * 0.5 + 0.5) * uResolution;
    } else {
        float id = texelFetch(uObjectId, pixel, 0).x;
        vec3 local = pointAt(gl_FragCoord.xy, depth);
        vec3 world = movedToPrevious((uWorldFromCamera * vec4(local, 1.0)).xyz, id);
        previousPixel = previousPixelOf((uPreviousCameraFromWorld * vec4(world, 1.0)).xyz);
        float d = moved(id) ? 0.0 : reflectionDistance(pixel, id, length(local));
        if (d > 0.0) d = virtualImageDistance(d, screenCurvature(pixel, id, texelFetch(uNormalDepth, pixel, 0)));
        vec3 image = local + d * normalize(direction);
        virtualPixel = d > 0.0 ? previousPixelOf((uPreviousCameraFromWorld * (uWorldFromCamera * vec4(image, 1.0))).xyz) : previousPixel;
    }
    outMotion = vec4(previousPixel - gl_FragCoord.xy, virtualPixel - gl_FragCoord.xy);
}
