#version 450 core
// The moments pass's blur of a point light's cube (renderer/shadow/moments_pass.cpp), across its faces' edges: a
// texel is the direction of its centre, and its taps move from there by direction in the lookups' cube-face frame
// (shadow/cube_face_depth.glsl), so a tap beyond a face's edge reads the neighbouring face's nearest texel (the
// sampler picks face and texel, as for the lookups). Separable, the same weights as moments.comp.glsl's blur:
//   FIRST:  one face's raw moments blurred along its frame's s (uAxis 0) or t (uAxis 1), into that cube of the
//           temporary cube array (the t blur only where the second pass reads it: within uRadius of the edges of
//           the faces whose t is a crossing neighbour's s, the +-y faces; moments_pass.cpp picks them);
//   second: along the frame's t, reading the first pass's blur along this face's s: on its own face that is its s
//           blur; on a neighbour face, the one of its two blurs along the same world axis (the shared edge's).
// At a corner of the cube the second pass's taps beyond an edge read a neighbour's first-pass blur, which itself
// crosses that neighbour's other edge into the third face: no texel is clamped or left out.
// CPU mirror: renderer/shading/filters/moments_mirror.cpp (momentsOfCube).
layout(local_size_x = 8, local_size_y = 8) in;
layout(MOMENT_FORMAT, binding = 0) uniform writeonly image2D uOut;  // the written face (a layer of a cube array)
uniform samplerCubeArray uIn;  // read at level 0 with a nearest sampler
uniform int uSize;             // the faces' resolution
uniform mat3 uFace;            // the written face's s and t directions and its axis (OpenGL 4.5, table 8.19)
uniform int uRadius;
uniform float uWeights[32];  // uWeights[|i|] for the tap i texels away (shading/filters: blurWeights)
#ifdef FIRST
uniform int uCube;  // the light's cube in the moments array
uniform int uAxis;  // 0: along the frame's s, 1: along its t
#endif

#include "shadow/cube_face_depth.glsl"

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (p.x >= uSize || p.y >= uSize) return;
    float step = 1.0 / float(uSize);
    vec2 c = (vec2(p) + 0.5) * (2.0 * step) - 1.0;
    CubeFaceFrame frame = cubeFaceFrame(uFace[2] + c.x * uFace[0] + c.y * uFace[1], step);
    vec4 sum = vec4(0.0);
#ifdef FIRST
    if (uAxis == 1 && min(min(p.x, p.y), uSize - 1 - max(p.x, p.y)) > uRadius) return;
    vec2 along = uAxis == 0 ? vec2(1.0, 0.0) : vec2(0.0, 1.0);
    for (int i = -uRadius; i <= uRadius; ++i)
        sum += uWeights[abs(i)] * textureLod(uIn, vec4(cubeFaceTap(frame, float(i) * along), float(uCube)), 0.0);
#else
    for (int i = -uRadius; i <= uRadius; ++i) {
        vec3 tap = cubeFaceTap(frame, vec2(0.0, float(i)));
        float blur = abs(dot(cubeFaceFrame(tap, step).s, frame.s)) > 0.5 ? 0.0 : 1.0;  // the tap's face's s or t
        sum += uWeights[abs(i)] * textureLod(uIn, vec4(tap, blur), 0.0);
    }
#endif
    imageStore(uOut, p, sum);
}
