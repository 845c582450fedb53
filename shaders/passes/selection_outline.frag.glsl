// The selection outline's second stage (renderer/passes/selection_outline_pass.h), at the output's
// size: an output pixel whose mask differs from that of a neighbour one output pixel away takes the
// outline's colour, so the line is two pixels wide at any scale, one on each side of the edge.
// Everything else is transparent (alpha 0).
uniform sampler2D uMask;       // at the image's size
uniform vec2 uImageFromOutput; // image pixels per output pixel
uniform vec4 uColour;

out vec4 outColour;

float maskAt(vec2 outputPixel) {
    ivec2 size = textureSize(uMask, 0);
    ivec2 pixel = clamp(ivec2(outputPixel * uImageFromOutput), ivec2(0), size - 1);
    return texelFetch(uMask, pixel, 0).r;
}

void main() {
    vec2 here = gl_FragCoord.xy;
    float inside = maskAt(here);
    float edge = max(max(abs(inside - maskAt(here + vec2(1.0, 0.0))), abs(inside - maskAt(here - vec2(1.0, 0.0)))),
                     max(abs(inside - maskAt(here + vec2(0.0, 1.0))), abs(inside - maskAt(here - vec2(0.0, 1.0)))));
    outColour = edge < 0.5 ? vec4(0.0) : uColour;
}
