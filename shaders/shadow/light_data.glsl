// One light as the main pass sees it (std140 block uLights) and its view's depth convention. The CPU fills it in
// renderer/shading/main_pass.cpp.
struct LightData {
    mat4 viewProjection;  // directional / spot: render-origin-relative world -> light clip
    vec4 position;        // xyz: spot / point position (render-origin-relative); w: range, 0 = no limit
    vec4 direction;       // xyz: unit direction the light travels; w: cos(half cone) (spot)
    vec4 radiance;        // rgb: colour; w: intensity
    vec4 shadow;          // x: map array, y: layer (2D) or cube index, z: 1 / resolution, w: normal offset (texels)
    vec4 depth;           // x: near, y: far, z: texel world size (directional) or per unit of depth (spot, point),
                          // w: flags: 1 = reversed-Z (the map stores near 1, far 0; its sampler compares GEQUAL),
                          //    2 = receiver-plane depth bias
    vec4 views;           // a cascaded light: x = its first cascade in uCascades, y = how many (0: its one view);
                          // z: the light's size as a lookup spreads it (filter_technique.h's lightSpread; PCSS)
};
// Texture coordinates and window depth in the view's depth convention: GL's [-1, 1] clip depth, or reversed-Z's
// zero-to-one depth (near 1, far 0). The CPU's copy is LightSpace::textureOf.
bool reversedZ(LightData L) { return (int(L.depth.w) & 1) != 0; }

vec3 toLightTexture(LightData L, vec3 worldPosition) {
    vec4 clip = L.viewProjection * vec4(worldPosition, 1.0);
    vec3 ndc = clip.xyz / clip.w;
    return vec3(ndc.xy * 0.5 + 0.5, reversedZ(L) ? ndc.z : ndc.z * 0.5 + 0.5);
}

// Receivers beyond the far plane compare as if on it (far = 1, or 0 reversed).
float clampToFar(LightData L, float depth) { return reversedZ(L) ? max(depth, 0.0) : min(depth, 1.0); }

