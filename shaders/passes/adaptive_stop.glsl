// Whether adaptive sampling stopped a pixel (renderer/passes/adaptive_sampling.h): its stop depth
// is below 1. The accumulations keep a stopped pixel's mean as it is. Without ADAPTIVE_STOPS no
// pixel is stopped and nothing is read.
#ifdef ADAPTIVE_STOPS
uniform sampler2D uStopDepth;
bool pixelStopped(ivec2 pixel) { return texelFetch(uStopDepth, pixel, 0).r < 1.0; }
#else
bool pixelStopped(ivec2 pixel) { return false; }
#endif
