#version 450
// The Vulkan twin of shaders/shadow_depth.vert.glsl for the lavapipe check: the same float arithmetic, then GL's
// [-1,1] clip depth remapped to Vulkan's [0,1] (z' = 0.5 (z + w)), which keeps the window depth unchanged.
// remapDepth false: the pipeline keeps GL's [-1,1] clip depth (VK_EXT_depth_clip_control negativeOneToOne).
layout(constant_id = 0) const bool remapDepth = true;
layout(location = 0) in vec3 inPosition;
layout(push_constant) uniform Push {
    mat4 lightViewProjection;  // ShadowLab's light matrix (GL clip), render-origin-relative world -> clip
    mat4 model;                // object -> render-origin-relative world
} pc;

void main() {
    vec4 clip = pc.lightViewProjection * (pc.model * vec4(inPosition, 1.0));
    if (remapDepth) clip.z = 0.5 * (clip.z + clip.w);
    gl_Position = clip;
}
