// PCSS (Fernando 2005): a blocker search over the depth map, a penumbra estimate from the light's size, then a PCF
// whose width follows it. Both stages read the FILTER_TAPS disk (pcss_filter.cpp's pcssDisk: uniform over the unit
// disc's area, as a disc light's visibility across an edge asks), rotated per pixel by a hash of the pixel. The whole
// lookup (shadow2D, shadowCube) is this file, the variant's "alias:lookup"; its CPU mirror (the pixel probe) is
// renderer/shading/filters/pcss_filter.cpp, step for step in float.
//   uTechnique  x: the largest blocker-search radius, y: the largest filter radius (texels)
//   L.views.z   the light's size: its width per unit of distance (directional: 2 tan(angular diameter / 2)), or
//               its diameter (spot, point)
// Radii are in texels at the receiver; a map's texel is an angle (perspective views) or a width (orthographic), the
// same at every depth, so a width anywhere along the light's cone converts with the receiver's texel.
#include "shadow/light_data.glsl"
#include "shadow/filter_taps.glsl"
#include "shadow/compare_2d.glsl"
#include "shadow/compare_cube.glsl"
#include "shadow/cube_face_depth.glsl"

uniform vec4 uTechnique;
#if MAP_ARRAYS_2D > 0
uniform sampler2DArray uDepth2D[MAP_ARRAYS_2D];  // the same maps, read as depths (nearest, no comparison)
#endif
#if MAP_ARRAYS_CUBE > 0
uniform samplerCubeArray uDepthCube[MAP_ARRAYS_CUBE];
#endif

// The pixel's rotation (cos, sin): an integer hash of gl_FragCoord, turned into a point of the unit circle by its
// rational parametrization (no trigonometry: the CPU mirror computes the same floats); a hash bit picks the half turn.
vec2 pcssRotation() {
    uvec2 p = uvec2(gl_FragCoord.xy);
    uint h = p.x * 1664525u + p.y * 1013904223u;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    float t = float(h & 0xffffu) / 32767.5 - 1.0;
    float d = 1.0 + t * t;
    vec2 r = vec2((1.0 - t * t) / d, 2.0 * t / d);
    return (h & 0x10000u) != 0u ? -r : r;
}

vec2 rotateTap(vec2 o, vec2 r) { return vec2(r.x * o.x - r.y * o.y, r.y * o.x + r.x * o.y); }

// Distance along a perspective view's axis of window depth z (cube_face_depth.glsl's mapping, inverted).
float pcssDistance(LightData L, float z) {
    float n = L.depth.x, f = L.depth.y;
    if (reversedZ(L)) return n * f / (n + z * (f - n));
    return 2.0 * f * n / ((f + n) - (2.0 * z - 1.0) * (f - n));
}

// The light's width, in texels at the receiver, that a blocker at window depth zB spreads over the receiver at zR:
// perspective (dR: the receiver's distance along the axis): the light's diameter x (dR - dB) / dB over the texel at
// dR; orthographic (depthPerWorld: window depth per world unit along the light): the gap in world units x the width
// per unit of distance, over the texel's world size.
float pcssSpread(LightData L, bool perspective, float zR, float zB, float dR, float depthPerWorld, float texelWorld) {
    if (perspective) {
        float dB = pcssDistance(L, zB);
        return L.views.z * max(dR - dB, 0.0) / dB / (L.depth.z * dR);
    }
    return L.views.z * max((zR - zB) / depthPerWorld, 0.0) / texelWorld;
}

// A stored depth nearer the light than the receiver's.
bool pcssBlocks(LightData L, float stored, float receiver) { return reversedZ(L) ? stored > receiver : stored < receiver; }

#if MAP_ARRAYS_2D > 0
float sampleDepth2D(int map, ivec3 texel) {
#if MAP_ARRAYS_2D == 1
    return texelFetch(uDepth2D[0], texel, 0).r;
#else
    float result = 1.0;
    for (int k = 0; k < MAP_ARRAYS_2D; ++k)
        if (k == map) result = texelFetch(uDepth2D[k], texel, 0).r;
    return result;
#endif
}

