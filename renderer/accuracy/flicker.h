#pragma once
// Flicker (DESIGN.md, "Accuracy", version 2): the share of pixels whose shadow factor S changes between two frames
// while the exact visibility V does not, the camera or a light moving by a (sub-texel) step per frame (motion.h).
//
// What is compared: the SAME surface points in both frames of a pair, so a pixel that merely sees another point after
// the camera moved is not flicker. For the pair (f, f+1) the frame-(f+1) camera is rendered with frame f's light and
// views and with frame f+1's: S_prev / V_prev and S_cur / V_cur belong to identical pixels and points (V from the
// accuracy meter's exact reference, S from the tool's own frame). A light motion keeps the camera: frames f and f+1
// are the pair (one measurement per frame). A camera motion keeps the light: where the light's views do not follow
// the camera (scene fit, cube faces) both halves are frame f+1 itself and flicker is exactly 0; where they do
// (cascades) the first half is frame f+1's camera shaded with frame f's cascades, chosen by frame f's depths
// (AccuracyMeter::measure's shadowCamera: two measurements per frame, one reference), so a fit whose texel grid moves
// with the camera flickers. Each pair records how many shadow views the renderer's planner re-rendered for frame f+1
// (FrameStats::views): 0 under camera motion shows the maps really were kept; > 0 with cascades shows they followed.
//
// At a pixel measured in both halves (the meter's rules: OutOfRange, background, culled faces are not):
//   flicker     = V_prev == V_cur and S crosses 0.5 (the state flips: the threshold of wrong pixels)
//   V changed   = V_prev != V_cur (the shadow truly moved)
//   |dS| > 1/8  = V_prev == V_cur and |S_cur - S_prev| > 1/8 (a visible change short of a flip; secondary)
//   mean |dS|   = mean |S_cur - S_prev| over the pixels where V did not change
// Shares are percentages of the pixels measured in both halves. Knows no window, UI or CLI.
#include "accuracy/accuracy_meter.h"
#include "accuracy/accuracy_overlay.h"
#include "accuracy/motion.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

inline constexpr float kFlickerFlip = 0.5f;          // S on either side of this is a different shadow state
inline constexpr float kFlickerVisibleDelta = 0.125f;  // the secondary figure's |dS|

// One pair's counts (pixels measured in both halves) and figures.
struct FlickerCounts {
    std::size_t measured = 0;
    std::size_t flicker = 0;
    std::size_t vChanged = 0;
    std::size_t visibleDelta = 0;  // |dS| > 1/8 while V did not change
    double flickerPercent = 0.0;
    double vChangedPercent = 0.0;
    double visibleDeltaPercent = 0.0;
    double meanAbsDeltaS = 0.0;  // over measured pixels where V did not change
};

// What one half of a pair is at each pixel (row 0 = top): the meter's verdict, S and whether it is measured.
struct FlickerHalf {
    const std::vector<PixelClass>* classes = nullptr;
    const std::vector<float>* shadow = nullptr;
    const std::vector<std::uint8_t>* measured = nullptr;
};

// Counts one pair (both halves of the same size, at the same pixels and points); `flickering` (optional) gets 1 where
// a pixel flickers. No GL: unit-testable on synthetic buffers.
FlickerCounts compareFlickerPair(const FlickerHalf& previous, const FlickerHalf& current,
                                 std::vector<std::uint8_t>* flickering = nullptr);

struct FlickerPair {
    int from = 0;  // frames `from` and `from` + 1
    FlickerCounts counts;
    std::size_t shadowViewsRendered = 0;  // by the planner for frame from + 1 (camera motion: always 0)
};

struct FlickerFrame {
    AccuracyNumbers numbers;  // the usual metrics of this frame (its camera and light)
    std::size_t shadowViewsRendered = 0;
    AccuracyCost cost;        // what measuring it cost (a light motion traces new rays every frame)
};

struct FlickerReport {
    bool ok = false;
    bool cancelled = false;
    std::string error;  // when !ok: why (names the option or key)
    std::vector<std::string> warnings;
    Motion motion;
    std::size_t lightIndex = 0;  // = motion.light
    LightType lightType = LightType::Directional;
    // The step in texels of the light's map: camera: the step over the texel's world size (directional: exact; spot /
    // point: at the scene centre's distance); camera turn: the same for the looked-at point's sweep (its distance x
    // the angle); light: the largest shift in the map of the scene's centre or a bounding-box corner inside it.
    double stepTexels = 0.0;
    double texelWorldSize = 0.0;
    // A cascaded light: the step in each cascade's texels, nearest first (camera: the step over the cascade's texel;
    // camera turn: the looked-at point's sweep over it; light: the largest shift of the points it holds, its slice's
    // near, middle and far points on the camera's axis among them). stepTexels is cascade 0's for the camera, the
    // largest for the light. Empty otherwise.
    std::vector<double> cascadeStepTexels;

    std::vector<FlickerFrame> frames;  // motion.frames entries
    std::vector<FlickerPair> pairs;    // motion.frames - 1 entries
    // Over the pairs.
    double maxFlickerPercent = 0.0, meanFlickerPercent = 0.0;
    double maxVChangedPercent = 0.0, meanVChangedPercent = 0.0;
    double maxVisibleDeltaPercent = 0.0, meanVisibleDeltaPercent = 0.0;
    double maxMeanAbsDeltaS = 0.0, meanMeanAbsDeltaS = 0.0;
    int worstPair = 0;  // the pair with the most flickering pixels (the first on ties)

    // Per pixel, row 0 = top (PNG order), width * height.
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> flickerMask;  // 1 where a pixel flickered in any pair (union over pairs)
    std::vector<std::uint8_t> overlayRgba;  // the last frame dimmed; flickering pixels (union) and, where none
                                            // flickers, pixels whose V changed in any pair, in flickerLegend()'s colours
    // The worst pair's frames f and f+1 as rendered (each with its own camera and light), unmarked dimmed pictures
    // of S x Lambert (accuracy_overlay.h): side by side they show what flickers. A light motion's pair is exactly the
    // two halves compared.
    std::vector<std::uint8_t> worstPreviousRgba;
    std::vector<std::uint8_t> worstCurrentRgba;
};

const std::vector<LegendEntry>& flickerLegend();  // flicker, V changed

// Plays `motion` on light motion.light of the effective lights (measured alone, light_isolation.h) and measures
// every frame with `meter`. Bad motions (motionError), lights that cannot be measured, failed frames or a cancel give
// ok = false with the reason; nothing throws for user input. Progress: fraction over all frames.
FlickerReport measureFlicker(AccuracyMeter& meter, const Scene& scene, const Settings& settings, const Camera& camera,
                             int width, int height, const Motion& motion, AccuracyProgress* progress = nullptr);

}  // namespace shadowlab
