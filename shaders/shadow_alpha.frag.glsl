#version 450 core
// Shadow pass for alpha-tested (glTF MASK) casters. Mip 0 only: mip selection in the shadow pass would thin the
// coverage.
layout(location = 1) in vec2 vUv;
#define ALPHA_TEST_MIP0
#include "common/alpha_test.glsl"

void main() {
    if (!alphaTestPasses(vUv)) discard;
}
