// EVSM2: VSM over the positive exponential warp of depth (its two moments). See evsm_warp.glsl.
#include "shadow/techniques/evsm_warp.glsl"

vec4 encodeMoments(float z) {
    float p = warpDepth(z).x;
    return vec4(p, p * p, 0.0, 0.0);
}

float momentShadow(vec4 m, float z) { return reduceBleeding(warpedBound(m.xy, warpDepth(z).x, uTechnique.x), uTechnique.w); }
