// While nothing moves, the reconstructed frame fades into the running mean of every sample since
// the last change, filtered by the mean denoiser (whose bias falls with its variance): weight n / N
// on the mean, so after N samples the output is the filtered mean itself, which tends to the exact
// mean. A linear fade over 16 samples keeps the error falling frame after frame (docs/DENOISING.md).
// At the first sample the mean is this very frame, which the real-time filters have just
// reconstructed: it gets no weight, so a view that moves (always at its first) never needs it.
uniform sampler2D uReconstructed;
uniform sampler2D uStillMean;
uniform float uStillSamples; // n
uniform float uFadeSamples;  // N

out vec4 outRadiance;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float t = uStillSamples < 2.0 ? 0.0 : min(uStillSamples / uFadeSamples, 1.0);
    vec4 mean = texelFetch(uStillMean, pixel, 0);
    outRadiance = t >= 1.0 ? mean : vec4(mix(texelFetch(uReconstructed, pixel, 0).rgb, mean.rgb, t), mean.a);
}
