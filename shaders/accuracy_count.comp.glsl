#version 450 core
// The GPU counter of the accuracy numbers (gpu_accuracy_counter.h): the tool's shadow factor S, read where the frame
// left it, against the cached exact reference, counted without reading the frame back. The C++ side defines STAGE
// and every constant below (class codes, count slots, group size), so the layouts have one source: the counter.
//   STAGE_COUNT     PIXELS_PER_INVOCATION pixels per invocation (counts in registers: few atomics): DESIGN.md's sets (the rule of computeMetrics in accuracy_metrics.cpp;
//                   the counter's test holds the two equal), sums of |S-V| and 1-S per group, each mismatched
//                   pixel's distance (its key for the edge error) and its index in a list, and the pixels whose
//                   distance the CPU must still decide (probing).
//   STAGE_FINISH    one group: the groups' sums added in double, the edge error's rank from the mismatched count,
//                   the histogram's dispatch size from the list's length.
//   STAGE_HISTOGRAM one invocation per listed pixel: 256-bin histogram of one byte of the three edge-error keys
//                   (texels, world units, screen pixels) among the keys that share the bytes picked so far.
//   STAGE_PICK      one group: the bin holding the rank, per key. Four HISTOGRAM + PICK rounds (bytes 3..0) give
//                   the nearest-rank percentile exactly, as the CPU's nth_element does.
layout(local_size_x = GROUP_SIZE) in;

layout(std430, binding = 0) buffer Words { uint words[]; };              // counts, then WORD_* slots
layout(std430, binding = 1) buffer Sums { double sums[]; };              // [0] sum |S-V|, [1] sum 1-S over acne
layout(std430, binding = 2) buffer Partials { dvec2 partials[]; };       // per group of STAGE_COUNT
layout(std430, binding = 3) buffer Keys { float keys[]; };               // per pixel: distance in texels, or -1
layout(std430, binding = 4) buffer Unresolved { uint unresolved[]; };    // pixels the CPU must decide
layout(std430, binding = 5) readonly buffer Reference { uvec4 reference[]; };  // visible, flipAt, probedTo bits; class | flags
layout(std430, binding = 6) readonly buffer Units { vec2 units[]; };     // world units per texel, screen px per texel
layout(std430, binding = 7) buffer Histogram { uint histogram[]; };      // 3 x 256
layout(std430, binding = 8) buffer Listed { uint listed[]; };            // the mismatched pixels with a key
layout(std430, binding = 9) buffer Dispatch { uint dispatchSize[3]; };   // STAGE_HISTOGRAM's groups

layout(binding = 0) uniform sampler2D uShadow;  // the tool's frame in the shadow view: S in r = g = b
uniform ivec2 uSize;          // view size; pixel i = row * width + x with row 0 at the TOP (the CPU's order)
uniform uint uPartials;       // number of groups STAGE_COUNT ran
uniform float uK;             // filter radius + 1 texel
uniform float uCap;           // distances are capped at the map's size
uniform float uLitBelow;      // kLitBelow
uniform float uShadowedAbove; // kVisibleStep
uniform double uWrongError;   // kWrongError
uniform bool uProbing;        // the boundary probes with rays: a far pixel's distance may still be unknown
uniform uint uPercent;        // kEdgeErrorPercentile
uniform int uShift;           // the byte of this HISTOGRAM / PICK round: 24, 16, 8, 0

bool nonFinite(float v) { return (floatBitsToUint(v) & 0x7F800000u) == 0x7F800000u; }
bool isNaNBits(float v) { return nonFinite(v) && (floatBitsToUint(v) & 0x007FFFFFu) != 0u; }
// Float bits in an order integers keep (negatives below positives).
uint orderBits(float v) {
    uint b = floatBitsToUint(v);
    return (b & 0x80000000u) != 0u ? ~b : b | 0x80000000u;
}

