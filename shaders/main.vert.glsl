#version 450 core
// Main pass vertex shader: positions relative to the render origin (large worlds keep their precision).
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

uniform mat4 uViewProjection;
uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform mat3 uUvTransform;

layout(location = 0) out vec3 vWorldPosition;
layout(location = 1) out vec3 vNormal;
layout(location = 2) out vec2 vUv;

void main() {
    vec4 world = uModel * vec4(inPosition, 1.0);
    vWorldPosition = world.xyz;
    vNormal = uNormalMatrix * inNormal;
    vUv = (uUvTransform * vec3(inUv, 1.0)).xy;
    gl_Position = uViewProjection * world;
}
