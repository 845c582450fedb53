// The selection outline's first stage (renderer/passes/selection_outline_pass.h), at the shown
// image's size: 1 where the pixel's first hit is one of the outlined objects, else 0.
#include "common/sorted_ids.glsl"

uniform sampler2D uObjectId; // the G-buffer's: the first hit's node id, 0 where nothing is hit
uniform samplerBuffer uIds;  // the outlined node ids, sorted
uniform int uIdCount;

out vec4 outMask;

void main() {
    float id = texelFetch(uObjectId, ivec2(gl_FragCoord.xy), 0).x;
    outMask = vec4(id > 0.0 && sortedIdIndex(uIds, uIdCount, 1, id) >= 0 ? 1.0 : 0.0);
}
