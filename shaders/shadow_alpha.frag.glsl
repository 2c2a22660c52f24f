#version 450 core
// Shadow pass for alpha-tested (glTF MASK) casters: baseColor alpha (factor x texture) against alphaCutoff.
// Mip 0 only: mip selection in the shadow pass would thin the coverage.
layout(location = 1) in vec2 vUv;
uniform float uAlphaFactor;
uniform float uAlphaCutoff;
#ifdef BASE_COLOR_TEXTURE
uniform sampler2D uBaseColor;
#endif

void main() {
    float alpha = uAlphaFactor;
#ifdef BASE_COLOR_TEXTURE
    alpha *= textureLod(uBaseColor, vUv, 0.0).a;
#endif
    if (alpha < uAlphaCutoff) discard;
}
