// The shadow factor of a moments technique (VSM, EVSM, MSM): one filtered read of the view's blurred moments at the
// lookup (bilinear; with MOMENT_MIPS trilinear, at the level of the pixel's footprint in the map), given to the
// technique's momentShadow with the receiver's depth as the moments pass stored depths (shadow/linear_depth.glsl).
// The technique's file (encodeMoments, momentShadow) is the variant's "alias:technique". The pixel probe mirrors
// this (renderer/probe/moment_probe.cpp).
#include "shadow/light_data.glsl"
#include "shadow/cube_face_depth.glsl"
#include "shadow/linear_depth.glsl"

uniform vec4 uTechnique;  // the technique's terms (shading/filters/<technique>_filter.cpp: uniforms)
#include "alias:technique"

#if MAP_ARRAYS_2D > 0
uniform sampler2DArray uMaps2D[MAP_ARRAYS_2D];
#endif
#if MAP_ARRAYS_CUBE > 0
uniform samplerCubeArray uMapsCube[MAP_ARRAYS_CUBE];
#endif

// textureLod of map `map` of `count` arrays, read with constant indices only (see shadow/compare_2d.glsl); with one
// array no selection at all (the branch folds at compile time).
#define READ_MOMENTS(result, maps, count, map, coord, level)                       \
    if (count == 1) result = textureLod(maps[0], coord, level);                     \
    else for (int k = 0; k < count; ++k) if (k == map) result = textureLod(maps[k], coord, level);

#ifdef MOMENT_MIPS
// Screen-space derivatives of the surface position, taken in main() where control flow is uniform (dFdxFine: the
// pixel's own row and column of its quad, which the probe's mirror recomputes from the surface's plane).
vec3 gPositionDx, gPositionDy;

// The mip level of a lookup whose map coordinate moves by stepX and stepY (map widths) across one pixel: log2 of
// the larger in texels (GL's rho), within the map's levels. The probe computes the same (moment_probe.cpp).
float momentLevel(float stepX, float stepY, float texel) {
    return clamp(log2(max(stepX, stepY) / texel), 0.0, floor(log2(1.0 / texel)));
}

// A point on a cube face in face coordinates (map widths), the face's axis component constant: differences are steps.
vec3 faceCoord(vec3 v, vec3 axis) { return 0.5 * v / dot(v, axis); }
#endif

#if MAP_ARRAYS_2D > 0
float shadow2D(LightData L, vec3 lookup, vec3 ray, float texelWorld) {
    vec3 lightTex = toLightTexture(L, lookup);
    bool perspective = L.viewProjection[2][3] != 0.0;  // a spot view
    float z = momentDepth(clampToFar(L, lightTex.z), perspective, reversedZ(L), L.depth.x, L.depth.y);
    float level = 0.0;
#ifdef MOMENT_MIPS
    level = momentLevel(length(toLightTexture(L, lookup + gPositionDx).xy - lightTex.xy),
                        length(toLightTexture(L, lookup + gPositionDy).xy - lightTex.xy), L.shadow.z);
#endif
    // Inside the map the read stays half a texel (of the coarser level read) from its edge, as the depth lookups'
    // taps do: the border's moments are not mixed in.
    float edge = 0.5 * L.shadow.z * exp2(ceil(level));
    bool inside = all(greaterThanEqual(lightTex.xy, vec2(0.0))) && all(lessThanEqual(lightTex.xy, vec2(1.0)));
    vec2 tex = inside ? clamp(lightTex.xy, vec2(edge), vec2(1.0 - edge)) : lightTex.xy;
    vec4 m = vec4(0.0);
    READ_MOMENTS(m, uMaps2D, MAP_ARRAYS_2D, int(L.shadow.x), vec3(tex, L.shadow.y), level)
    return momentShadow(m, z);
}
#endif

#if MAP_ARRAYS_CUBE > 0
float shadowCube(LightData L, vec3 lookup) {
    vec3 v = lookup - L.position.xyz;
    float z = momentDepth(clampToFar(L, faceDepth(v, v, L)), true, reversedZ(L), L.depth.x, L.depth.y);
    float level = 0.0;
#ifdef MOMENT_MIPS
    vec3 axis = cubeFaceAxis(cubeFaceOf(v));
    level = momentLevel(length(faceCoord(v + gPositionDx, axis) - faceCoord(v, axis)),
                        length(faceCoord(v + gPositionDy, axis) - faceCoord(v, axis)), L.shadow.z);
#endif
    vec4 m = vec4(0.0);
    READ_MOMENTS(m, uMapsCube, MAP_ARRAYS_CUBE, int(L.shadow.x), vec4(v, L.shadow.y), level)
    return momentShadow(m, z);
}
#endif
