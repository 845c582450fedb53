// Adaptive sampling's per-pixel test (renderer/passes/adaptive_sampling.h): converged when the
// standard error of the mean, summed over R, G and B, is below the threshold times the square root
// of the mean's R + G + B (Cycles' normalisation, so dark pixels need a smaller absolute error).
// n >= 2 samples; NaN or Inf: not converged.
bool converged(vec3 mean, vec3 meanSquared, float n, float threshold) {
    // The sample variance n/(n-1) (E[x^2] - E[x]^2), over n: the variance of the mean.
    vec3 standardError = sqrt(max(meanSquared - mean * mean, vec3(0.0)) / (n - 1.0));
    float error = (standardError.r + standardError.g + standardError.b) / (1.0e-4 + sqrt(max(mean.r + mean.g + mean.b, 0.0)));
    return error < threshold;
}
