#include "accuracy/flicker.h"

#include "accuracy/accuracy_overlay.h"
#include "accuracy/light_isolation.h"
#include "light/light_space.h"
#include "scene/scene_animation.h"
#include "views/view_select.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

constexpr LegendEntry kFlicker{"flicker (S flips, V does not)", 255, 40, 230};
constexpr LegendEntry kVChanged{"V changed (the true shadow moved)", 40, 200, 120};

double percentOf(std::size_t n, std::size_t of) { return of ? 100.0 * double(n) / double(of) : 0.0; }

// Where `world` (render-origin-relative) lands in `space`'s map, in texels; false behind a perspective light.
bool mapTexel(const LightSpace& space, const glm::dvec3& world, glm::dvec2& texel) {
    const glm::dvec4 clip = space.viewProjection() * glm::dvec4(world, 1.0);
    if (clip.w <= 1e-12) return false;
    texel = (glm::dvec2(clip) / clip.w * 0.5 + 0.5) * double(space.resolution);
    return true;
}

// The views of `light`, relative to the scene's centre, following `camera` (null: none; then a fit that follows the
// camera cannot be built); empty when they cannot be built (the frame itself then fails with the reason).
std::vector<ShadowView> lightViews(const LightSettings& light, const Bounds& bounds, const ViewCamera* camera) {
    std::string error;
    const auto views = buildLightViews(light, 0, bounds, renderOriginOf(bounds), camera, error);
    return views ? *views : std::vector<ShadowView>{};
}

// Whether the light's views move with the camera (cascades): only those are built from a camera, so they alone fail
// without one.
bool viewsFollowCamera(const LightSettings& light, const Bounds& bounds) {
    std::string error;
    return !buildLightViews(light, 0, bounds, renderOriginOf(bounds), nullptr, error);
}

// A light motion's step in each view's texels: the largest shift between frames 0 and 1 of the points the view holds
// at frame 0 (inside its map), among the scene's bounding-box centre and corners (a spot's cone sees few corners; a
// point light: in the cube face the point lies in) and, for a cascade, its slice's near, middle and far points on the
// camera's axis (the box's corners lie beyond the near cascades). A point moves by the turn times its distance from
// the rotation's pivot along the light, so one point alone can read near 0. 0 for a view that holds none of them.
std::vector<double> lightStepTexels(const LightSettings& start, const Motion& motion, const Bounds& bounds,
                                    const ViewCamera& camera) {
    if (bounds.empty) return {};
    const std::vector<ShadowView> before = lightViews(lightAtFrame(start, motion, bounds, 0), bounds, &camera);
    const std::vector<ShadowView> after = lightViews(lightAtFrame(start, motion, bounds, 1), bounds, &camera);
    if (before.empty() || before.size() != after.size()) return {};
    const glm::dvec3 centre(bounds.center());
    std::vector<glm::dvec3> points;
    for (int c = 0; c < 9; ++c)
        points.push_back(c == 8 ? glm::dvec3(0.0)
                                : glm::dvec3(c & 1 ? bounds.max.x : bounds.min.x, c & 2 ? bounds.max.y : bounds.min.y,
                                             c & 4 ? bounds.max.z : bounds.min.z) - centre);
    for (const ShadowView& v : before)
        if (v.kind == ShadowViewKind::Cascade)
            for (double share : {0.0, 0.5, 1.0})
                points.push_back(v.slice.camera.eye + v.slice.camera.forward * (v.slice.nearDepth + share *
                                                                                 (v.slice.farDepth - v.slice.nearDepth)));
    std::vector<double> largest(before.size(), 0.0);
    for (const glm::dvec3& p : points) {
        const int held = selectView(before, p).view;
        if (held < 0) continue;
        const std::size_t view = std::size_t(held);
        glm::dvec2 a, b;
        const double size = double(before[view].space.resolution);
        if (mapTexel(before[view].space, p, a) && mapTexel(after[view].space, p, b) && a.x >= 0.0 && a.y >= 0.0 &&
            a.x <= size && a.y <= size)
            largest[view] = std::max(largest[view], glm::length(b - a));
    }
    return largest;
}

FlickerHalf halfOf(const AccuracyReport& r) { return {&r.pixelClass, &r.pixelShadow, &r.pixelMeasured}; }

}  // namespace

const std::vector<LegendEntry>& flickerLegend() {
    static const std::vector<LegendEntry> legend = {kFlicker, kVChanged};
    return legend;
}

