// Tone curves on linear Rec.709 radiance, and the sRGB transfer function.

// Stephen Hill's fit of the ACES RRT + ODT (sRGB primaries in and out).
vec3 acesFitted(vec3 color) {
    const mat3 inputMatrix = mat3(0.59719, 0.07600, 0.02840, 0.35458, 0.90834, 0.13383, 0.04823, 0.01566, 0.83777);
    const mat3 outputMatrix = mat3(1.60475, -0.10208, -0.00327, -0.53108, 1.10813, -0.07276, -0.07367, -0.00605, 1.07602);
    vec3 v = inputMatrix * color;
    vec3 a = v * (v + 0.0245786) - 0.000090537;
    vec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
    return outputMatrix * (a / b);
}

// Khronos PBR Neutral (reference implementation of the published specification).
vec3 pbrNeutral(vec3 color) {
    const float startCompression = 0.8 - 0.04;
    const float desaturation = 0.15;
    float x = min(color.r, min(color.g, color.b));
    float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    color -= offset;
    float peak = max(color.r, max(color.g, color.b));
    if (peak < startCompression) return color;
    const float d = 1.0 - startCompression;
    float newPeak = 1.0 - d * d / (peak + d - startCompression);
    color *= newPeak / peak;
    float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return mix(color, vec3(newPeak), g);
}

// Beyond this every curve is white; above it ACES's squares overflow to inf / inf = NaN (black).
const float kTonemapCeiling = 1.0e6;

vec3 applyTonemapper(vec3 color, int tonemapper) {
    color = min(color, vec3(kTonemapCeiling));
    if (tonemapper == 1) return acesFitted(color);
    if (tonemapper == 2) return pbrNeutral(color);
    return color;
}

vec3 encodeSrgb(vec3 linear) {
    vec3 low = linear * 12.92;
    vec3 high = 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055;
    return mix(high, low, lessThanEqual(linear, vec3(0.0031308)));
}
