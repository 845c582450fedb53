// Raster preview: scene geometry transformed to clip space, world-space normal for shading.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uClipFromWorld;
uniform mat4 uWorldFromLocal;
uniform mat3 uNormalFromLocal; // inverse transpose of uWorldFromLocal's upper 3x3

out vec3 vWorldPosition;
out vec3 vWorldNormal;

void main() {
    vec4 world = uWorldFromLocal * vec4(aPosition, 1.0);
    vWorldPosition = world.xyz;
    vWorldNormal = uNormalFromLocal * aNormal;
    gl_Position = uClipFromWorld * world;
}
