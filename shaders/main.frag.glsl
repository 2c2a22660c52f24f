#version 450 core
// Main pass: for each light, projects the pixel into that light's shadow view and compares depths. The renderer
// prepends #defines (renderer/shading/shader_variants.cpp):
//   light set  DIR_LIGHTS, DIR_CASTERS, SPOT_LIGHTS, SPOT_CASTERS, POINT_LIGHTS, POINT_CASTERS: how many lights of
//              each kind, casters first (uLights holds them in that order: directional, spot, point)
//   maps       MAP_ARRAYS_2D (sampler2DArrayShadow, directional and spot views), MAP_ARRAYS_CUBE
//              (samplerCubeArrayShadow, point lights: per-face perspective depth); moments techniques: sampler2DArray
//              and samplerCubeArray of moments
//   filter     FILTER_TAPS and FILTER_GRID_RADIUS or FILTER_TAP_OFFSETS (texels; scaled by uFilterScale): the filter
//              technique's taps; or MOMENT_TECHNIQUE: moments maps read through the technique's own file (MOMENT_MIPS:
//              at the level of the pixel's footprint)
//              (renderer/shading/filter_taps.cpp, shared with the pixel probe)
//   view       VIEW_LIT | VIEW_SHADOW | VIEW_LIGHT_DEPTH | VIEW_CASCADES | VIEW_TEXEL_DENSITY; NORMAL_OFFSET, ALPHA_MASK (+ BASE_COLOR_TEXTURE)
//   CASCADES   how many cascades the frame's cascaded directional lights have together (uCascades' length)
//   RECEIVER_PLANE  some directional / spot caster uses receiver-plane depth bias (its LightData flag says which);
//              with FILTER_NEAREST (taps that read one texel) the plane is taken at the texel's centre
// Only the lights, kinds and features a frame uses are compiled in; loop counts are compile-time constants.
// The light block, the 2D and cube lookups (with the filter's taps and the cube-face selection) and the alpha test
// are included files (shaders/shadow/, shaders/common/), each written once.
layout(location = 0) in vec3 vWorldPosition;
layout(location = 1) in vec3 vNormal;
layout(location = 2) in vec2 vUv;
layout(location = 0) out vec4 outColor;

#define LIGHT_COUNT (DIR_LIGHTS + SPOT_LIGHTS + POINT_LIGHTS)
#define SPOT_BEGIN DIR_LIGHTS
#define POINT_BEGIN (DIR_LIGHTS + SPOT_LIGHTS)

#include "shadow/light_data.glsl"
#include "shadow/lookup.glsl"
#include "shadow/cascades.glsl"

#if LIGHT_COUNT > 0
layout(std140, binding = 0) uniform Lights { LightData uLights[LIGHT_COUNT]; };
#endif

uniform vec3 uCameraPosition;  // render-origin-relative
uniform vec3 uCameraForward;   // unit viewing direction: the texel density measures depth along it
// The camera the cascades were fitted to (the view's, or one frozen while the view moves): they are picked by depth
// along its viewing direction from its eye, as the CPU's view selection does with each slice's camera.
uniform vec3 uCascadeEye;
uniform vec3 uCascadeForward;
uniform float uPixelPerDepth;  // a screen pixel's world size per unit of depth (texel density view)
uniform vec3 uBaseColor;
uniform float uAmbient;
#ifdef ALPHA_MASK
#include "common/alpha_test.glsl"
#endif

// glTF's range window (KHR_lights_punctual's recommended falloff, without the inverse square): 1 with no range.
float rangeWindow(float distance, float range) {
    if (range <= 0.0) return 1.0;
    float r = distance / range;
    return clamp(1.0 - r * r * r * r, 0.0, 1.0) * clamp(1.0 - r * r * r * r, 0.0, 1.0);
}

// What the lights add up to at this pixel.
struct Shading {
    vec3 n;          // unit normal, facing the viewer's side
    vec3 v;          // unit vector to the camera
    vec3 lambert;    // (1 - ambient) x N.L x light, summed over lights
    vec3 specular;
    float shadowSum; // VIEW_SHADOW: the mean shadow factor of the lights that reach the pixel
    float reaching;
};

