// Sampling piecewise-constant 1D and 2D distributions from CDF tables stored in a one-channel float
// texture (the C++ twin reads the same layout through its own sampler2D). A row of the table holds
// n + 1 ascending values, cdf[0] = 0 and cdf[n] = 1; bin i covers [i, i + 1) / n of the domain.
#ifdef __cplusplus
#pragma once
#endif
#include "common/compat.glsl"

float cdfAt(sampler2D table, int row, int i) { return texelFetch(table, ivec2(i, row), 0).x; }

// The bin i of `row` with cdf[i] <= u < cdf[i + 1] (never an empty bin); u in [0, 1).
int findCdfInterval(sampler2D table, int row, int n, float u) {
    int lo = 0;
    int hi = n;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (cdfAt(table, row, mid) <= u) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return lo;
}

// A point in [0, 1) drawn from the row's distribution, continuous inside its bin i; pdf per unit
// length.
float samplePiecewiseConstant1D(sampler2D table, int row, int n, float u, OUT(float) pdf, OUT(int) i) {
    i = findCdfInterval(table, row, n, u);
    float c0 = cdfAt(table, row, i);
    float c1 = cdfAt(table, row, i + 1);
    float width = c1 - c0;
    pdf = width * float(n);
    float offset = width > 0.0f ? clamp((u - c0) / width, 0.0f, 1.0f) : 0.5f;
    return min((float(i) + offset) / float(n), 0.99999994f);
}

float piecewiseConstant1DPdf(sampler2D table, int row, int n, float x) {
    int i = clamp(int(x * float(n)), 0, n - 1);
    return (cdfAt(table, row, i + 1) - cdfAt(table, row, i)) * float(n);
}

// 2D table of size.x columns and size.y rows: rows 0..size.y-1 hold each row's conditional CDF over
// columns, row size.y the marginal CDF over rows. Returns (x, y) in [0, 1)^2; pdf per unit area.
vec2 samplePiecewiseConstant2D(sampler2D table, ivec2 size, vec2 u, OUT(float) pdf) {
    float pdfRow;
    int row;
    float y = samplePiecewiseConstant1D(table, size.y, size.y, u.y, pdfRow, row);
    float pdfColumn;
    int column;
    float x = samplePiecewiseConstant1D(table, row, size.x, u.x, pdfColumn, column);
    pdf = pdfRow * pdfColumn;
    return vec2(x, y);
}

float piecewiseConstant2DPdf(sampler2D table, ivec2 size, vec2 p) {
    int row = clamp(int(p.y * float(size.y)), 0, size.y - 1);
    return piecewiseConstant1DPdf(table, size.y, size.y, p.y) * piecewiseConstant1DPdf(table, row, size.x, p.x);
}