FlickerCounts compareFlickerPair(const FlickerHalf& previous, const FlickerHalf& current,
                                 std::vector<std::uint8_t>* flickering) {
    FlickerCounts c;
    const std::size_t count = previous.classes->size();
    if (flickering) flickering->assign(count, 0);
    double deltaSum = 0.0;
    std::size_t stable = 0;
    for (std::size_t i = 0; i < count; ++i) {
        if (!(*previous.measured)[i] || !(*current.measured)[i]) continue;
        ++c.measured;
        if (isLit((*previous.classes)[i]) != isLit((*current.classes)[i])) {
            ++c.vChanged;
            continue;
        }
        const float before = (*previous.shadow)[i], after = (*current.shadow)[i];
        const float delta = std::abs(after - before);
        ++stable;
        deltaSum += double(delta);
        if (delta > kFlickerVisibleDelta) ++c.visibleDelta;
        if ((before >= kFlickerFlip) != (after >= kFlickerFlip)) {
            ++c.flicker;
            if (flickering) (*flickering)[i] = 1;
        }
    }
    c.flickerPercent = percentOf(c.flicker, c.measured);
    c.vChangedPercent = percentOf(c.vChanged, c.measured);
    c.visibleDeltaPercent = percentOf(c.visibleDelta, c.measured);
    c.meanAbsDeltaS = stable ? deltaSum / double(stable) : 0.0;
    return c;
}

