#version 450 core
// Overlay lines (the light's volume) in the main view: positions relative to the render origin, like the scene.
layout(location = 0) in vec3 inPosition;

uniform mat4 uViewProjection;

void main() {
    gl_Position = uViewProjection * vec4(inPosition, 1.0);
}
