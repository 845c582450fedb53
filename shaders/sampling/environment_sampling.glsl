// Importance sampling of an equirectangular environment by its luminance (tables built on the CPU by
// renderer/cpu_twin/env_sampling.h). Orientation as docs/UNITS.md, "Environment": for a unit direction
// d, u = 0.5 + atan2(d.z, d.x) / 2pi from the left edge, v = acos(d.y) / pi from the top row. The
// caller rotates directions into the map's frame; a rotation does not change the pdf.
#ifdef __cplusplus
#pragma once
#endif
#include "common/math.glsl"
#include "sampling/distribution.glsl"

// sin of the angle to +Y (the map's pole), accurate near the poles where sqrt(1 - y^2) is not.
float sinThetaOf(vec3 d) { return sqrt(d.x * d.x + d.z * d.z); }

// v = acos(d.y) / pi, computed as atan2(sin, cos): acos loses float digits near the poles.
vec2 equirectFromDirection(vec3 d) {
    return vec2(0.5f + atan(d.z, d.x) * INV_TWO_PI, atan(sinThetaOf(d), d.y) * INV_PI);
}

vec3 directionFromEquirect(vec2 uv) {
    float phi = (uv.x - 0.5f) * TWO_PI;
    float theta = uv.y * PI;
    float sinTheta = sin(theta);
    return vec3(sinTheta * cos(phi), cos(theta), sinTheta * sin(phi));
}

// The (u, v) square maps onto the sphere with dw = 2 pi^2 sin(theta) du dv.
float solidAngleFromEquirectPdf(float pdfUv, float sinTheta) {
    return sinTheta > 0.0f ? pdfUv / (2.0f * PI * PI * sinTheta) : 0.0f;
}

// `size` is the environment image's width and height (the table is one texel wider and taller).
vec3 sampleEnvironmentDirection(sampler2D cdfTable, ivec2 size, vec2 u, OUT(float) pdf) {
    float pdfUv;
    vec2 uv = samplePiecewiseConstant2D(cdfTable, size, u, pdfUv);
    vec3 d = directionFromEquirect(uv);
    pdf = solidAngleFromEquirectPdf(pdfUv, sinThetaOf(d));
    return d;
}

float environmentDirectionPdf(sampler2D cdfTable, ivec2 size, vec3 d) {
    vec2 uv = equirectFromDirection(d);
    return solidAngleFromEquirectPdf(piecewiseConstant2DPdf(cdfTable, size, uv), sinThetaOf(d));
}