void addLight(inout Shading s, LightData L, vec3 l, float shadow, float attenuation) {
    s.shadowSum += shadow;
    s.reaching += 1.0;
    float nDotL = max(dot(s.n, l), 0.0);
    vec3 h = normalize(l + s.v);
    float highlight = nDotL > 0.0 ? pow(max(dot(s.n, h), 0.0), 48.0) * 0.25 : 0.0;
    float direct = L.radiance.w * shadow * attenuation;
    s.lambert += (1.0 - uAmbient) * nDotL * direct * L.radiance.rgb;
    s.specular += highlight * direct * L.radiance.rgb;
}

// The lookup moved along the normal by a fixed number of texels' world size (Holbert's normal offset).
vec3 offsetLookup(Shading s, LightData L, float texelWorld) {
#ifdef NORMAL_OFFSET
    return vWorldPosition + s.n * (L.shadow.w * texelWorld);
#else
    return vWorldPosition;
#endif
}

// One function per kind; `casts` is a constant at every call, so no runtime branch decides whether to take taps.
void directionalLight(inout Shading s, LightData L, const bool casts) {
    float shadow = 1.0;
#if MAP_ARRAYS_2D > 0
#if CASCADES > 0
    if (casts && L.views.y > 0.0) {
        shadow = cascadedShadow(L, vWorldPosition, offsetLookup(s, L, 1.0) - vWorldPosition, uCascadeEye,
                                uCascadeForward);
    } else
#endif
    if (casts) shadow = shadow2D(L, offsetLookup(s, L, L.depth.z), L.direction.xyz, L.depth.z);
#endif
    addLight(s, L, -L.direction.xyz, shadow, 1.0);
}

void spotLight(inout Shading s, LightData L, const bool casts) {
    vec3 toLight = L.position.xyz - vWorldPosition;
    float lightDistance = length(toLight);
    vec3 l = toLight / max(lightDistance, 1e-20);
    float attenuation = rangeWindow(lightDistance, L.position.w);
    if (dot(-l, L.direction.xyz) < L.direction.w || attenuation <= 0.0) {  // outside the cone or the range: no taps
        return;
    }
    float shadow = 1.0;
#if MAP_ARRAYS_2D > 0
    if (casts) {
        float texelWorld = L.depth.z * dot(vWorldPosition - L.position.xyz, L.direction.xyz);
        shadow = shadow2D(L, offsetLookup(s, L, texelWorld), -l, texelWorld);
    }
#endif
    addLight(s, L, l, shadow, attenuation);
}

void pointLight(inout Shading s, LightData L, const bool casts) {
    vec3 toLight = L.position.xyz - vWorldPosition;
    float lightDistance = length(toLight);
    vec3 l = toLight / max(lightDistance, 1e-20);
    float attenuation = rangeWindow(lightDistance, L.position.w);
    if (attenuation <= 0.0) return;  // beyond its range: no taps
    float shadow = 1.0;
#if MAP_ARRAYS_CUBE > 0
    vec3 a = abs(vWorldPosition - L.position.xyz);
    if (casts) shadow = shadowCube(L, offsetLookup(s, L, L.depth.z * max(a.x, max(a.y, a.z))));
#endif
    addLight(s, L, l, shadow, attenuation);
}

