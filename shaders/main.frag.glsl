#version 450 core
// Main pass: for each light, projects the pixel into that light's shadow view and compares depths. The renderer
// prepends #defines (renderer/shading/shader_variants.cpp):
//   light set  DIR_LIGHTS, DIR_CASTERS, SPOT_LIGHTS, SPOT_CASTERS, POINT_LIGHTS, POINT_CASTERS: how many lights of
//              each kind, casters first (uLights holds them in that order: directional, spot, point)
//   maps       MAP_ARRAYS_2D (sampler2DArrayShadow, directional and spot views), MAP_ARRAYS_CUBE
//              (samplerCubeArrayShadow, point lights: per-face perspective depth)
//   filter     FILTER_TAPS, FILTER_TAP_OFFSETS (texels; scaled by uFilterScale): the filter technique's taps
//              (renderer/shading/filter_taps.cpp, shared with the pixel probe)
//   view       VIEW_LIT | VIEW_SHADOW | VIEW_LIGHT_DEPTH; NORMAL_OFFSET, ALPHA_MASK (+ BASE_COLOR_TEXTURE)
// Only the lights, kinds and features a frame uses are compiled in; loop counts are compile-time constants.
layout(location = 0) in vec3 vWorldPosition;
layout(location = 1) in vec3 vNormal;
layout(location = 2) in vec2 vUv;
layout(location = 0) out vec4 outColor;

#define LIGHT_COUNT (DIR_LIGHTS + SPOT_LIGHTS + POINT_LIGHTS)
#define SPOT_BEGIN DIR_LIGHTS
#define POINT_BEGIN (DIR_LIGHTS + SPOT_LIGHTS)

struct LightData {
    mat4 viewProjection;  // directional / spot: render-origin-relative world -> light clip
    vec4 position;        // xyz: spot / point position (render-origin-relative); w: range, 0 = no limit
    vec4 direction;       // xyz: unit direction the light travels; w: cos(half cone) (spot)
    vec4 radiance;        // rgb: colour; w: intensity
    vec4 shadow;          // x: map array, y: layer (2D) or cube index, z: 1 / resolution, w: normal offset (texels)
    vec4 depth;           // x: near, y: far, z: texel world size (directional) or per unit of depth (spot, point)
};
#if LIGHT_COUNT > 0
layout(std140, binding = 0) uniform Lights { LightData uLights[LIGHT_COUNT]; };
#endif
#if MAP_ARRAYS_2D > 0
uniform sampler2DArrayShadow uMaps2D[MAP_ARRAYS_2D];
#endif
#if MAP_ARRAYS_CUBE > 0
uniform samplerCubeArrayShadow uMapsCube[MAP_ARRAYS_CUBE];
#endif

uniform vec3 uCameraPosition;  // render-origin-relative
uniform vec3 uBaseColor;
uniform float uAmbient;
uniform float uFilterScale;    // tap offsets are multiplied by it (Poisson: the radius; grids: 1)
#ifdef ALPHA_MASK
uniform float uAlphaFactor;
uniform float uAlphaCutoff;
#ifdef BASE_COLOR_TEXTURE
uniform sampler2D uBaseColorTexture;
#endif
#endif

const vec2 TAP_OFFSETS[FILTER_TAPS] = vec2[](FILTER_TAP_OFFSETS);

vec3 toLightTexture(mat4 viewProjection, vec3 worldPosition) {
    vec4 clip = viewProjection * vec4(worldPosition, 1.0);
    vec3 ndc = clip.xyz / clip.w;
    return ndc * 0.5 + 0.5;
}

// glTF's range window (KHR_lights_punctual's recommended falloff, without the inverse square): 1 with no range.
float rangeWindow(float distance, float range) {
    if (range <= 0.0) return 1.0;
    float r = distance / range;
    return clamp(1.0 - r * r * r * r, 0.0, 1.0) * clamp(1.0 - r * r * r * r, 0.0, 1.0);
}

#if MAP_ARRAYS_2D > 0
// Fraction of light reaching the point through a 2D view, 1 = lit. Receivers beyond the far plane compare as if on it.
float shadow2D(LightData L, vec3 lookup) {
    vec3 lightTex = toLightTexture(L.viewProjection, lookup);
    float ref = min(lightTex.z, 1.0);
    int map = int(L.shadow.x);
    float sum = 0.0;
    for (int i = 0; i < FILTER_TAPS; ++i)
        sum += texture(uMaps2D[map], vec4(lightTex.xy + TAP_OFFSETS[i] * uFilterScale * L.shadow.z, L.shadow.y, ref));
    return sum / float(FILTER_TAPS);
}
#endif

#if MAP_ARRAYS_CUBE > 0
// The stored value of a cube face is that face's perspective depth, so the reference is the receiver's depth in the
// face the tap's direction selects: its distance along that face's axis, through the same near/far mapping.
float faceDepth(vec3 fromLight, vec3 tapDirection, float near, float far) {
    vec3 a = abs(tapDirection);
    vec3 axis = a.x >= a.y && a.x >= a.z ? vec3(sign(tapDirection.x), 0.0, 0.0)
              : a.y >= a.z                ? vec3(0.0, sign(tapDirection.y), 0.0)
                                          : vec3(0.0, 0.0, sign(tapDirection.z));
    float z = max(dot(fromLight, axis), near);
    return ((far + near) / (far - near) - 2.0 * far * near / ((far - near) * z)) * 0.5 + 0.5;
}

