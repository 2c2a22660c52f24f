// The shadow factor of a moments technique (VSM, EVSM, MSM): one bilinear read of the view's blurred moments at the
// lookup, given to the technique's momentShadow with the receiver's depth (near 0, far 1 in both conventions: the
// moments pass stores reversed-Z maps flipped). The technique's file (encodeMoments, momentShadow) is the variant's
// "alias:technique". The pixel probe mirrors this (renderer/probe/pixel_probe.cpp, moment lookups).
#include "shadow/light_data.glsl"
#include "shadow/cube_face_depth.glsl"

uniform vec4 uTechnique;  // the technique's terms (shading/filters/<technique>_filter.cpp: uniforms)
#include "alias:technique"

#if MAP_ARRAYS_2D > 0
uniform sampler2DArray uMaps2D[MAP_ARRAYS_2D];
#endif
#if MAP_ARRAYS_CUBE > 0
uniform samplerCubeArray uMapsCube[MAP_ARRAYS_CUBE];
#endif

float nearZeroDepth(LightData L, float depth) { return reversedZ(L) ? 1.0 - depth : depth; }

// Map arrays are read with constant indices only (see shadow/compare_2d.glsl).
#if MAP_ARRAYS_2D > 0
vec4 sampleMoments2D(int map, vec3 coord) {
#if MAP_ARRAYS_2D == 1
    return texture(uMaps2D[0], coord);
#else
    vec4 result = vec4(0.0);
    for (int k = 0; k < MAP_ARRAYS_2D; ++k)
        if (k == map) result = texture(uMaps2D[k], coord);
    return result;
#endif
}

float shadow2D(LightData L, vec3 lookup, vec3 ray, float texelWorld) {
    vec3 lightTex = toLightTexture(L, lookup);
    float z = nearZeroDepth(L, clampToFar(L, lightTex.z));
    // Inside the map the read stays half a texel from its edge, as the depth lookups' taps do.
    bool inside = all(greaterThanEqual(lightTex.xy, vec2(0.0))) && all(lessThanEqual(lightTex.xy, vec2(1.0)));
    vec2 tex = inside ? clamp(lightTex.xy, vec2(0.5 * L.shadow.z), vec2(1.0 - 0.5 * L.shadow.z)) : lightTex.xy;
    return momentShadow(sampleMoments2D(int(L.shadow.x), vec3(tex, L.shadow.y)), z);
}
#endif

#if MAP_ARRAYS_CUBE > 0
vec4 sampleMomentsCube(int map, vec4 coord) {
#if MAP_ARRAYS_CUBE == 1
    return texture(uMapsCube[0], coord);
#else
    vec4 result = vec4(0.0);
    for (int k = 0; k < MAP_ARRAYS_CUBE; ++k)
        if (k == map) result = texture(uMapsCube[k], coord);
    return result;
#endif
}

float shadowCube(LightData L, vec3 lookup) {
    vec3 v = lookup - L.position.xyz;
    float z = nearZeroDepth(L, clampToFar(L, faceDepth(v, v, L)));
    return momentShadow(sampleMomentsCube(int(L.shadow.x), vec4(v, L.shadow.y)), z);
}
#endif