void main() {
#ifdef ALPHA_MASK
    if (!alphaTestPasses(vUv)) discard;
#endif
#ifdef RECEIVER_PLANE
    gPositionDx = dFdx(vWorldPosition);
    gPositionDy = dFdy(vWorldPosition);
#elif defined(MOMENT_MIPS)
    gPositionDx = dFdxFine(vWorldPosition);
    gPositionDy = dFdyFine(vWorldPosition);
#endif
    Shading s;
    s.n = normalize(vNormal);
    if (!gl_FrontFacing) s.n = -s.n;  // two-sided lighting: broken windings and double-sided materials shade right
    s.v = normalize(uCameraPosition - vWorldPosition);
    s.lambert = vec3(0.0);
    s.specular = vec3(0.0);
    s.shadowSum = 0.0;
    s.reaching = 0.0;

    // uLights: directional, spot, point; casters first within each kind. Loop bounds are compile-time constants.
#if DIR_CASTERS > 0
    for (int i = 0; i < DIR_CASTERS; ++i) directionalLight(s, uLights[i], true);
#endif
#if DIR_LIGHTS > DIR_CASTERS
    for (int i = DIR_CASTERS; i < DIR_LIGHTS; ++i) directionalLight(s, uLights[i], false);
#endif
#if SPOT_CASTERS > 0
    for (int i = SPOT_BEGIN; i < SPOT_BEGIN + SPOT_CASTERS; ++i) spotLight(s, uLights[i], true);
#endif
#if SPOT_LIGHTS > SPOT_CASTERS
    for (int i = SPOT_BEGIN + SPOT_CASTERS; i < POINT_BEGIN; ++i) spotLight(s, uLights[i], false);
#endif
#if POINT_CASTERS > 0
    for (int i = POINT_BEGIN; i < POINT_BEGIN + POINT_CASTERS; ++i) pointLight(s, uLights[i], true);
#endif
#if POINT_LIGHTS > POINT_CASTERS
    for (int i = POINT_BEGIN + POINT_CASTERS; i < LIGHT_COUNT; ++i) pointLight(s, uLights[i], false);
#endif

#if defined(VIEW_SHADOW)
    outColor = vec4(vec3(s.reaching > 0.0 ? s.shadowSum / s.reaching : 0.0), 1.0);
#elif defined(VIEW_LIGHT_DEPTH)
    // The first light's depth: directional as stored, spot and point as linear distance (not all white).
    float depth = 0.0;
#if LIGHT_COUNT > 0
    LightData first = uLights[0];
    if (DIR_LIGHTS > 0) {
        depth = toLightTexture(first, vWorldPosition).z;
        if (reversedZ(first)) depth = 1.0 - depth;  // near dark in both conventions
    } else {
        vec3 fromLight = vWorldPosition - first.position.xyz;
        float viewDepth = SPOT_LIGHTS > 0 ? dot(fromLight, first.direction.xyz) : length(fromLight);
        depth = (viewDepth - first.depth.x) / (first.depth.y - first.depth.x);
    }
#endif
    outColor = vec4(vec3(clamp(depth, 0.0, 1.0)), 1.0);
#elif defined(VIEW_CASCADES)
    // The lit picture tinted by the cascade that holds the pixel (its blend band mixes the next one's tint); grey
    // beyond the shadow distance or for a light without cascades.
    // The colours: renderer/shading/cascade_tints.h (the editor's frusta and lists show the same ones).
    const vec3 tints[4] = CASCADE_TINTS;
    vec3 tint = vec3(0.5);
#if CASCADES > 0
    if (gCascadeView >= 0) tint = tints[gCascadeView];
    if (gCascadeNext >= 0) tint = mix(tint, tints[gCascadeNext], gCascadeWeight);
#endif
    vec3 color = pow(uBaseColor * (uAmbient + s.lambert) + s.specular, vec3(1.0 / 2.2));
    outColor = vec4(mix(color, tint, 0.45), 1.0);
#elif defined(VIEW_TEXEL_DENSITY)
    // The first light's shadow-map texels per screen pixel: a pixel's world size at its depth over the texel's world
    // size there (the cascade's, for a cascaded light). log2 from -2 (blue: texels 4x larger than pixels, blocky) to
    // +2 (red: 4 texels per pixel, wasted); green = 1. The CPU's figure (measure) is the same ratio.
    float texels = 0.0;
#if LIGHT_COUNT > 0
    LightData first = uLights[0];
    vec3 fromLight = vWorldPosition - first.position.xyz;
    float texelWorld = DIR_LIGHTS > 0 ? first.depth.z
                     : SPOT_LIGHTS > 0 ? first.depth.z * dot(fromLight, first.direction.xyz)
                     : first.depth.z * max(abs(fromLight.x), max(abs(fromLight.y), abs(fromLight.z)));
#if CASCADES > 0
    if (gCascadeTexel > 0.0) texelWorld = gCascadeTexel;
#endif
    float pixelWorld = dot(vWorldPosition - uCameraPosition, uCameraForward) * uPixelPerDepth;
    texels = texelWorld > 0.0 ? pixelWorld / texelWorld : 0.0;
#endif
    float t = clamp(log2(max(texels, 1e-6)) * 0.25 + 0.5, 0.0, 1.0);  // -2 .. +2 -> 0 .. 1
    vec3 density = t < 0.5 ? mix(vec3(0.15, 0.3, 1.0), vec3(0.2, 0.85, 0.3), t * 2.0)
                           : mix(vec3(0.2, 0.85, 0.3), vec3(1.0, 0.2, 0.15), t * 2.0 - 1.0);
    outColor = vec4(texels > 0.0 ? density : vec3(0.3), 1.0);
#else
    vec3 color = uBaseColor * (uAmbient + s.lambert) + s.specular;
    outColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
#endif
}