#if STAGE == STAGE_COUNT
shared uint groupCounts[COUNT_SLOTS];
shared dvec2 groupSums[GROUP_SIZE];
uint counts[COUNT_SLOTS];

void add(uint slot) { counts[slot] += 1u; }

// ShadowBoundary::distance(i, k) from what the boundary knew when it was uploaded; false when it must probe.
bool distanceOf(uvec4 r, out float d) {
    float visible = uintBitsToFloat(r.x), flipAt = uintBitsToFloat(r.y), probedTo = uintBitsToFloat(r.z);
    d = visible;
    if (visible <= uK) return true;
    if (flipAt <= uK) {
        d = flipAt;
        return true;
    }
    return !uProbing || probedTo >= uK;
}

// One pixel's part of the sets; returns its (|S-V|, 1-S if acne) for the sums.
dvec2 countPixel(uint i) {
    dvec2 sum = dvec2(0.0);
    float key = -1.0;
    uvec4 r = reference[i];
    uint cls = r.w & 0xFFu;
    if ((r.w & FLAG_ON_BOUNDARY) != 0u) add(C_BOUNDARY);
    int x = int(i % uint(uSize.x)), row = int(i / uint(uSize.x));
    vec4 px = texelFetch(uShadow, ivec2(x, uSize.y - 1 - row), 0);
    // The shadow view writes grey; the clear colour is not grey.
    bool covered = !isNaNBits(px.r) && !isNaNBits(px.g) && !isNaNBits(px.b) && px.r == px.g && px.g == px.b;
    if ((cls != CLASS_BACKGROUND) != covered) add(C_COVERAGE_MISMATCH);
    if (cls == CLASS_BACKGROUND) add(C_BACKGROUND);
    else if (cls == CLASS_NON_FINITE) add(C_NON_FINITE);
    else if (cls == CLASS_FACING_AWAY) add(C_FACING_AWAY);
    else {
        if (cls == CLASS_OUTSIDE_CONE) add(C_OUTSIDE_CONE);
        bool lit = cls == CLASS_LIT;
        if (!lit && covered && uintBitsToFloat(r.x) <= uK) add(C_SHADOWED_NEAR_EDGE);
        float s = px.r;
        if (covered && nonFinite(s)) add(C_NON_FINITE);
        else if (covered) {
            add(C_MEASURED);
            add(lit ? C_LIT : C_SHADOWED);
            double error = abs(double(s) - (lit ? 1.0lf : 0.0lf));
            sum.x = error;
            bool wrong = error >= uWrongError;
            if (wrong) add(C_WRONG);
            if (lit ? s < uLitBelow : s > uShadowedAbove) {
                add(C_MISMATCHED);
                float d;
                if (!distanceOf(r, d)) {
                    unresolved[atomicAdd(words[WORD_UNRESOLVED], 1u)] = i;
                } else {
                    d = min(d, uCap);
                    key = d;
                    listed[atomicAdd(words[WORD_LISTED], 1u)] = i;
                    bool beyondK = d > uK;
                    if (wrong && beyondK) add(C_WRONG_BEYOND_K);
                    if (!beyondK) add(C_MISMATCHED_WITHIN_K);
                    if (lit && beyondK) {
                        add(C_ACNE);
                        sum.y = 1.0lf - double(s);
                    }
                    if (!lit && beyondK) add(C_LEAK);
                }
            }
        }
    }
    keys[i] = key;
    return sum;
}

