// Multiple importance sampling weights (Veach 1997), one sample from each of two strategies.
#ifdef __cplusplus
#pragma once
#endif
#include "common/compat.glsl"

// Weight of strategy A. Written as a ratio so that huge pdfs do not overflow to inf / inf.
float powerHeuristic(float pdfA, float pdfB) {
    if (pdfA <= 0.0f) return 0.0f;
    float r = pdfB / pdfA;
    return 1.0f / (1.0f + r * r);
}