FlickerReport measureFlicker(AccuracyMeter& meter, const Scene& scene, const Settings& settings, const Camera& camera,
                             int width, int height, const Motion& motion, AccuracyProgress* progress) {
    FlickerReport report;
    report.motion = motion;
    report.lightIndex = motion.light;
    auto fail = [&](std::string error) {
        report.ok = false;
        report.error = std::move(error);
        return report;
    };
    if (std::string error = motionError(motion, scene.bounds); !error.empty()) return fail(error);
    std::string error;
    const std::optional<Settings> isolated = isolateLight(settings, scene, motion.light, error);
    if (!isolated) return fail(error);
    const LightSettings start = isolated->lights[0];
    report.lightType = start.type;
    if (motion.kind == MotionKind::Light && start.type == LightType::Point && !scene.bounds.empty &&
        glm::length(glm::dvec3(start.position) - glm::dvec3(scene.bounds.center())) <
            1e-6 * std::max(double(scene.bounds.radius()), 1e-9))
        return fail("--motion light: lights." + std::to_string(motion.light) +
                    " is a point light at the scene's centre; turning it about the centre does not move it");
    const double aspect = double(std::max(width, 1)) / double(std::max(height, 1));
    const bool follows = viewsFollowCamera(start, scene.bounds);
    if (motion.kind == MotionKind::Light) {
        const std::vector<double> steps =
            lightStepTexels(start, motion, scene.bounds, viewCameraOf(camera, aspect, renderOriginOf(scene.bounds)));
        for (double step : steps) report.stepTexels = std::max(report.stepTexels, step);
        if (follows) report.cascadeStepTexels = steps;
    }
    // The animation motion poses a copy of the scene at each frame's time (the camera and light stay).
    Scene animated;
    if (motion.kind == MotionKind::Animation) {
        const std::optional<std::vector<int>> chosen = chosenAnimations(scene, isolated->animation.play, error);
        if (!chosen) return fail(error);
        if (chosen->empty())
            return fail("--motion animation: the scene " + scene.name + " has no animation to play (animation.play " +
                        isolated->animation.play + ")");
        animated = scene;
    }

    const float outerBase = progress ? progress->base : 0.0f, outerSpan = progress ? progress->span : 1.0f;
    const std::size_t count = std::size_t(std::max(width, 0)) * std::size_t(std::max(height, 0));
    std::vector<std::uint8_t> flickering, vChanged(count, 0);
    report.flickerMask.assign(count, 0);
    AccuracyReport previous;
    std::vector<std::uint8_t> previousPicture;
    std::size_t worstFlicker = 0;
    // Views that follow the camera: each pair's first half is frame f's pixels shaded with frame f-1's views.
    const bool shifted = movesCamera(motion.kind) && follows;
    const int measuresPerFrame = shifted ? 2 : 1;
    for (int f = 0; f < motion.frames; ++f) {
        Settings frameSettings = *isolated;
        frameSettings.lights[0] = lightAtFrame(start, motion, scene.bounds, f);
        frameSettings.animation.time = float(animationTimeAtFrame(isolated->animation.time, motion, f));
        if (motion.kind == MotionKind::Animation) poseScene(animated, frameSettings.animation);
        const Scene& frameScene = motion.kind == MotionKind::Animation ? animated : scene;
        const Camera frameCamera = cameraAtFrame(camera, motion, f);
        const Camera previousCamera = cameraAtFrame(camera, motion, std::max(f - 1, 0));
        // Measure `half` of this frame (0: with frame f-1's views; 1: the frame itself); its progress share.
        auto measureHalf = [&](int half) {
            if (progress) {
                progress->base = outerBase + outerSpan * (float(f) + float(half) / float(measuresPerFrame)) /
                                                 float(motion.frames);
                progress->span = outerSpan / float(motion.frames * measuresPerFrame);
            }
            AccuracyReport r = meter.measure(frameScene, frameSettings, frameCamera, width, height, progress,
                                             half == 0 ? &previousCamera : nullptr);
            if (progress) {
                progress->base = outerBase;
                progress->span = outerSpan;
            }
            return r;
        };
        // The first half before the frame itself, so frame f-1's views are still in the renderer (kept, not redrawn).
        AccuracyReport withPrevious;
        if (shifted && f > 0) {
            withPrevious = measureHalf(0);
            if (!withPrevious.ok) {
                report.cancelled = withPrevious.cancelled;
                return fail(withPrevious.cancelled ? withPrevious.error
                                                   : "frame " + std::to_string(f) + " with frame " +
                                                         std::to_string(f - 1) + "'s views: " + withPrevious.error);
            }
        }
        AccuracyReport current = measureHalf(shifted ? 1 : 0);
        if (!current.ok) {
            report.cancelled = current.cancelled;
            return fail(current.cancelled ? current.error : "frame " + std::to_string(f) + ": " + current.error);
        }
        for (const std::string& w : current.warnings)
            if (std::find(report.warnings.begin(), report.warnings.end(), w) == report.warnings.end())
                report.warnings.push_back(w);
        report.frames.push_back({static_cast<const AccuracyNumbers&>(current), current.shadowViewsRendered, current.cost});
        if (f == 0) {
            report.texelWorldSize = current.texelWorldSize;
            // A turn sweeps the looked-at point across the receivers by its distance x the angle.
            const double travel = motion.kind == MotionKind::Camera ? std::abs(motion.step)
                                  : motion.kind == MotionKind::CameraTurn
                                      ? glm::length(camera.target - camera.position) * glm::radians(std::abs(motion.step))
                                      : 0.0;
            if (movesCamera(motion.kind) && current.texelWorldSize > 0.0)
                report.stepTexels = travel / current.texelWorldSize;
            if (movesCamera(motion.kind))
                for (const CascadeNumbers& c : current.cascades.cascades)
                    report.cascadeStepTexels.push_back(c.texelWorldSize > 0.0 ? travel / c.texelWorldSize : 0.0);
        }
        std::vector<std::uint8_t> picture = dimmedPicture(width, height, current.pixelClass, current.pixelShadow,
                                                          current.pixelLambert, frameSettings.ambient);
        if (f > 0) {
            // The pair's halves at frame f's camera: a light motion keeps the camera (frame f-1 is the first half);
            // a camera motion keeps the light, so frame f with frame f-1's light and views is frame f itself unless
            // the views follow the camera (then the first half was measured with frame f-1's views).
            const AccuracyReport& first = shifted ? withPrevious : movesCamera(motion.kind) ? current : previous;
            FlickerPair pair;
            pair.from = f - 1;
            pair.counts = compareFlickerPair(halfOf(first), halfOf(current), &flickering);
            pair.shadowViewsRendered = current.shadowViewsRendered;
            for (std::size_t i = 0; i < count; ++i) {
                report.flickerMask[i] |= flickering[i];
                vChanged[i] |= std::uint8_t(first.pixelMeasured[i] && current.pixelMeasured[i] &&
                                            isLit(first.pixelClass[i]) != isLit(current.pixelClass[i]));
            }
            if (report.pairs.empty() || pair.counts.flicker > worstFlicker) {
                worstFlicker = pair.counts.flicker;
                report.worstPair = pair.from;
                report.worstPreviousRgba = previousPicture;
                report.worstCurrentRgba = picture;
            }
            report.pairs.push_back(pair);
        }
        if (f + 1 == motion.frames) {
            // The overlay: the last frame dimmed, V changes, then flicker on top (it is what the measure is about).
            report.overlayRgba = picture;
            for (std::size_t i = 0; i < count; ++i) {
                const LegendEntry* mark = report.flickerMask[i] ? &kFlicker : vChanged[i] ? &kVChanged : nullptr;
                if (!mark) continue;
                report.overlayRgba[i * 4] = mark->red;
                report.overlayRgba[i * 4 + 1] = mark->green;
                report.overlayRgba[i * 4 + 2] = mark->blue;
            }
        }
        previous = std::move(current);
        previousPicture = std::move(picture);
    }

    for (const FlickerPair& pair : report.pairs) {
        const FlickerCounts& c = pair.counts;
        report.maxFlickerPercent = std::max(report.maxFlickerPercent, c.flickerPercent);
        report.maxVChangedPercent = std::max(report.maxVChangedPercent, c.vChangedPercent);
        report.maxVisibleDeltaPercent = std::max(report.maxVisibleDeltaPercent, c.visibleDeltaPercent);
        report.maxMeanAbsDeltaS = std::max(report.maxMeanAbsDeltaS, c.meanAbsDeltaS);
        report.meanFlickerPercent += c.flickerPercent;
        report.meanVChangedPercent += c.vChangedPercent;
        report.meanVisibleDeltaPercent += c.visibleDeltaPercent;
        report.meanMeanAbsDeltaS += c.meanAbsDeltaS;
    }
    const double pairs = double(report.pairs.size());
    report.meanFlickerPercent /= pairs;
    report.meanVChangedPercent /= pairs;
    report.meanVisibleDeltaPercent /= pairs;
    report.meanMeanAbsDeltaS /= pairs;
    report.width = width;
    report.height = height;
    report.ok = true;
    return report;
}

}  // namespace shadowlab
