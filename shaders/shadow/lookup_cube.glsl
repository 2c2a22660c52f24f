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
    CubeFaceFrame frame = cubeFaceFrame(v, L);
    int map = int(L.shadow.x);
    float sum = 0.0;
    FOR_EACH_TAP {
        vec3 d = cubeFaceTap(frame, TAP_OFFSET * uFilterScale);
        float ref = clampToFar(L, faceDepth(v, d, L));
        sum += sampleMapCube(map, vec4(d, L.shadow.y), ref);
    }
    return sum / float(FILTER_TAPS);
}
#endif

