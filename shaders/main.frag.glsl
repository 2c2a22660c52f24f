#version 450 core
// Main pass: projects the pixel into light space and compares depths. The renderer prepends #defines:
//   filter  FILTER_POINT | FILTER_HARDWARE_2X2 | FILTER_PCF (PCF_KERNEL n) | FILTER_POISSON (POISSON_TAPS, POISSON_DISK)
//           (renderer/shading/filter_taps.cpp: the one list of taps, shared with the pixel probe)
//   view    VIEW_LIT | VIEW_SHADOW | VIEW_LIGHT_DEPTH
//   LIGHT_PERSPECTIVE (spot light), NORMAL_OFFSET, ALPHA_MASK (+ BASE_COLOR_TEXTURE)
// Only the features a frame uses are compiled in; kernel sizes are compile-time constants.
layout(location = 0) in vec3 vWorldPosition;
layout(location = 1) in vec3 vNormal;
layout(location = 2) in vec2 vUv;
layout(location = 0) out vec4 outColor;

uniform sampler2DShadow uShadowMap;
uniform mat4 uLightViewProjection;
uniform vec3 uLightDirection;    // unit, the direction light travels
uniform vec3 uLightPosition;     // spot: render-origin-relative
uniform vec3 uCameraPosition;    // render-origin-relative
uniform vec2 uShadowTexel;       // 1 / shadow map size
uniform vec3 uBaseColor;
uniform float uLightIntensity;
uniform float uAmbient;
uniform vec2 uLightDepthRange;   // near, far (for VIEW_LIGHT_DEPTH)
#ifdef NORMAL_OFFSET
uniform float uNormalOffsetTexels;
uniform float uTexelWorldSize;   // directional: world size of a texel; spot: at unit distance from the light
#endif
#ifdef LIGHT_PERSPECTIVE
uniform float uSpotCosHalfAngle;
#endif
#ifdef ALPHA_MASK
uniform float uAlphaFactor;
uniform float uAlphaCutoff;
#ifdef BASE_COLOR_TEXTURE
uniform sampler2D uBaseColorTexture;
#endif
#endif

#ifdef FILTER_POISSON
// POISSON_TAPS and POISSON_DISK come from renderer/shading/filter_taps.cpp (the probe reads the same taps).
const vec2 POISSON_DISK_TAPS[POISSON_TAPS] = vec2[](POISSON_DISK);
uniform float uPoissonRadiusTexels;
#endif

vec3 toLightTexture(vec3 worldPosition) {
    vec4 clip = uLightViewProjection * vec4(worldPosition, 1.0);
    vec3 ndc = clip.xyz / clip.w;
    return ndc * 0.5 + 0.5;
}

// Fraction of light reaching the point, 1 = lit. Receivers beyond the far plane compare as if on it.
float shadowFactor(vec3 lightTex) {
    float ref = min(lightTex.z, 1.0);
#if defined(FILTER_POINT) || defined(FILTER_HARDWARE_2X2)
    return texture(uShadowMap, vec3(lightTex.xy, ref));
#elif defined(FILTER_PCF)
    const int R = PCF_KERNEL / 2;
    float sum = 0.0;
    for (int y = -R; y <= R; ++y)
        for (int x = -R; x <= R; ++x)
            sum += texture(uShadowMap, vec3(lightTex.xy + vec2(x, y) * uShadowTexel, ref));
    return sum / float(PCF_KERNEL * PCF_KERNEL);
#elif defined(FILTER_POISSON)
    float sum = 0.0;
    for (int i = 0; i < POISSON_TAPS; ++i)
        sum += texture(uShadowMap, vec3(lightTex.xy + POISSON_DISK_TAPS[i] * uPoissonRadiusTexels * uShadowTexel, ref));
    return sum / float(POISSON_TAPS);
#endif
}

void main() {
#ifdef ALPHA_MASK
    float alpha = uAlphaFactor;
#ifdef BASE_COLOR_TEXTURE
    alpha *= texture(uBaseColorTexture, vUv).a;
#endif
    if (alpha < uAlphaCutoff) discard;
#endif
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;  // two-sided lighting: broken windings and double-sided materials shade right
#ifdef LIGHT_PERSPECTIVE
    vec3 toLight = uLightPosition - vWorldPosition;
    float lightDistance = length(toLight);
    vec3 l = toLight / max(lightDistance, 1e-20);
    float inCone = step(uSpotCosHalfAngle, dot(-l, uLightDirection));
#else
    vec3 l = -uLightDirection;
    float inCone = 1.0;
#endif

    vec3 lookup = vWorldPosition;
#ifdef NORMAL_OFFSET
    // Move the lookup along the normal by a fixed number of texels' world size (Holbert's normal offset).
#ifdef LIGHT_PERSPECTIVE
    float texelWorld = uTexelWorldSize * dot(vWorldPosition - uLightPosition, uLightDirection);
#else
    float texelWorld = uTexelWorldSize;
#endif
    lookup += n * (uNormalOffsetTexels * texelWorld);
#endif
    vec3 lightTex = toLightTexture(lookup);
    float shadow = shadowFactor(lightTex) * inCone;

#if defined(VIEW_SHADOW)
    outColor = vec4(vec3(shadow), 1.0);
#elif defined(VIEW_LIGHT_DEPTH)
#ifdef LIGHT_PERSPECTIVE
    // Linear distance along the light axis, so the picture is not all white.
    float viewDepth = dot(vWorldPosition - uLightPosition, uLightDirection);
    float depth = (viewDepth - uLightDepthRange.x) / (uLightDepthRange.y - uLightDepthRange.x);
#else
    float depth = toLightTexture(vWorldPosition).z;
#endif
    outColor = vec4(vec3(clamp(depth, 0.0, 1.0)), 1.0);
#else
    float nDotL = max(dot(n, l), 0.0);
    vec3 v = normalize(uCameraPosition - vWorldPosition);
    vec3 h = normalize(l + v);
    float specular = nDotL > 0.0 ? pow(max(dot(n, h), 0.0), 48.0) * 0.25 : 0.0;
    float direct = uLightIntensity * shadow;
    vec3 color = uBaseColor * (uAmbient + (1.0 - uAmbient) * nDotL * direct) + vec3(specular * direct);
    outColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
#endif
}
