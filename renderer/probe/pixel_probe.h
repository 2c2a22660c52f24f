#pragma once
// "Why is THIS pixel dark?": for one main-view pixel of a frame, the surface point (double), its place in the
// shadow map, every filter tap's stored depths and comparisons, each bias term at this surface, and the shadow factor
// S recomputed on the CPU next to the GPU's own value at that pixel. Knows no window, UI or CLI.
#include "accuracy/accuracy_meter.h"
#include "accuracy/gbuffer_pass.h"
#include "frame/renderer.h"
#include "light/depth_bias.h"
#include "reference/surface_samples.h"
#include "shading/filters/filter_technique.h"

#include <glm/ext/vector_double2.hpp>
#include <glm/ext/vector_int2.hpp>

#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

// One stored texel a tap compares against.
struct ProbeTexel {
    glm::ivec2 texel{0};     // after the address mode (row 0 = the map's bottom, as GL stores it); see `border`
    int face = -1;           // a point light's tap read across a cube edge: the face it reads (-1: the lookup's)
    bool border = false;     // outside the map with clamp-to-border: compared against sampler.borderDepth
                             // (1 - it for reversed-Z)
    double stored = 0.0;     // the depth the map holds there (bias of its caster included), in the map's convention
    double weight = 1.0;     // bilinear weight inside its tap (1 for a nearest tap)
    bool lit = false;        // receiver depth <= stored (GL_LEQUAL; reversed-Z: >=, GL_GEQUAL)
    bool uncertain = false;  // |receiver - stored| is within float rounding: the GPU may decide either way
};

struct ProbeTap {
    glm::dvec2 offsetTexels{0.0};  // from filter_taps.h, as the shader adds it
    glm::dvec2 texelCoord{0.0};    // where it samples, in texels (texture coordinate x resolution)
    bool bilinear = false;
    std::vector<ProbeTexel> texels;  // 1 (nearest) or 4 (bilinear)
    double value = 0.0;            // the tap's result in [0, 1]
    double low = 0.0, high = 0.0;  // what the GPU can get, its uncertain comparisons and texel choice either way
};

// The bias at this surface, in the units depth_bias.h reports.
struct ProbeBias {
    double depthSlope = 0.0;  // m of the surface's triangle in the map (window depth per texel); 0 if edge-on
    double step = 0.0;        // r at the receiver's depth (the format's minimum resolvable difference)
    BiasTerm constant;        // DepthBias x r
    BiasTerm slope;           // SlopeScaledDepthBias x m
    BiasTerm clamp;           // DepthBiasClamp (depth 0 = none)
    BiasTerm total;           // what the surface gets as a caster: min(constant + slope, clamp)
    double normalOffsetWorld = 0.0;   // the lookup's move along the normal, world units
    double normalOffsetTexels = 0.0;  // the same, in this surface's texels (the setting)
};

struct PixelProbeReport {
    bool ok = false;
    std::string error;  // when !ok: why (pixel outside the view, background, a frame that failed)
    int x = 0, y = 0;   // pixel, y down from the top
    int width = 0, height = 0;

    glm::dvec3 world{0.0};           // the surface point, world coordinates (double)
    glm::dvec3 geometricNormal{0.0}; // toward the camera
    glm::dvec3 shadingNormal{0.0};   // the main pass's interpolated normal, flipped on back faces
    bool frontFacing = true;
    int instance = -1, triangle = -1;
    std::string meshName;
    glm::dvec3 lookupWorld{0.0};     // world + normal offset: where the map is read
    glm::dvec3 lightView{0.0};       // the lookup in the light's view space (x, y across, z toward the light)
    glm::dvec3 lightTexture{0.0};    // texture coordinates (x, y in [0, 1] inside the map) and window depth z
    glm::dvec2 texelCoord{0.0};      // lightTexture.xy x resolution
    glm::ivec2 texel{0};             // the texel it falls in
    bool insideMap = true;           // lightTexture.xy within [0, 1]
    bool inCone = true;              // spot: inside the cone (else S = 0)
    std::size_t light = 0;           // the probed light's index in the frame's effective lights (capture's `lightIndex`)
    LightType lightType = LightType::Directional;
    int face = -1;                   // a point light: the cube face the lookup falls in (GL order +X,-X,+Y,-Y,+Z,-Z)
    std::string viewName;            // the shadow view probed, e.g. "light 0", "light 0 +X" (the light as captured)
    std::string cascade;             // a cascaded light: the cascade probed ("cascade:1"); "" otherwise
    int viewCount = 1;               // the light's views (6 cube faces, its cascades)
    bool viewChosen = false;         // the view was asked for (at()'s `view`), not the one holding the point
    std::string blendNote;           // a cascade's blend band, beyond the shadow distance or a --view the GPU does not
                                     // read here: how the GPU's S relates to the taps below
    bool reversedZ = false;          // the map's depth convention: near 1, far 0 (depths below are as stored)
    double receiverDepth = 0.0;      // what each tap compares: z clamped to the far plane (fixed point: to [0, 1])
    double depthUncertainty = 0.0;   // float rounding of the GPU's receiver depth, in depth
    glm::dvec2 receiverPlane{0.0};   // receiver-plane bias: d(depth)/d(texel) each tap adds (0 when not applied)

