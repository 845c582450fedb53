// Bilinear reads with texelFetch (the filtering is the shader's, the same on every driver), clamped
// to the image's edge.
vec4 fetchClamped(sampler2D image, ivec2 texel) {
    return texelFetch(image, clamp(texel, ivec2(0), textureSize(image, 0) - 1), 0);
}

// `position` in texels of `image` (texel centres at +0.5).
vec4 bilinear(sampler2D image, vec2 position) {
    vec2 p = position - 0.5;
    ivec2 base = ivec2(floor(p));
    vec2 f = p - vec2(base);
    return mix(mix(fetchClamped(image, base), fetchClamped(image, base + ivec2(1, 0)), f.x),
               mix(fetchClamped(image, base + ivec2(0, 1)), fetchClamped(image, base + ivec2(1, 1)), f.x), f.y);
}
