// EVSM's exponential warp (Lauritzen & McCool 2008) and the bound of one warped channel, shared by evsm2.glsl and
// evsm4.glsl. uTechnique: x = c+, y = c- (each clamped on the CPU to what the storage holds), z = minimum variance in
// depth units (scaled by the warp's slope), w = light-bleeding reduction. CPU copy: shading/filters/evsm_filter.cpp.
#include "shadow/techniques/chebyshev.glsl"

// z in [0, 1] -> (exp(c+ d), -exp(-c- d)) with d = 2z - 1 in [-1, 1].
vec2 warpDepth(float z) {
    float d = 2.0 * z - 1.0;
    return vec2(exp(uTechnique.x * d), -exp(-uTechnique.y * d));
}

// One warped channel's bound: the minimum variance follows the warp's slope at the receiver (dw/dz = 2 c w).
float warpedBound(vec2 moments, float warped, float exponent) {
    float slope = 2.0 * exponent * warped;
    return chebyshevUpperBound(moments.x, moments.y, warped, uTechnique.z * slope * slope);
}
