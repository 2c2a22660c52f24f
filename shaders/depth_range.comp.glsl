#version 450 core
// Min and max of the depths written (below 1) over a whole depth texture (a shadow map: what casters wrote; the
// camera's depth: what it sees), as float bits: non-negative floats order
// like their bit patterns, so integer atomics find them. Each invocation reads a block of BLOCK x BLOCK texels
// (BLOCK is defined by the renderer). uChannel >= 0: the range of that channel of any float texture (the map
// viewer's moments), every finite value counted, in ordered bits (negative values too).
layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 0) uniform sampler2D uDepth;
uniform bool uReversedZ;  // near 1, far 0: measured as 1 - stored, the unit the picture shows
uniform int uChannel;     // -1: depth, as above; 0..3: that channel, every finite value
layout(std430, binding = 0) buffer Range {
    uint minBits;  // starts at 0xFFFFFFFF: still that when no caster wrote
    uint maxBits;  // starts at 0
};

// A float's bits reordered so that unsigned order is float order for either sign (the CPU undoes it).
uint orderedBits(float v) {
    uint bits = floatBitsToUint(v);
    return (bits & 0x80000000u) != 0u ? ~bits : bits | 0x80000000u;
}

shared uint groupMin;
shared uint groupMax;

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        groupMin = 0xFFFFFFFFu;
        groupMax = 0u;
    }
    barrier();
    ivec2 size = textureSize(uDepth, 0);
    ivec2 base = ivec2(gl_GlobalInvocationID.xy) * BLOCK;
    uint localMin = 0xFFFFFFFFu, localMax = 0u;
    for (int y = 0; y < BLOCK; ++y)
        for (int x = 0; x < BLOCK; ++x) {
            ivec2 p = base + ivec2(x, y);
            if (p.x >= size.x || p.y >= size.y) continue;
            if (uChannel >= 0) {
                float v = texelFetch(uDepth, p, 0)[uChannel];
                if (isnan(v) || isinf(v)) continue;
                localMin = min(localMin, orderedBits(v));
                localMax = max(localMax, orderedBits(v));
                continue;
            }
            float d = texelFetch(uDepth, p, 0).r;
            if (uReversedZ) d = 1.0 - d;
            if (d < 1.0) {
                uint bits = floatBitsToUint(max(d, 0.0));
                localMin = min(localMin, bits);
                localMax = max(localMax, bits);
            }
        }
    atomicMin(groupMin, localMin);
    atomicMax(groupMax, localMax);
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        atomicMin(minBits, groupMin);
        atomicMax(maxBits, groupMax);
    }
}
