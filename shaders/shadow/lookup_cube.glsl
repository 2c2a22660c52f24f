// The shadow factor through a point light's cube map: the filter's taps moved across the face, each compared with
// the receiver's depth in the face its direction selects (shadow/view_select.glsl).
#include "shadow/light_data.glsl"
#include "shadow/filter_taps.glsl"
#include "shadow/view_select.glsl"
#include "shadow/cube_face_depth.glsl"
#include "shadow/compare_cube.glsl"

#if MAP_ARRAYS_CUBE > 0
float shadowCube(LightData L, vec3 lookup) {
    vec3 v = lookup - L.position.xyz;
    vec3 a = abs(v);
    float major = max(a.x, max(a.y, a.z));
    // The face's two tangent axes: taps move across the face by texels (2 / resolution at unit distance).
    int axis = cubeFaceOf(v) / 2;
    vec3 s = axis == 0 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 t = axis == 1 ? vec3(0.0, 0.0, 1.0) : vec3(0.0, 1.0, 0.0);
    float texelAtMajor = 2.0 * L.shadow.z * major;
    int map = int(L.shadow.x);
    float sum = 0.0;
    FOR_EACH_TAP {
        vec2 o = TAP_OFFSET * uFilterScale * texelAtMajor;
        vec3 d = v + o.x * s + o.y * t;
        float ref = clampToFar(L, faceDepth(v, d, L));
        sum += sampleMapCube(map, vec4(d, L.shadow.y), ref);
    }
    return sum / float(FILTER_TAPS);
}
#endif

