// Shared constants of the path tracer.
const float PI = 3.14159265358979;
const float TWO_PI = 6.28318530717959;
const float INV_PI = 0.318309886183791;
const float RAY_MAX = 3.0e38;