float shadowCube(LightData L, vec3 lookup) {
    vec3 v = lookup - L.position.xyz;
    vec3 a = abs(v);
    float major = max(a.x, max(a.y, a.z));
    // The face's two tangent axes: taps move across the face by texels (2 / resolution at unit distance).
    vec3 s = a.x >= a.y && a.x >= a.z ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 t = a.y >= a.x && a.y >= a.z ? vec3(0.0, 0.0, 1.0) : vec3(0.0, 1.0, 0.0);
    float texelAtMajor = 2.0 * L.shadow.z * major;
    int map = int(L.shadow.x);
    float sum = 0.0;
    for (int i = 0; i < FILTER_TAPS; ++i) {
        vec2 o = TAP_OFFSETS[i] * uFilterScale * texelAtMajor;
        vec3 d = v + o.x * s + o.y * t;
        float ref = min(faceDepth(v, d, L.depth.x, L.depth.y), 1.0);
        sum += texture(uMapsCube[map], vec4(d, L.shadow.y), ref);
    }
    return sum / float(FILTER_TAPS);
}
#endif

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
    vec3 v = normalize(uCameraPosition - vWorldPosition);

    vec3 lambert = vec3(0.0);  // (1 - ambient) x N.L x light, summed over lights
    vec3 specular = vec3(0.0);
    float shadowSum = 0.0;     // VIEW_SHADOW: the mean shadow factor of the lights that reach the pixel
    float reaching = 0.0;

#if LIGHT_COUNT > 0
    for (int i = 0; i < LIGHT_COUNT; ++i) {
        LightData L = uLights[i];
        vec3 l;
        float attenuation = 1.0;
        float texelWorld = L.depth.z;
        if (i < SPOT_BEGIN) {
            l = -L.direction.xyz;
        } else {
            vec3 toLight = L.position.xyz - vWorldPosition;
            float lightDistance = length(toLight);
            l = toLight / max(lightDistance, 1e-20);
            attenuation = rangeWindow(lightDistance, L.position.w);
            if (i < POINT_BEGIN) {
                if (dot(-l, L.direction.xyz) < L.direction.w) continue;  // outside the cone: no light, no taps
                texelWorld = L.depth.z * dot(vWorldPosition - L.position.xyz, L.direction.xyz);
            } else {
                vec3 a = abs(vWorldPosition - L.position.xyz);
                texelWorld = L.depth.z * max(a.x, max(a.y, a.z));
            }
            if (attenuation <= 0.0) continue;  // beyond its range
        }

        float shadow = 1.0;
        bool casts = i < DIR_CASTERS || (i >= SPOT_BEGIN && i < SPOT_BEGIN + SPOT_CASTERS) ||
                     (i >= POINT_BEGIN && i < POINT_BEGIN + POINT_CASTERS);
        if (casts) {
            vec3 lookup = vWorldPosition;
#ifdef NORMAL_OFFSET
            // Move the lookup along the normal by a fixed number of texels' world size (Holbert's normal offset).
            lookup += n * (L.shadow.w * texelWorld);
#endif
#if MAP_ARRAYS_CUBE > 0
            if (i >= POINT_BEGIN) shadow = shadowCube(L, lookup);
#endif
#if MAP_ARRAYS_2D > 0
            if (i < POINT_BEGIN) shadow = shadow2D(L, lookup);
#endif
        }
        shadowSum += shadow;
        reaching += 1.0;

        float nDotL = max(dot(n, l), 0.0);
        vec3 h = normalize(l + v);
        float highlight = nDotL > 0.0 ? pow(max(dot(n, h), 0.0), 48.0) * 0.25 : 0.0;
        float direct = L.radiance.w * shadow * attenuation;
        lambert += (1.0 - uAmbient) * nDotL * direct * L.radiance.rgb;
        specular += highlight * direct * L.radiance.rgb;
    }
#endif

#if defined(VIEW_SHADOW)
    outColor = vec4(vec3(reaching > 0.0 ? shadowSum / reaching : 0.0), 1.0);
#elif defined(VIEW_LIGHT_DEPTH)
    // The first light's depth: directional as stored, spot and point as linear distance (not all white).
    float depth = 0.0;
#if LIGHT_COUNT > 0
    LightData first = uLights[0];
    if (DIR_LIGHTS > 0) {
        depth = toLightTexture(first.viewProjection, vWorldPosition).z;
    } else {
        vec3 fromLight = vWorldPosition - first.position.xyz;
        float viewDepth = SPOT_LIGHTS > 0 ? dot(fromLight, first.direction.xyz) : length(fromLight);
        depth = (viewDepth - first.depth.x) / (first.depth.y - first.depth.x);
    }
#endif
    outColor = vec4(vec3(clamp(depth, 0.0, 1.0)), 1.0);
#else
    vec3 color = uBaseColor * (uAmbient + lambert) + specular;
    outColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
#endif
}
