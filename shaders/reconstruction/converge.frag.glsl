// While nothing moves, the reconstructed frame fades into the exact running mean of every sample
// since the last change: weight (n / N)^2 on the mean, so after N samples the output is the
// accumulated image itself and the filters leave no bias in a converged picture.
uniform sampler2D uReconstructed;
uniform sampler2D uStillMean;
uniform float uStillSamples; // n
uniform float uFadeSamples;  // N

out vec4 outRadiance;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float t = min(uStillSamples / uFadeSamples, 1.0);
    vec4 mean = texelFetch(uStillMean, pixel, 0);
    outRadiance = t >= 1.0 ? mean : vec4(mix(texelFetch(uReconstructed, pixel, 0).rgb, mean.rgb, t * t), mean.a);
}
