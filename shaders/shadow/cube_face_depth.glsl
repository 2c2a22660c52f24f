// A point light's cube faces as its lookups read them: the lookup face's tangent frame (taps move across it) and the
// receiver's depth in the face a tap's direction selects (the depth, PCSS and moments lookups share both; the moments
// pass's cube blur moves its taps in the same frame). CPU mirror: renderer/shading/filters/cube_face_frame.cpp.
#include "shadow/light_data.glsl"
#include "shadow/view_select.glsl"

// The stored value of a cube face is that face's perspective depth, so the reference is the receiver's depth in the
// face the tap's direction selects: its distance along that face's axis, through the same near/far mapping.
float faceDepth(vec3 fromLight, vec3 tapDirection, LightData L) {
    vec3 axis = cubeFaceAxis(cubeFaceOf(tapDirection));
    float near = L.depth.x, far = L.depth.y;
    float z = max(dot(fromLight, axis), near);
    if (reversedZ(L)) return near * (far - z) / (z * (far - near));  // zero-to-one, near 1, far 0
    return ((far + near) / (far - near) - 2.0 * far * near / ((far - near) * z)) * 0.5 + 0.5;
}

// The lookup's face as a filter spreads taps over it: its two tangent axes (the other two world axes) and a texel's
// width there (2 / resolution at unit distance, times the lookup's distance along the face's axis, `major`).
struct CubeFaceFrame {
    vec3 fromLight;  // the lookup from the light
    vec3 s, t;
    float major;
    float texel;
};

// `texelStep`: 1 / the face's resolution (LightData.shadow.z; the moments pass's cube blur gives its own).
CubeFaceFrame cubeFaceFrame(vec3 fromLight, float texelStep) {
    vec3 a = abs(fromLight);
    int axis = cubeFaceOf(fromLight) / 2;
    CubeFaceFrame f;
    f.fromLight = fromLight;
    f.s = axis == 0 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    f.t = axis == 1 ? vec3(0.0, 0.0, 1.0) : vec3(0.0, 1.0, 0.0);
    f.major = max(a.x, max(a.y, a.z));
    f.texel = 2.0 * texelStep * f.major;
    return f;
}

CubeFaceFrame cubeFaceFrame(vec3 fromLight, LightData L) { return cubeFaceFrame(fromLight, L.shadow.z); }

// The direction of a tap `offsetTexels` across the face from the lookup: it may select a neighbouring face.
vec3 cubeFaceTap(CubeFaceFrame f, vec2 offsetTexels) {
    vec2 o = offsetTexels * f.texel;
    return f.fromLight + o.x * f.s + o.y * f.t;
}
