// EVSM4: the positive and the negative warp's moments; the lower of the two bounds. See evsm_warp.glsl.
#include "shadow/techniques/evsm_warp.glsl"

vec4 encodeMoments(float z) {
    vec2 w = warpDepth(z);
    return vec4(w.x, w.x * w.x, w.y, w.y * w.y);
}

float momentShadow(vec4 m, float z) {
    vec2 w = warpDepth(z);
    float bound = min(warpedBound(m.xy, w.x, uTechnique.x), warpedBound(m.zw, w.y, uTechnique.y));
    return reduceBleeding(bound, uTechnique.w);
}
