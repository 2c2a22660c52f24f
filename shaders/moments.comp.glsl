#version 450 core
// The moments pass (renderer/shadow/moments_pass.cpp), one layer of one view at a time:
//   CONVERT: the depth map's texels -> the technique's moments (encodeMoments, its file is "alias:technique");
//   BLUR:    one direction of the separable box blur (uDirection), edge texels repeated (a caster touching the map's
//            edge keeps its moments; the clear value is not mixed in).
// MOMENT_FORMAT: the storage's image format (rg16f, rg32f, rgba16f, rgba32f, rgba16). The CPU mirror is
// renderer/shadow/moments_mirror.cpp.
layout(local_size_x = 8, local_size_y = 8) in;
layout(MOMENT_FORMAT, binding = 0) uniform writeonly image2D uOut;
uniform int uSize;

#ifdef CONVERT
uniform vec4 uTechnique;
#include "alias:technique"
uniform sampler2DArray uDepth;  // the depth array's layers (a cube-map array viewed as 2D layers)
uniform int uLayer;
uniform bool uReversedZ;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= uSize || p.y >= uSize) return;
    float d = texelFetch(uDepth, ivec3(p, uLayer), 0).r;
    imageStore(uOut, p, encodeMoments(uReversedZ ? 1.0 - d : d));
}
#else
layout(MOMENT_FORMAT, binding = 1) uniform readonly image2D uIn;
uniform ivec2 uDirection;
uniform int uRadius;
uniform float uWeights[32];  // uWeights[|i|] for the tap i texels away (shading/filters: blurWeights)

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= uSize || p.y >= uSize) return;
    vec4 sum = vec4(0.0);
    for (int i = -uRadius; i <= uRadius; ++i)
        sum += uWeights[abs(i)] * imageLoad(uIn, clamp(p + i * uDirection, ivec2(0), ivec2(uSize - 1)));
    imageStore(uOut, p, sum);
}
#endif
