#version 450 core
// The moments pass (renderer/shadow/moments_pass.cpp), one layer of one view at a time:
//   CONVERT: the depth map's texels -> the technique's moments (encodeMoments, its file is "alias:technique") of the
//            depth in the near-0 convention moments use (shadow/linear_depth.glsl: linear for perspective views);
//   BLUR:    one direction of the separable box blur (uDirection), edge texels repeated (a caster touching the map's
//            edge keeps its moments; the clear value is not mixed in);
//   MIPS:    one mip level from the one below (level 1 from the unblurred moments: it runs before the blur): each
//            texel the mean of the 2x2 texels under it that hold a caster (filter.momentMips).
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
layout(MOMENT_FORMAT, binding = 1) uniform readonly image2D uIn;  // the level below, unblurred (the blur runs after)
uniform vec4 uEmpty;  // the stored moments of "no caster" (a cleared texel: the far plane; moments_mirror: emptyMoments)

// A texel that holds "no caster": its first moment is the far plane's (within a storage step; moments_mirror.cpp's
// isEmptyMoments is the CPU copy).
bool emptyMoments(vec4 m) { return abs(m.x - uEmpty.x) <= 1e-3 * max(1.0, abs(uEmpty.x)); }

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= uSize || p.y >= uSize) return;
    // The mean of the 2x2 texels under this one that hold a caster; "no caster" only where none does. A receiver whose
    // footprint reaches past the casters' outline (its own surface ends there) then reads the moments of what is in
    // the map, not the far plane's (which pulled the mean past a contact shadow's receiver: builtin:room's walls).
    ivec2 q = 2 * p;
    vec4 sum = vec4(0.0);
    float n = 0.0;
    for (int i = 0; i < 4; ++i) {
        vec4 m = imageLoad(uIn, q + ivec2(i & 1, i >> 1));
        if (emptyMoments(m)) continue;
        sum += m;
        n += 1.0;
    }
    imageStore(uOut, p, n > 0.0 ? sum / n : uEmpty);
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