void main() {
    uint local = gl_LocalInvocationIndex;
    for (uint s = local; s < uint(COUNT_SLOTS); s += uint(GROUP_SIZE)) groupCounts[s] = 0u;
    for (int s = 0; s < COUNT_SLOTS; ++s) counts[s] = 0u;
    barrier();
    dvec2 sum = dvec2(0.0);
    uint count = uint(uSize.x) * uint(uSize.y);
    uint stride = gl_NumWorkGroups.x * uint(GROUP_SIZE);
    for (uint i = gl_GlobalInvocationID.x; i < count; i += stride) sum += countPixel(i);
    for (int s = 0; s < COUNT_SLOTS; ++s)
        if (counts[s] != 0u) atomicAdd(groupCounts[s], counts[s]);
    groupSums[local] = sum;
    barrier();
    for (uint width = uint(GROUP_SIZE) / 2u; width > 0u; width /= 2u) {
        if (local < width) groupSums[local] += groupSums[local + width];
        barrier();
    }
    if (local == 0u) partials[gl_WorkGroupID.x] = groupSums[0];
    for (uint s = local; s < uint(COUNT_SLOTS); s += uint(GROUP_SIZE))
        if (groupCounts[s] != 0u) atomicAdd(words[s], groupCounts[s]);
}

#elif STAGE == STAGE_FINISH
shared dvec2 groupSums[GROUP_SIZE];

void main() {
    uint local = gl_LocalInvocationIndex;
    dvec2 sum = dvec2(0.0);
    for (uint g = local; g < uPartials; g += uint(GROUP_SIZE)) sum += partials[g];
    groupSums[local] = sum;
    barrier();
    for (uint stride = uint(GROUP_SIZE) / 2u; stride > 0u; stride /= 2u) {
        if (local < stride) groupSums[local] += groupSums[local + stride];
        barrier();
    }
    if (local == 0u) {
        sums[0] = groupSums[0].x;
        sums[1] = groupSums[0].y;
        // nearestRankIndex: ceil(p n / 100) - 1, at least 0.
        uint n = words[C_MISMATCHED];
        uint rank = (uPercent * n + 99u) / 100u;
        for (int m = 0; m < 3; ++m) {
            words[WORD_RANK + m] = rank > 0u ? rank - 1u : 0u;
            words[WORD_PREFIX + m] = 0u;
        }
        dispatchSize[0] = (words[WORD_LISTED] + uint(GROUP_SIZE) - 1u) / uint(GROUP_SIZE);
        dispatchSize[1] = 1u;
        dispatchSize[2] = 1u;
    }
}

#elif STAGE == STAGE_HISTOGRAM
shared uint groupBins[3 * 256];

void main() {
    uint local = gl_LocalInvocationIndex;
    for (uint b = local; b < 768u; b += uint(GROUP_SIZE)) groupBins[b] = 0u;
    barrier();
    if (gl_GlobalInvocationID.x < words[WORD_LISTED]) {
        uint i = listed[gl_GlobalInvocationID.x];
        float d = keys[i];
        vec2 u = units[i];
        float values[3] = float[3](d, d * u.x, d * u.y);
        for (int m = 0; m < 3; ++m) {
            uint bits = orderBits(values[m]);
            // Only keys whose higher bytes match the bytes picked so far.
            if (uShift == 24 || (bits >> uint(uShift + 8)) == (words[WORD_PREFIX + m] >> uint(uShift + 8)))
                atomicAdd(groupBins[m * 256 + int((bits >> uint(uShift)) & 0xFFu)], 1u);
        }
    }
    barrier();
    for (uint b = local; b < 768u; b += uint(GROUP_SIZE))
        if (groupBins[b] != 0u) atomicAdd(histogram[b], groupBins[b]);
}

#elif STAGE == STAGE_PICK
void main() {
    uint m = gl_LocalInvocationIndex;
    if (m < 3u) {
        uint rank = words[WORD_RANK + m], before = 0u;
        for (uint b = 0u; b < 256u; ++b) {
            uint n = histogram[m * 256u + b];
            if (before + n > rank) {
                words[WORD_PREFIX + m] |= b << uint(uShift);
                words[WORD_RANK + m] = rank - before;
                break;
            }
            before += n;
        }
    }
    barrier();
    memoryBarrierBuffer();
    barrier();
    // Empty for the next round.
    for (uint b = m; b < 768u; b += uint(GROUP_SIZE)) histogram[b] = 0u;
}
#endif
