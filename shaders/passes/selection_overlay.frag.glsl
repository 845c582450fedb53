// The selection outline's last stage (renderer/passes/selection_outline_pass.h): its line, drawn
// at the output's size, copied over the shown image where it is drawn (alpha 1).
uniform sampler2D uLine;

out vec4 outColour;

void main() {
    vec4 line = texelFetch(uLine, ivec2(gl_FragCoord.xy), 0);
    if (line.a < 0.5) discard;
    outColour = line;
}
