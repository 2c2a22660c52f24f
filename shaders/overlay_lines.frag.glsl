#version 450 core
// One flat colour per draw; alpha < 1 draws the parts hidden behind the scene fainter.
uniform vec4 uColor;

layout(location = 0) out vec4 outColor;

void main() {
    outColor = uColor;
}
