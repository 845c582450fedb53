// The running mean of the render passes (renderer/passes/render_passes_pass.h): the RENDER_PASSES
// path tracer's targets 3-7, every channel averaged, by the same formula as the beauty's
// (accumulate.frag.glsl), so the passes' means sum to the beauty's mean up to float rounding. A
// pixel adaptive sampling stopped keeps its passes, as the beauty keeps its mean.
#include "adaptive_stop.glsl"

uniform sampler2D uPrevious0;
uniform sampler2D uPrevious1;
uniform sampler2D uPrevious2;
uniform sampler2D uPrevious3;
uniform sampler2D uPrevious4;
uniform sampler2D uSample0;
uniform sampler2D uSample1;
uniform sampler2D uSample2;
uniform sampler2D uSample3;
uniform sampler2D uSample4;
uniform float uSampleCount; // n, counting this sample

out vec4 outPass0;
out vec4 outPass1;
out vec4 outPass2;
out vec4 outPass3;
out vec4 outPass4;

vec4 runningMean(sampler2D previous, sampler2D current, ivec2 pixel) {
    vec4 mean = texelFetch(previous, pixel, 0);
    vec4 value = texelFetch(current, pixel, 0);
    return uSampleCount <= 1.0 ? value : mean + (value - mean) / uSampleCount;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (pixelStopped(pixel)) {
        outPass0 = texelFetch(uPrevious0, pixel, 0);
        outPass1 = texelFetch(uPrevious1, pixel, 0);
        outPass2 = texelFetch(uPrevious2, pixel, 0);
        outPass3 = texelFetch(uPrevious3, pixel, 0);
        outPass4 = texelFetch(uPrevious4, pixel, 0);
        return;
    }
    outPass0 = runningMean(uPrevious0, uSample0, pixel);
    outPass1 = runningMean(uPrevious1, uSample1, pixel);
    outPass2 = runningMean(uPrevious2, uSample2, pixel);
    outPass3 = runningMean(uPrevious3, uSample3, pixel);
    outPass4 = runningMean(uPrevious4, uSample4, pixel);
}
