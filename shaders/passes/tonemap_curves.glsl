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

// AgX (Troy Sobotka), as the published minimal AgX (Benjamin Wrensch): log2 encoding between -12.47
// and +4.03 stops around 0.18 in the AgX inset primaries, a 6th-order fit of the default contrast
// sigmoid, then back to Rec.709 and linearised (the sigmoid's output is gamma-2.2 display code).
vec3 agxContrast(vec3 x) {
    vec3 x2 = x * x;
    vec3 x4 = x2 * x2;
    return 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
}

vec3 agx(vec3 color) {
    const mat3 inset = mat3(0.842479062253094, 0.0423282422610123, 0.0423756549057051, 0.0784335999999992,
                            0.878468636469772, 0.0784336, 0.0792237451477643, 0.0791661274605434, 0.879142973793104);
    const mat3 outset = mat3(1.19687900512017, -0.0528968517574562, -0.0529716355144438, -0.0980208811401368,
                             1.15190312990417, -0.0980434501171241, -0.0990297440797205, -0.0989611768448433, 1.15107367264116);
    const float minEv = -12.47393;
    const float maxEv = 4.026069;
    vec3 v = clamp(log2(max(inset * color, vec3(1.0e-10))), minEv, maxEv);
    v = agxContrast((v - minEv) / (maxEv - minEv));
    return pow(max(outset * v, vec3(0.0)), vec3(2.2));
}

// Reinhard's extended operator (2002, eq. 4) on luminance, white (the luminance that maps to 1) at 4.
vec3 reinhardExtended(vec3 color) {
    const float white = 4.0;
    float l = dot(color, vec3(0.2126, 0.7152, 0.0722));
    if (l <= 0.0) return vec3(0.0);
    return color * ((1.0 + l / (white * white)) / (1.0 + l));
}

// John Hable's filmic curve from Uncharted 2: exposure bias 2, white point 11.2.
vec3 hableCurve(vec3 x) {
    const float A = 0.15, B = 0.50, C = 0.10, D = 0.20, E = 0.02, F = 0.30;
    return (x * (A * x + C * B) + D * E) / (x * (A * x + B) + D * F) - E / F;
}

vec3 hable(vec3 color) { return hableCurve(2.0 * color) / hableCurve(vec3(11.2)); }

// Beyond this every curve is white; above it ACES's squares overflow to inf / inf = NaN (black).
const float kTonemapCeiling = 1.0e6;

vec3 applyTonemapper(vec3 color, int tonemapper) {
    color = min(color, vec3(kTonemapCeiling));
    if (tonemapper == 1) return acesFitted(color);
    if (tonemapper == 2) return pbrNeutral(color);
    if (tonemapper == 3) return agx(color);
    if (tonemapper == 4) return reinhardExtended(color);
    if (tonemapper == 5) return hable(color);
    return color;
}

vec3 encodeSrgb(vec3 linear) {
    vec3 low = linear * 12.92;
    vec3 high = 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055;
    return mix(high, low, lessThanEqual(linear, vec3(0.0031308)));
}
