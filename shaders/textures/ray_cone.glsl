// Texture level of detail by ray cones (Akenine-Moller et al., "Texture Level of Detail Strategies
// for Real-Time Ray Tracing", Ray Tracing Gems ch. 20). A cone has a width at the ray origin and a
// spread angle. Camera rays start with the pixel's footprint (perspective: the angle one pixel
// subtends; orthographic: the pixel's width); each hit widens the cone by spread * t, and each
// bounce adds to the spread: the surface's curvature (estimated from how the vertex normals turn
// along the triangle's edges) and, for rough lobes, the lobe's width (2 alpha, alpha = roughness^2).
struct RayCone {
    float width;  // metres at the ray origin
    float spread; // radians
};

float coneWidthAt(RayCone c, float t) { return abs(c.width + c.spread * t); }

// The cone after a bounce at distance t: width there, spread widened by curvature and roughness.
RayCone bounceCone(RayCone c, float t, float curvature, float roughness) {
    float width = coneWidthAt(c, t);
    float alpha = roughness * roughness;
    return RayCone(width, c.spread + 2.0 * curvature * width + 2.0 * alpha);
}

// The texture-independent part of the LOD (lambda in the paper): log2 of the footprint's width
// over the triangle's texel density. uvArea and worldArea are twice the triangle's areas (their
// ratio is what counts); add 0.5 log2(w h) of a texture and its transform's bias.
float coneLod(float width, float cosine, float uvArea, float worldArea) {
    return log2(width / max(abs(cosine), 1e-4)) + 0.5 * log2(max(uvArea, 1e-30) / max(worldArea, 1e-30));
}