    int resolution = 0;
    DepthFormat format = DepthFormat::D32F;
    FilterSettings filter;
    AddressMode addressMode = AddressMode::ClampToBorder;
    std::vector<ProbeTap> taps;
    ProbeBias bias;
    // A moments technique: the one bilinear lookup of stored moments (its four texels are taps[0], their `stored` the
    // first moment), the filtered moments, the receiver's depth in the moments' near-0 convention, and the lookup in
    // words (mean, variance, the bound: the technique's explain).
    bool momentLookup = false;
    glm::dvec4 moments{0.0};
    double momentDepth = 0.0;   // linear for perspective views (shaders/shadow/linear_depth.glsl)
    double momentLevel = -1.0;  // filter.momentMips: the mip level read (trilinear), from the pixel's footprint; -1 none
    std::string momentText;
    // A technique with a lookup of its own (PCSS): its search in numbers and words (the taps it then compares are
    // `taps`; none when it found no blocker: S = 1).
    bool ownLookup = false;
    OwnLookupResult search;

    double shadowCpu = 0.0;   // S recomputed here from the stored texels
    double shadowLow = 0.0, shadowHigh = 0.0;  // range the GPU may give (uncertain comparisons, filter weights)
    double shadowGpu = 0.0;   // S as the main pass wrote it at this pixel
    double tolerance = 0.0;   // filter precision: the bilinear weights' sub-texel steps (0 for nearest taps)
    bool agrees = false;      // shadowGpu within [shadowLow - tolerance, shadowHigh + tolerance] (true when !compared)
    bool compared = true;     // false: a view chosen with at()'s `view` that the GPU does not read (alone) here
    int uncertainComparisons = 0;

    // A cascade's blend band: the GPU's S = mix(S of this view, S of the next, blendWeight). `blend` holds the next
    // cascade's own lookup of the same surface (its taps, bias and S in its texels; its own `blend` empty), and
    // shadowCpu / shadowLow / shadowHigh above are the mix; shadowView is this view's S alone.
    std::vector<PixelProbeReport> blend;  // 0 or 1
    double blendWeight = 0.0;
    double shadowView = 0.0;

    // From an accuracy measurement of the same view, when one was given.
    bool measured = false;
    PixelClass exact = PixelClass::Background;
    MismatchCause cause = MismatchCause::None;
    float measuredShadow = 0.0f;
};

class PixelProbe {
public:
    // Needs a current GL 4.5 context; throws std::runtime_error if the G-buffer's shaders do not build.
    PixelProbe() = default;

    // Renders the frame to probe (the shadow factor into a float target, and the G-buffer) with `renderer`, whose
    // shadow map is the one probed. `settings` must hold exactly the light to probe (light_isolation.h's
    // isolateLight): the GPU's S is then that light's alone; several lights are refused, never light 0 silently. "" or why not. Keep renderer and scene unchanged until the last at().
    // `lightIndex`: which light of the caller's frame it is, for the report's label.
    std::string capture(Renderer& renderer, const Scene& scene, const Settings& settings, const Camera& camera,
                        int width, int height, std::size_t lightIndex = 0);
    bool captured() const { return renderer_ != nullptr; }

    // One pixel of the captured frame (y down from the top). `measured`: an accuracy report of the same view (its
    // exact visibility and cause are copied), or null. `view`: an index into views() to look up in instead of the
    // view holding the point (the selection's; in a blend band both cascades it mixes); the GPU's S is then compared
    // only when it is the view the GPU reads there alone.
    PixelProbeReport at(int x, int y, const AccuracyReport* measured = nullptr,
                        std::optional<std::size_t> view = std::nullopt) const;

    // The captured light's views (what `--view` chooses among: views/shadow_view.h's findView).
    const std::vector<ShadowView>& views() const { return views_; }

    const FrameStats& stats() const { return stats_; }
    const SurfaceSamples& samples() const { return samples_; }

private:
    struct Surface;
    // View `view`'s lookup of the surface: r's view, lookup, taps, bias and S fields. A point light's face follows the
    // lookup (after the normal offset) unless `forced`.
    // `search`: a technique with a lookup of its own takes this search outcome instead of its mirror's (the other
    // outcomes rounding allows, each bounded in turn).
    void lookupIn(PixelProbeReport& r, std::size_t view, bool forced, const Surface& s,
                  const OwnLookupResult* search = nullptr) const;

    GBufferPass gbuffer_;
    RenderTarget target_;
    const Renderer* renderer_ = nullptr;
    const Scene* scene_ = nullptr;
    Settings settings_;
    std::size_t lightIndex_ = 0;
    Camera camera_;
    FrameStats stats_;
    std::vector<ShadowView> views_;          // the light's views in the frame (frameViewsOf)
    std::vector<std::size_t> viewStats_;     // each one's index into stats_.views
    SurfaceSamples samples_;
    std::vector<float> shadow_;  // row 0 = top
    // A point light's faces, each read back whole on first use (PCSS's taps cross faces): row 0 = bottom.
    mutable std::vector<std::vector<float>> cubeFaces_;
    float cubeDepth(int face, int x, int y) const;
};

// The texel GL reads for integer coordinate i under the address mode; nullopt = the border (clamp-to-border only).
std::optional<int> addressTexel(int i, int resolution, AddressMode mode);

// The stored depth of texels [x0, x0+w) x [y0, y0+h) of a shadow map (row 0 = bottom), read back from the GPU.
std::vector<float> readShadowMapRect(const ShadowMap& map, int x0, int y0, int w, int h);

}  // namespace shadowlab
