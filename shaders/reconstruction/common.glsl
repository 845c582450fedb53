// Helpers shared by the reconstruction stages: luminance, YCoCg, the history guard, the
// disocclusion test that compares this frame's surface with the previous frame's, and the bilinear
// taps of a reprojection that pass it.

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

vec3 yCoCgFromRgb(vec3 c) {
    return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b, -0.25 * c.r + 0.5 * c.g - 0.25 * c.b);
}

vec3 rgbFromYCoCg(vec3 c) { return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

// NaN, Inf and negative values never enter history (they would persist for many frames).
vec3 finiteRadiance(vec3 c) {
    bvec3 bad = bvec3(isnan(c.x) || isinf(c.x), isnan(c.y) || isinf(c.y), isnan(c.z) || isinf(c.z));
    return max(mix(c, vec3(0.0), bad), vec3(0.0));
}

// Reversible tone curve for blending in a perceptual space (Karis 2014): a firefly's weight is
// bounded by 1 instead of by its energy.
vec3 perceptualFromLinear(vec3 c) { return c / (1.0 + luminance(c)); }
vec3 linearFromPerceptual(vec3 c) { return c / max(1.0 - luminance(c), 1.0e-4); }

// Whether the previous frame saw the same surface at its reprojected position: same object id,
// depth within a relative tolerance, normals within ~35 degrees. Misses (depth < 0) match misses.
bool sameSurface(vec4 normalDepth, float id, vec4 previousNormalDepth, float previousId) {
    if (abs(id - previousId) > 0.5) return false;
    if (normalDepth.w < 0.0 || previousNormalDepth.w < 0.0) return normalDepth.w < 0.0 && previousNormalDepth.w < 0.0;
    if (abs(normalDepth.w - previousNormalDepth.w) > 0.1 * max(normalDepth.w, 1.0e-3)) return false;
    return dot(normalDepth.xyz, previousNormalDepth.xyz) > 0.8 * length(normalDepth.xyz) * length(previousNormalDepth.xyz);
}

bool insideImage(vec2 position, vec2 size) {
    return all(greaterThanEqual(position, vec2(0.0))) && all(lessThan(position, size));
}

// The previous frame's four bilinear taps around `previous` (pixel coordinates) with their weights;
// a tap outside the image or on another surface (sameSurface) has weight 0, so a disoccluded pixel
// gets no history. SVGF's and anti-lag's reprojections both use it.
void sameSurfaceTaps(vec2 previous, ivec2 size, vec4 normalDepth, float id, sampler2D previousNormalDepth,
                     sampler2D previousObjectId, out ivec2 taps[4], out float weights[4]) {
    vec2 base = floor(previous - 0.5);
    vec2 f = previous - 0.5 - base;
    for (int k = 0; k < 4; ++k) {
        int i = k & 1, j = k >> 1;
        ivec2 q = ivec2(base) + ivec2(i, j);
        taps[k] = q;
        weights[k] = 0.0;
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
        if (!sameSurface(normalDepth, id, texelFetch(previousNormalDepth, q, 0), texelFetch(previousObjectId, q, 0).x)) continue;
        weights[k] = (i == 1 ? f.x : 1.0 - f.x) * (j == 1 ? f.y : 1.0 - f.y);
    }
}
