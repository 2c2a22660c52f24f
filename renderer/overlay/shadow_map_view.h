#pragma once
// A picture of the shadow map for display: the depth texture turned into an RGBA8 texture of any size, with
// contrast control (auto: stretched over the depths casters wrote, measured on the GPU only when the map changed;
// full [0,1]; manual min/max), optional linearization of a spot light's perspective depth, zoom and pan (a uv
// rectangle, see map_zoom_pan.h), and a texel grid once a texel covers kGridMinTexelPixels view pixels.
// Grey goes from black (near the light) to white (far); texels no caster wrote (depth 1) are shown in blue. A
// reversed-Z map (near 1, far 0) is shown as 1 - stored depth, so near is dark in both conventions and the contrast
// range is in that unit. A moments technique's map can be shown as one of its stored moments instead (channel 1..4 of
// the view's layer of the moments array, after the blur): grey from the channel's least value (black) to its greatest
// (white) over the whole layer in auto contrast; no texel is "no caster" there (the blur spreads casters' moments).
#include "frame/render_target.h"
#include "gl/depth_range_reduction.h"
#include "gl/gl_objects.h"
#include "light/light_space.h"
#include "overlay/map_zoom_pan.h"
#include "shadow/moments_pass.h"
#include "shadow/shadow_map.h"

#include <cstdint>
#include <optional>
#include <string>

namespace shadowlab {

enum class DepthContrast { Auto, Full, Manual };

struct ShadowMapViewOptions {
    DepthContrast contrast = DepthContrast::Auto;
    float manualMin = 0.0f;  // manual contrast, in the shown unit (stored depth, or linear depth when linearized)
    float manualMax = 1.0f;
    bool linearize = false;  // spot lights: show distance from the light between near and far, not stored depth
    UvRect visible;          // the part of the map shown (zoom and pan)
    bool texelGrid = true;   // draw the grid when zoomed in far enough
    int channel = 0;         // 0: stored depth; 1..4: that stored moment (render's `moments` says where)

    bool operator==(const ShadowMapViewOptions&) const = default;
};

// The range the picture stretched to black..white, in the shown unit.
struct ShownDepthRange {
    float min = 0.0f;
    float max = 1.0f;
    bool anyCaster = false;  // auto: whether any texel was written below depth 1
};

inline constexpr double kGridMinTexelPixels = 8.0;

// Stored depth [0,1] -> linear depth in [0,1] between the light's near (0) and far (1) planes. Directional
// (orthographic) depth is already linear.
double linearLightDepth(const LightSpace& light, double storedDepth);

class ShadowMapView {
public:
    ShadowMapView();  // needs a current GL 4.5 context; throws std::runtime_error if a shader does not build

    // Draws the picture at width x height. `mapRedrawn`: the shadow pass ran since the last call (FrameStats::
    // shadowPass.ran); auto contrast re-measures the map only then, or when the map was reallocated. Returns "" or
    // why nothing was drawn (no map yet, bad size, manual min >= max); the previous picture is kept then.
    // When neither the map nor anything else changed since the last picture, it is kept without drawing.
    // options.channel > 0 shows that moment of `moments` (the view's moments layer, whose contents `mapRedrawn` then
    // also covers): refused when there is none or it holds fewer channels.
    std::string render(const ShadowMap& map, const LightSpace& light, bool mapRedrawn,
                       const ShadowMapViewOptions& options, int width, int height,
                       const MomentsLayer* moments = nullptr);

    GLuint texture() const { return target_.colorTexture(); }  // RGBA8, row 0 = bottom (show it flipped in ImGui)
    int width() const { return target_.width(); }
    int height() const { return target_.height(); }
    std::vector<std::uint8_t> readPixels() const { return target_.readColor(); }

    ShownDepthRange shownRange() const { return shown_; }
    bool gridShown() const { return gridShown_; }
    bool redrawn() const { return redrawn_; }  // whether the last render() call drew (false: picture reused)

    // One stored depth read back from the map (for hover); nullopt off the map or when there is none.
    std::optional<float> depthAt(const ShadowMap& map, int texelX, int texelY) const;

private:
    void measureWrittenRange(const ShadowMap& map, bool reversedZ);
    void measureChannelRange(int channel);
    void viewMomentsLayer(const MomentsLayer& layer);  // momentsView_ shows that layer

    // Everything the picture depends on besides the map's contents.
    struct Inputs {
        ShadowMapViewOptions options;
        int width = 0, height = 0;
        GLuint mapTexture = 0;
        std::uint64_t mapGeneration = 0;
        bool perspective = false;
        double nearPlane = 0.0, farPlane = 0.0;
        bool reversedZ = false;
        GLuint momentsTexture = 0;
        int momentsLayer = 0;
        std::uint64_t momentsGeneration = 0;
        bool operator==(const Inputs&) const = default;
    };

    struct DisplayUniforms {
        GLint uvMin = -1, uvMax = -1, viewSize = -1, range = -1, linearize = -1, nearFar = -1, gridTexelPixels = -1,
              reversedZ = -1, channel = -1;
    };

    gl::Program displayProgram_;
    DisplayUniforms uniforms_;  // looked up once
    gl::VertexArray emptyVertexArray_;
    gl::Sampler rawSampler_;     // nearest, no comparison: reads stored depth (and stored moments)
    gl::Texture momentsView_;    // the shown moments layer as a plain 2D texture (a texture view)
    MomentsLayer momentsViewOf_;  // what momentsView_ views
    DepthRangeReduction rangeReduction_;  // auto contrast: the depths casters wrote
    RenderTarget target_;
    std::optional<float> writtenMin_, writtenMax_;  // measured range; empty when no caster wrote
    bool rangeStale_ = true;                 // the map changed since the range was measured
    std::uint64_t measuredGeneration_ = 0;
    bool measuredReversedZ_ = false;
    int measuredChannel_ = 0;  // 0: the range is the depth's; k: moment k's
    MomentsLayer measuredMoments_;  // ... of this layer
    ShownDepthRange shown_;
    bool gridShown_ = false;
    std::optional<Inputs> drawn_;  // what the current picture shows
    bool redrawn_ = false;
};

}  // namespace shadowlab
