// Adaptive sampling, second stage (renderer/passes/adaptive_sampling.h), drawn into the
// accumulation's other target: a pixel of a converged tile writes the depth that stops it,
// n / 2^24, and copies its mean there, so both targets of the ping-pong hold it from now on;
// pixels of tiles still noisy discard and keep sampling. Stopped pixels fail the depth test here too
// (GL_LESS against their earlier, smaller stop), so a stop never moves.
uniform sampler2D uTileConverged;
uniform sampler2D uMean0;
uniform sampler2D uMean1;
uniform sampler2D uMean2;
uniform sampler2D uMean3;
uniform sampler2D uMean4;
uniform sampler2D uMean5;
uniform sampler2D uMean6;
uniform sampler2D uMean7; // the mean squared radiance
uniform float uSampleCount;

out vec4 out0;
out vec4 out1;
out vec4 out2;
out vec4 out3;
out vec4 out4;
out vec4 out5;
out vec4 out6;
out vec4 out7;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (texelFetch(uTileConverged, pixel / 8, 0).r < 0.5) discard;
    out0 = texelFetch(uMean0, pixel, 0);
    out1 = texelFetch(uMean1, pixel, 0);
    out2 = texelFetch(uMean2, pixel, 0);
    out3 = texelFetch(uMean3, pixel, 0);
    out4 = texelFetch(uMean4, pixel, 0);
    out5 = texelFetch(uMean5, pixel, 0);
    out6 = texelFetch(uMean6, pixel, 0);
    out7 = texelFetch(uMean7, pixel, 0);
    gl_FragDepth = uSampleCount / 16777216.0;
}
