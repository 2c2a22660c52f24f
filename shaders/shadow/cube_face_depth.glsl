// A point light's receiver depth in a cube face (the depth and the moments lookups both compare with it).
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
