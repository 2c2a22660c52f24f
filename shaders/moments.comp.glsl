#version 450 core
// The moments pass (renderer/shadow/moments_pass.cpp), one layer of one view at a time:
//   CONVERT: the depth map's texels -> the technique's moments (encodeMoments, its file is "alias:technique") of the
//            depth in the near-0 convention moments use (shadow/linear_depth.glsl: linear for perspective views);
//   BLUR:    one direction of the separable box blur (uDirection), edge texels repeated (a caster touching the map's
//            edge keeps its moments; the clear value is not mixed in);
//   MIPS:    one mip level from the one below: each texel the mean of the 2x2 texels under it (filter.momentMips).
// MOMENT_FORMAT: the storage's image format (rg16f, rg32f, rgba16f, rgba32f, rgba16). The CPU mirror is
// renderer/shading/filters/moments_mirror.cpp.
layout(local_size_x = 8, local_size_y = 8) in;
layout(MOMENT_FORMAT, binding = 0) uniform writeonly image2D uOut;
uniform int uSize;  // the written level's size

#ifdef CONVERT
uniform vec4 uTechnique;
#include "alias:technique"
#include "shadow/linear_depth.glsl"
uniform sampler2DArray uDepth;  // the depth array's layers (a cube-map array viewed as 2D layers)
uniform int uLayer;
uniform bool uReversedZ;
uniform bool uPerspective;
uniform vec2 uNearFar;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= uSize || p.y >= uSize) return;
    float d = texelFetch(uDepth, ivec3(p, uLayer), 0).r;
    imageStore(uOut, p, encodeMoments(momentDepth(d, uPerspective, uReversedZ, uNearFar.x, uNearFar.y)));
}
#elif defined(MIPS)
layout(MOMENT_FORMAT, binding = 1) uniform readonly image2D uIn;  // the level below

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= uSize || p.y >= uSize) return;
    ivec2 q = 2 * p;
    vec4 sum = imageLoad(uIn, q) + imageLoad(uIn, q + ivec2(1, 0));
    sum += imageLoad(uIn, q + ivec2(0, 1));
    sum += imageLoad(uIn, q + ivec2(1, 1));
    imageStore(uOut, p, sum * 0.25);
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
