#version 450 core
// Accuracy G-buffer: which draw and which triangle the main pass shows at each pixel. Paired with main.vert.glsl
// and the main pass's depth state, draw order and alpha test, so it covers exactly the main pass's pixels; the CPU
// rebuilds the exact point and normal from these ids. ALPHA_MASK (+ BASE_COLOR_TEXTURE) as in main.frag.glsl.
layout(location = 2) in vec2 vUv;
layout(location = 0) out uvec2 outIds;

uniform uint uDrawId;
#ifdef ALPHA_MASK
#include "common/alpha_test.glsl"
#endif

void main() {
#ifdef ALPHA_MASK
    if (!alphaTestPasses(vUv)) discard;
#endif
    outIds = uvec2(uDrawId + 1u, uint(gl_PrimitiveID));
}
