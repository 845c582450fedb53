// NaN and Inf are tested by their bits (common/math.glsl): isnan()/isinf() may be optimised away.

// A sample with any non-finite or negative channel is dropped whole (counted as black), so one bad
// path cannot poison the running mean.
vec3 finiteNonNegative(vec3 v) {
    return isFiniteVec3(v) && all(greaterThanEqual(v, vec3(0.0))) ? v : vec3(0.0);
}

vec3 finiteOrZero(vec3 v) {
    return isFiniteVec3(v) ? v : vec3(0.0);
}

// The specular part of a sample: 0 outside the SPLIT_LOBES variant, dropped with its radiance, and
// never above it (rounding), so that the diffuse part, radiance - specular, is never negative.
vec3 guardedSpecular(vec3 specular, vec3 guardedRadiance) {
#ifdef SPLIT_LOBES
    return min(finiteNonNegative(specular), guardedRadiance);
#else
    return vec3(0.0);
#endif
}

// The first bounce's reflection distance (lobe_radiance.glsl) in the SPLIT_LOBES variant (0 when
// not finite or negative); elsewhere 1, as before it existed: only SVGF reads it.
float guardedReflectionDistance(float distance) {
#ifdef SPLIT_LOBES
    return isFiniteFloat(distance) && distance > 0.0 ? distance : 0.0;
#else
    return 1.0;
#endif
}
