// MSM, Hamburger 4 moments (Peters & Klein, "Moment Shadow Mapping", I3D 2015): depth's first four moments; the
// lookup bounds the lit share by the three-point distribution that matches them. 16-bit storage is unorm with the
// paper's optimized quantization (a 4x4 transform and an offset). uTechnique: x = moment bias, y = light-bleeding
// reduction, z = 1 for the quantized 16-bit encoding. CPU copy: renderer/shading/filters/msm_filter.cpp.
#include "shadow/techniques/chebyshev.glsl"

// The transform and its inverse as GLSL matrices (column c = the paper's row c): M * b is the paper's b * M.
const mat4 kMsmEncode = mat4(-2.07224649, 13.7948857237, 0.105877704, 9.7924062118,
                             32.23703778, -59.4683975703, -1.9077466311, -33.7652110555,
                             -68.571074599, 82.0359750338, 9.3496555107, 47.9456096605,
                             39.3703274134, -35.364903257, -6.6543490743, -23.9728048165);
const mat4 kMsmDecode = mat4(0.2227744146, 0.1549679261, 0.1451988946, 0.163127443,
                             0.0771972861, 0.1394629426, 0.2120202157, 0.2591432266,
                             0.7926986636, 0.7963415838, 0.7258694464, 0.6539092497,
                             0.0319417555, -0.1722823173, -0.2758014811, -0.3376131734);
const float kMsmOffset = 0.035955884801;

vec4 encodeMoments(float z) {
    float z2 = z * z;
    vec4 b = vec4(z, z2, z2 * z, z2 * z2);
    if (uTechnique.z == 0.0) return b;
    vec4 q = kMsmEncode * b;
    q.x += kMsmOffset;
    return q;
}

float momentShadow(vec4 stored, float z) {
    vec4 raw = stored;
    if (uTechnique.z != 0.0) {
        raw.x -= kMsmOffset;
        raw = kMsmDecode * raw;
    }
    vec4 b = mix(raw, vec4(0.5), uTechnique.x);
    // Cholesky factorization of the Hankel matrix of b, then the roots of the quadratic through the receiver.
    float l32d22 = -b.x * b.y + b.z;
    float d22 = -b.x * b.x + b.y;
    float squaredDepthVariance = -b.y * b.y + b.w;
    float d33d22 = dot(vec2(squaredDepthVariance, -l32d22), vec2(d22, l32d22));
    float invD22 = 1.0 / d22;
    float l32 = l32d22 * invD22;
    vec3 c = vec3(1.0, z, z * z);
    c.y -= b.x;
    c.z -= b.y + l32 * c.y;
    c.y *= invD22;
    c.z *= d22 / d33d22;
    c.y -= l32 * c.z;
    c.x -= dot(c.yz, b.xy);
    float p = c.y / c.z;
    float q = c.x / c.z;
    float r = sqrt(max(p * p * 0.25 - q, 0.0));
    float z1 = -p * 0.5 - r, z2 = -p * 0.5 + r;
    vec4 sw = z2 < z ? vec4(z1, z, 1.0, 1.0) : (z1 < z ? vec4(z, z1, 0.0, 1.0) : vec4(0.0));
    float quotient = (sw.x * z2 - b.x * (sw.x + z2) + b.y) / ((z2 - sw.y) * (z - z1));
    float shadowed = clamp(sw.z + sw.w * quotient, 0.0, 1.0);
    return reduceBleeding(1.0 - shadowed, uTechnique.y);
}
