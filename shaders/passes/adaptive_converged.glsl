// Adaptive sampling's per-pixel measures (renderer/passes/adaptive_sampling.h), from a pixel's mean
// and mean square after n >= 2 samples.

// The sample variance n/(n-1) (E[x^2] - E[x]^2) of each channel.
vec3 sampleVariance(vec3 mean, vec3 meanSquared, float n) {
    return max(meanSquared - mean * mean, vec3(0.0)) * (n / (n - 1.0));
}

// AdaptiveGoal::Even's test: converged when the standard error of the mean, summed over R, G and B,
// is below the threshold times the square root of the mean's R + G + B (Cycles' normalisation, so
// dark pixels need a smaller absolute error). NaN or Inf: not converged.
bool converged(vec3 mean, vec3 meanSquared, float n, float threshold) {
    // The sample variance over n, the variance of the mean, in one division: not through
    // sampleVariance, whose extra rounding could move a stop and change Even's renders.
    vec3 standardError = sqrt(max(meanSquared - mean * mean, vec3(0.0)) / (n - 1.0));
    float error = (standardError.r + standardError.g + standardError.b) / (1.0e-4 + sqrt(max(mean.r + mean.g + mean.b, 0.0)));
    return error < threshold;
}

// AdaptiveGoal::Mean's measure: the variance of one sample in relMSE's normalisation (docs/CLI.md,
// glint bench: the squared error over the reference's square + 0.01), averaged over R, G and B, with
// the mean standing in for the reference.
float relativeVariance(vec3 mean, vec3 meanSquared, float n) {
    vec3 relative = sampleVariance(mean, meanSquared, n) / (mean * mean + 0.01);
    return (relative.r + relative.g + relative.b) / 3.0;
}
