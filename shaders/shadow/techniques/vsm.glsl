// VSM (Donnelly & Lauritzen 2006): the blurred mean and mean square of depth; a receiver beyond the mean is lit at
// most Chebyshev's bound. uTechnique: x = minimum variance, y = light-bleeding reduction. The CPU's copy (moments
// pass and probe): renderer/shading/filters/vsm_filter.cpp.
#include "shadow/techniques/chebyshev.glsl"

vec4 encodeMoments(float z) { return vec4(z, z * z, 0.0, 0.0); }

float momentShadow(vec4 m, float z) {
    return reduceBleeding(chebyshevUpperBound(m.x, m.y, z, uTechnique.x), uTechnique.y);
}
