#version 450 core
// The depth passes' vertex shader (shadow pass, depth-bounds prepass, the bare draw). Opaque casters: this stage
// alone (no fragment shader, so no fragment work). ALPHA_MASK: pass the texture coordinate on to
// shadow_alpha.frag.glsl. Each draw's model matrix comes from the scene's transform buffer, picked by the draw's
// index (an instanced attribute a multi-draw command's baseInstance selects: frame/gpu_scene.h), so a whole view's
// casters are a few multi-draw calls with no uniform between draws.
layout(location = 0) in vec3 inPosition;
layout(location = 3) in uint inDrawIndex;  // kDrawIndexAttribute
#ifdef ALPHA_MASK
layout(location = 2) in vec2 inUv;
layout(location = 1) out vec2 vUv;
uniform mat3 uUvTransform;
#endif

uniform mat4 uLightViewProjection;  // light clip from render-origin-relative world
// Object to render-origin-relative world, per draw (bound at kDrawTransformsBinding by bindDrawTransformsBlock).
layout(std430) readonly buffer DrawTransforms { mat4 drawModel[]; };

void main() {
#ifdef ALPHA_MASK
    vUv = (uUvTransform * vec3(inUv, 1.0)).xy;
#endif
    gl_Position = uLightViewProjection * (drawModel[inDrawIndex] * vec4(inPosition, 1.0));
}
