// glTF MASK materials: baseColor alpha (factor x texture) against alphaCutoff, the one copy the main pass, the
// accuracy G-buffer and the shadow pass share. ALPHA_TEST_MIP0 reads mip 0 only (the shadow pass: mip selection
// there would thin the coverage). BASE_COLOR_TEXTURE: the material has a base-colour texture.
uniform float uAlphaFactor;
uniform float uAlphaCutoff;
#ifdef BASE_COLOR_TEXTURE
uniform sampler2D uBaseColorTexture;
#endif

bool alphaTestPasses(vec2 uv) {
    float alpha = uAlphaFactor;
#ifdef BASE_COLOR_TEXTURE
#ifdef ALPHA_TEST_MIP0
    alpha *= textureLod(uBaseColorTexture, uv, 0.0).a;
#else
    alpha *= texture(uBaseColorTexture, uv).a;
#endif
#endif
    return alpha >= uAlphaCutoff;
}
