#pragma once
// The light's volume drawn as coloured lines over a main view: the ortho box of a directional light (plus its
// direction through the box's centre), or the spot light's pyramid (apex at the light, plus the cone's circle on the
// far plane). A cascaded light's cascades each in their own colour (shading/cascade_tints.h, as the cascade tint view),
// with the slice of the camera's frustum each answers for when the cascades follow a camera other than the view's.
// Lines are depth-tested against the view's depth buffer; the parts hidden behind geometry are drawn fainter, so the
// volume's shape stays readable while it is clear what lies in front.
#include "frame/frame_stats.h"
#include "frame/render_target.h"
#include "gl/gl_objects.h"
#include "light/light_space.h"

#include <glm/vec4.hpp>

#include <string>
#include <vector>

namespace shadowlab {

struct FrustumOverlayStyle {
    glm::vec4 color{1.0f, 0.78f, 0.15f, 1.0f};  // lines in front of the scene
    float hiddenAlpha = 0.3f;                   // opacity of the hidden parts; 0 hides them
};

// The 8 corners of the light's volume, render-origin relative: near plane then far plane, each in the order
// (-1,-1), (1,-1), (1,1), (-1,1) of the light's clip space.
std::vector<glm::dvec3> lightVolumeCorners(const LightSpace& light);

// Line segments (pairs of render-origin-relative points) that outline the light's volume.
std::vector<glm::dvec3> lightVolumeLines(const LightSpace& light);

// Light `light`'s volumes in the frame: its one view, or a point light's six cube faces (none without a view).
std::vector<LightSpace> lightVolumes(const FrameStats& stats, std::size_t light);

// Line segments that outline a cascade's slice of its camera's frustum (from its near to its far depth).
std::vector<glm::dvec3> cascadeSliceLines(const CascadeSlice& slice);

// Lines of one colour: pairs of render-origin-relative points.
struct OverlayLines {
    std::vector<glm::dvec3> points;
    glm::vec4 color{1.0f};
};

// What the overlay draws for light `light` of the frame: each view's volume, a cascade's in its tint and any other in
// `color`; with `slices`, each cascade's slice of the camera frustum too (in its tint; worth drawing only when the
// cascades' camera is not the view's, whose frustum is the picture's edges).
std::vector<OverlayLines> lightOverlayLines(const FrameStats& stats, std::size_t light, const glm::vec4& color,
                                            bool slices);

class LightFrustumOverlay {
public:
    LightFrustumOverlay();  // needs a current GL 4.5 context; throws std::runtime_error if the shader does not build

    // Draws over `target`, which must hold the frame `stats` describes (its colour and depth). Returns "" or why
    // nothing was drawn (the frame failed, or its matrices are not finite). Leaves depth writes on and blending off.
    std::string draw(const FrameStats& stats, RenderTarget& target, const FrustumOverlayStyle& style = {});
    // The same for the given light spaces (render-origin relative, as the frame's views): one light's view, or a
    // point light's six cube faces, whose frusta together outline the cube around its range. None: nothing drawn.
    std::string draw(const FrameStats& stats, const std::vector<LightSpace>& volumes, RenderTarget& target,
                     const FrustumOverlayStyle& style = {});
    // The same for lines in their own colours (style.color unused), e.g. lightOverlayLines's.
    std::string draw(const FrameStats& stats, const std::vector<OverlayLines>& lines, RenderTarget& target,
                     const FrustumOverlayStyle& style = {});

private:
    gl::Program program_;
    gl::VertexArray vertexArray_;
    gl::Buffer vertices_;
    GLint viewProjectionLocation_ = -1;
    GLint colorLocation_ = -1;
};

}  // namespace shadowlab
