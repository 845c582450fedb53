// Keeps this frame's normal + depth and object id for the next frame's disocclusion tests.
uniform sampler2D uNormalDepth;
uniform sampler2D uObjectId;

out vec4 outNormalDepth;
out vec4 outObjectId;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    outNormalDepth = texelFetch(uNormalDepth, pixel, 0);
    outObjectId = texelFetch(uObjectId, pixel, 0);
}
