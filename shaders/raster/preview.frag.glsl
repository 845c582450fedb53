// Raster preview shading: a headlight on a flat colour (solid view; two-sided, so open meshes read
// well), or the flat colour alone (wireframe lines). Output is display-referred already: the
// preview is not tonemapped.
in vec3 vWorldPosition;
in vec3 vWorldNormal;

uniform vec3 uEye;
uniform vec3 uColor;
uniform int uShaded;

out vec4 fColor;

void main() {
    if (uShaded == 0) {
        fColor = vec4(uColor, 1.0);
        return;
    }
    vec3 n = normalize(vWorldNormal);
    vec3 toEye = normalize(uEye - vWorldPosition);
    float headlight = abs(dot(n, toEye));
    fColor = vec4(uColor * (0.25 + 0.75 * headlight), 1.0);
}
