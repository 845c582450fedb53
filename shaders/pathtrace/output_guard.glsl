// NaN and Inf tested by their bits: isnan()/isinf() may be optimised away by fast-math compilers.
bool isFiniteBits(float x) {
    return (floatBitsToUint(x) & 0x7f800000u) != 0x7f800000u;
}

bool isFiniteBits(vec3 v) {
    return isFiniteBits(v.x) && isFiniteBits(v.y) && isFiniteBits(v.z);
}

// A sample with any non-finite or negative channel is dropped whole (counted as black), so one bad
// path cannot poison the running mean.
vec3 finiteNonNegative(vec3 v) {
    return isFiniteBits(v) && all(greaterThanEqual(v, vec3(0.0))) ? v : vec3(0.0);
}

vec3 finiteOrZero(vec3 v) {
    return isFiniteBits(v) ? v : vec3(0.0);
}