float shadow2D(LightData L, vec3 lookup, vec3 ray, float texelWorld) {
    vec3 lightTex = toLightTexture(L, lookup);
    float ref = clampToFar(L, lightTex.z);
    int map = int(L.shadow.x);
    bool inside = all(greaterThanEqual(lightTex.xy, vec2(0.0))) && all(lessThanEqual(lightTex.xy, vec2(1.0)));
    // Beyond the map: one comparison, the address mode's answer (as every filter's taps there).
    if (!inside) return sampleMap2D(map, vec4(lightTex.xy, L.shadow.y, ref));
#ifdef RECEIVER_PLANE
    vec2 plane = receiverPlaneSlope(L, lookup, lightTex, ray, texelWorld);
#else
    vec2 plane = vec2(0.0);
#endif
    bool perspective = L.viewProjection[2][3] != 0.0;
    float dR = perspective ? pcssDistance(L, ref) : 0.0;
    float depthPerWorld = perspective ? 0.0 : toLightTexture(L, lookup + ray).z - lightTex.z;
    vec2 lo = vec2(0.5 * L.shadow.z), hi = vec2(1.0 - 0.5 * L.shadow.z);
    vec2 rotation = pcssRotation();
    float resolution = 1.0 / L.shadow.z;

    // 1. Blockers: where the light's cone from the receiver crosses the map (widest at the near plane).
    float nearDepth = reversedZ(L) ? 1.0 : 0.0;
    float search = clamp(0.5 * pcssSpread(L, perspective, ref, nearDepth, dR, depthPerWorld, texelWorld), 1.0,
                         uTechnique.x);
    float blockerSum = 0.0;
    int blockers = 0;
    for (int i = 0; i < FILTER_TAPS; ++i) {
        vec2 tapTex = clamp(lightTex.xy + rotateTap(TAP_OFFSETS[i], rotation) * search * L.shadow.z, lo, hi);
        vec2 texel = floor(tapTex * resolution);
        float stored = sampleDepth2D(map, ivec3(ivec2(texel), int(L.shadow.y)));
        // The receiver's plane at the texel's centre, as a nearest tap compares it.
        float receiver = ref + dot(plane, texel + 0.5 - lightTex.xy * resolution);
        if (pcssBlocks(L, stored, receiver)) {
            blockerSum += stored;
            ++blockers;
        }
    }
    if (blockers == 0) return 1.0;

    // 2. The penumbra from the blockers' mean depth; the filter's radius is half of it.
    float blocker = blockerSum / float(blockers);
    float radius = clamp(0.5 * pcssSpread(L, perspective, ref, blocker, dR, depthPerWorld, texelWorld), 1.0,
                         uTechnique.y);

    // 3. PCF over the rotated disk of that radius, through the comparison sampler (bilinear).
    float sum = 0.0;
    for (int i = 0; i < FILTER_TAPS; ++i) {
        vec2 tapTex = clamp(lightTex.xy + rotateTap(TAP_OFFSETS[i], rotation) * radius * L.shadow.z, lo, hi);
        float tapRef = clampToFar(L, ref + dot(plane, (tapTex - lightTex.xy) * resolution));
        sum += sampleMap2D(map, vec4(tapTex, L.shadow.y, tapRef));
    }
    return sum / float(FILTER_TAPS);
}
#endif

#if MAP_ARRAYS_CUBE > 0
float sampleDepthCube(int map, vec4 coord) {
#if MAP_ARRAYS_CUBE == 1
    return texture(uDepthCube[0], coord).r;
#else
    float result = 1.0;
    for (int k = 0; k < MAP_ARRAYS_CUBE; ++k)
        if (k == map) result = texture(uDepthCube[k], coord).r;
    return result;
#endif
}

// A point light: the same three steps, the taps moved across the lookup's face by direction (cubeFaceTap, as
// lookup_cube.glsl's), each read and compared in the face its direction selects; blockers' distances along their own
// face's axis.
float shadowCube(LightData L, vec3 lookup) {
    vec3 v = lookup - L.position.xyz;
    CubeFaceFrame frame = cubeFaceFrame(v, L);
    int map = int(L.shadow.x);
    vec2 rotation = pcssRotation();
    float ref = clampToFar(L, faceDepth(v, v, L));
    float nearDepth = reversedZ(L) ? 1.0 : 0.0;
    float search = clamp(0.5 * pcssSpread(L, true, ref, nearDepth, frame.major, 0.0, 0.0), 1.0, uTechnique.x);
    float blockerSum = 0.0;
    int blockers = 0;
    for (int i = 0; i < FILTER_TAPS; ++i) {
        vec3 d = cubeFaceTap(frame, rotateTap(TAP_OFFSETS[i], rotation) * search);
        float stored = sampleDepthCube(map, vec4(d, L.shadow.y));
        float receiver = faceDepth(v, d, L);
        if (pcssBlocks(L, stored, receiver)) {  // every face maps distance to depth alike: the mean is a distance
            blockerSum += stored;
            ++blockers;
        }
    }
    if (blockers == 0) return 1.0;
    float radius = clamp(0.5 * pcssSpread(L, true, ref, blockerSum / float(blockers), frame.major, 0.0, 0.0), 1.0,
                         uTechnique.y);
    float sum = 0.0;
    for (int i = 0; i < FILTER_TAPS; ++i) {
        vec3 d = cubeFaceTap(frame, rotateTap(TAP_OFFSETS[i], rotation) * radius);
        sum += sampleMapCube(map, vec4(d, L.shadow.y), clampToFar(L, faceDepth(v, d, L)));
    }
    return sum / float(FILTER_TAPS);
}
#endif
