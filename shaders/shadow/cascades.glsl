// The shadow factor of a directional light through its cascades: the cascade that holds the pixel (by its depth in
// front of the camera, shadow/view_select.glsl's selectCascade), faded into the next one in its blend band. Each
// cascade is the light's 2D lookup with that cascade's matrix, layer and texel size, so the normal offset and the
// receiver plane (in texels) keep their meaning in every cascade. The CPU fills the block in
// renderer/shading/main_pass.cpp.
#include "shadow/light_data.glsl"
#include "shadow/lookup.glsl"
#include "shadow/view_select.glsl"

#if CASCADES > 0 && MAP_ARRAYS_2D > 0
struct CascadeData {
    mat4 viewProjection;  // render-origin-relative world -> the cascade's light clip
    vec4 slice;           // x: far depth, y: blend start (depths in front of the camera), z: layer, w: texel world size
};
layout(std140, binding = 1) uniform Cascades { CascadeData uCascades[CASCADES]; };
// The first cascaded light's choice at this pixel, for the cascade tint and texel density views.
int gCascadeView = -1, gCascadeNext = -1;
float gCascadeWeight = 0.0, gCascadeTexel = 0.0;

// The light as cascade `c` sees it.
LightData cascadeView(LightData L, int c) {
    L.viewProjection = uCascades[c].viewProjection;
    L.shadow.y = uCascades[c].slice.z;
    L.depth.z = uCascades[c].slice.w;
    return L;
}

// `position`: the pixel's render-origin-relative position; `normalStep`: its unit normal times the light's normal
// offset in texels (zero without NORMAL_OFFSET); the camera's position and unit viewing direction measure its depth.
float cascadedShadow(LightData L, vec3 position, vec3 normalStep, vec3 cameraPosition, vec3 cameraForward) {
    int first = int(L.views.x), count = int(L.views.y);
    vec4 farDepths = vec4(0.0), blendStarts = vec4(0.0);
    for (int i = 0; i < 4; ++i)
        if (i < count) {
            farDepths[i] = uCascades[first + i].slice.x;
            blendStarts[i] = uCascades[first + i].slice.y;
        }
    CascadeChoice choice = selectCascade(dot(position - cameraPosition, cameraForward), farDepths, blendStarts, count);
    if (gCascadeView < 0 && gCascadeNext < 0 && gCascadeTexel == 0.0) {
        gCascadeView = choice.view;
        gCascadeNext = choice.next;
        gCascadeWeight = choice.weight;
        gCascadeTexel = choice.view >= 0 ? uCascades[first + choice.view].slice.w : -1.0;
    }
    if (choice.view < 0) return 1.0;  // beyond the shadow distance: lit
    LightData C = cascadeView(L, first + choice.view);
    float shadow = shadow2D(C, position + normalStep * C.depth.z, C.direction.xyz, C.depth.z);
    if (choice.next >= 0 && choice.weight > 0.0) {
        LightData N = cascadeView(L, first + choice.next);
        shadow = mix(shadow, shadow2D(N, position + normalStep * N.depth.z, N.direction.xyz, N.depth.z), choice.weight);
    }
    return shadow;
}
#endif
