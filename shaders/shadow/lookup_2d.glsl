// The shadow factor through a directional or spot light's 2D view: the filter's taps, each compared with the
// receiver's depth (receiver-plane bias optional), kept inside the map. The pixel probe mirrors it
// (renderer/probe/pixel_probe.cpp).
#include "shadow/light_data.glsl"
#include "shadow/filter_taps.glsl"
#include "shadow/compare_2d.glsl"

#if MAP_ARRAYS_2D > 0
// Fraction of light reaching the point through a 2D view, 1 = lit. `ray` and `texelWorld` (the direction light
// travels and a texel's world size at the lookup) bound the receiver plane's tilt.
float shadow2D(LightData L, vec3 lookup, vec3 ray, float texelWorld) {
    vec3 lightTex = toLightTexture(L, lookup);
    float ref = clampToFar(L, lightTex.z);
#ifdef RECEIVER_PLANE
    vec2 plane = receiverPlaneSlope(L, lookup, lightTex, ray, texelWorld);
#endif
    int map = int(L.shadow.x);
    // A lookup inside the map keeps its taps inside it (half a texel from the edge: a bilinear tap's footprint too),
    // so a kernel near the edge reads the map's own border texels, not the address mode's "outside" (HARD_CASES 6).
    // The pixel probe mirrors this (probe/pixel_probe.cpp).
    bool inside = all(greaterThanEqual(lightTex.xy, vec2(0.0))) && all(lessThanEqual(lightTex.xy, vec2(1.0)));
    vec2 lo = inside ? vec2(0.5 * L.shadow.z) : vec2(-1e30), hi = inside ? vec2(1.0 - 0.5 * L.shadow.z) : vec2(1e30);
    float sum = 0.0;
    FOR_EACH_TAP {
        vec2 tapTex = clamp(lightTex.xy + TAP_OFFSET * uFilterScale * L.shadow.z, lo, hi);
#ifdef RECEIVER_PLANE
        vec2 offset = (tapTex - lightTex.xy) / L.shadow.z;  // texels, to the tap actually read (after the clamp)
#ifdef FILTER_NEAREST
        // A nearest tap reads one texel, whose stored depth is its caster's at the texel's centre: the plane there.
        vec2 lookupTexels = lightTex.xy / L.shadow.z;
        vec2 toCentre = floor(lookupTexels + offset) + 0.5 - lookupTexels;
        float tapRef = clampToFar(L, lightTex.z + dot(plane, toCentre));
#else
        float tapRef = clampToFar(L, lightTex.z + dot(plane, offset));  // the receiver's plane at the tap
#endif
#else
        float tapRef = ref;
#endif
        sum += sampleMap2D(map, vec4(tapTex, L.shadow.y, tapRef));
    }
    return sum / float(FILTER_TAPS);
}
#endif

