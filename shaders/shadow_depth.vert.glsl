#version 450 core
// Shadow pass vertex shader. Opaque casters: this stage alone (no fragment shader, so no fragment work).
// ALPHA_MASK: pass the texture coordinate on to shadow_alpha.frag.glsl.
layout(location = 0) in vec3 inPosition;
#ifdef ALPHA_MASK
layout(location = 2) in vec2 inUv;
layout(location = 1) out vec2 vUv;
uniform mat3 uUvTransform;
#endif

uniform mat4 uLightViewProjection;  // light clip from render-origin-relative world
uniform mat4 uModel;                // object to render-origin-relative world

void main() {
#ifdef ALPHA_MASK
    vUv = (uUvTransform * vec3(inUv, 1.0)).xy;
#endif
    gl_Position = uLightViewProjection * (uModel * vec4(inPosition, 1.0));
}
