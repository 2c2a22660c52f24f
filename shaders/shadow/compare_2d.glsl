// What a 2D view's depth comparisons share (lookup_2d.glsl's filters and PCSS's techniques/pcss.glsl): the
// comparison samplers, reading them with constant indices, and the receiver plane.
#include "shadow/light_data.glsl"

#if MAP_ARRAYS_2D > 0
uniform sampler2DArrayShadow uMaps2D[MAP_ARRAYS_2D];
#endif

#ifdef RECEIVER_PLANE
// Screen-space derivatives of the surface position, taken in main() where control flow is uniform (a light's cone
// test is not): the receiver's plane for every light.
vec3 gPositionDx, gPositionDy;

// A plane steeper than this many texel-world-sizes of depth along the light per texel across is clamped (grazing
// receivers, silhouettes): the tilt then stops growing and the slope bias covers the rest.
const float kReceiverPlaneMaxSlope = 8.0;

// Receiver-plane depth bias (Isidoro, GDC 2006): the receiver's depth change per texel along the map's u and v. The
// pixel's steps in x and y, taken into the map, give the Jacobian d(u,v)/d(x,y) and d(depth)/d(x,y); its inverse
// gives d(depth)/d(u,v). 0 when the light does not use it or the Jacobian is (near) singular (an edge-on receiver).
// `ray`: the unit direction light travels at the lookup; `texelWorld`: a texel's world size there.
vec2 receiverPlaneSlope(LightData L, vec3 lookup, vec3 lightTex, vec3 ray, float texelWorld) {
    if ((int(L.depth.w) & 2) == 0) return vec2(0.0);
    float texels = 1.0 / L.shadow.z;
    vec3 dx = toLightTexture(L, lookup + gPositionDx) - lightTex;
    vec3 dy = toLightTexture(L, lookup + gPositionDy) - lightTex;
    dx.xy *= texels;
    dy.xy *= texels;
    float det = dx.x * dy.y - dx.y * dy.x;
    if (!(abs(det) > 1e-3 * length(dx.xy) * length(dy.xy))) return vec2(0.0);
    vec2 slope = vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det;
    float limit = kReceiverPlaneMaxSlope * abs(toLightTexture(L, lookup + ray * texelWorld).z - lightTex.z);
    float length2 = dot(slope, slope);
    return length2 > limit * limit ? slope * (limit * inversesqrt(length2)) : slope;
}
#endif

// Map arrays are read with constant indices only. Mesa 22.3's LLVM 15 (llvmpipe: CI and every machine without a GPU)
// crashed in EarlyCSE compiling a sampler array indexed by a uniform-block value (uMaps2D[int(L.shadow.x)]) beside a
// cube-map array; a loop over the arrays that the compiler unrolls gives each texture() a constant index instead.
#if MAP_ARRAYS_2D > 0
float sampleMap2D(int map, vec4 coord) {
#if MAP_ARRAYS_2D == 1
    return texture(uMaps2D[0], coord);  // one array: no selection at all (a dynamic one is 3x slower on llvmpipe)
#else
    float result = 1.0;
    for (int k = 0; k < MAP_ARRAYS_2D; ++k)
        if (k == map) result = texture(uMaps2D[k], coord);
    return result;
#endif
}
#endif
