#include "cli/flicker_output.h"

#include "cli/accuracy_output.h"

#include <algorithm>
#include <iomanip>

namespace shadowlab::cli {

namespace {

nlohmann::json countsToJson(const FlickerCounts& c) {
    return {{"measured", c.measured},
            {"flicker", c.flicker},
            {"vChanged", c.vChanged},
            {"visibleDelta", c.visibleDelta},
            {"flickerPercent", c.flickerPercent},
            {"vChangedPercent", c.vChangedPercent},
            {"visibleDeltaPercent", c.visibleDeltaPercent},
            {"meanAbsDeltaS", c.meanAbsDeltaS}};
}

}  // namespace

void printFlicker(std::ostream& out, const FlickerReport& r) {
    const Motion& m = r.motion;
    out << std::setprecision(4);
    // cli::lightLabel ("lights.N"): unqualified, LightType's namespace adds the export's lightLabel ("light N"), an
    // ambiguous call wherever both are declared (the sanitizer trees' unity source of the app).
    out << "flicker, metrics version " << kMetricsVersion << " (" << r.width << "x" << r.height << ", "
        << cli::lightLabel(r.lightIndex, r.lightType) << "): " << motionName(m.kind) << " moved " << m.step << " "
        << motionInfo(m.kind).unit << " per frame";
    if (m.kind != MotionKind::Animation)  // an animation moves casters, not the map: no step in texels
        out << " = " << r.stepTexels << " texels of the light's map ("
            << (r.stepTexels < 1.0 ? "sub-texel" : "a texel or more") << "; texel = " << r.texelWorldSize
            << " world units)";
    out << ", " << m.frames << " frames, " << r.pairs.size() << " pairs\n";
    if (!r.cascadeStepTexels.empty()) {
        out << "  step per cascade (texels of each cascade's map, nearest first):";
        for (double step : r.cascadeStepTexels) out << " " << step;
        out << (movesCamera(m.kind) ? "; each pair's first half is the new camera with the previous frame's cascades\n"
                                    : "\n");
    }
    out << std::fixed << std::setprecision(3);
    out << "  flicker      max " << std::setw(8) << r.maxFlickerPercent << " %  mean " << std::setw(8)
        << r.meanFlickerPercent << " %   (S crosses 0.5 at the same surface point while V does not)\n";
    out << "  V changed    max " << std::setw(8) << r.maxVChangedPercent << " %  mean " << std::setw(8)
        << r.meanVChangedPercent << " %   (the true shadow moved: not flicker)\n";
    out << "  |dS| > 1/8   max " << std::setw(8) << r.maxVisibleDeltaPercent << " %  mean " << std::setw(8)
        << r.meanVisibleDeltaPercent << " %   (a visible change of S while V does not, flips included)\n";
    out << std::setprecision(5);
    out << "  mean |dS|    max " << std::setw(8) << r.maxMeanAbsDeltaS << "    mean " << std::setw(8)
        << r.meanMeanAbsDeltaS << "     (over pixels whose V did not change)\n";
    std::size_t rerendered = 0;
    for (const FlickerPair& p : r.pairs) rerendered += p.shadowViewsRendered;
    out << "  shadow views re-rendered after the first frame: " << rerendered
        << (!movesCamera(m.kind)         ? "\n"
            : r.cascadeStepTexels.empty() ? " (a camera motion must not re-render a scene-fitted map)\n"
                                          : " (cascades follow the camera)\n");
    // An animation moves instances: the reference's BVH follows them (renderer/reference/embree_scene.h).
    std::size_t updated = 0;
    double updateMs = 0.0;
    for (const FlickerFrame& f : r.frames)
        if (f.cost.bvhUpdated) {
            ++updated;
            updateMs = std::max(updateMs, f.cost.bvhUpdateMs);
        }
    if (updated > 0)
        out << std::setprecision(3) << "  reference BVH updated (instances moved, no mesh BVH rebuilt) in " << updated
            << " of " << r.frames.size() << " frames, at most " << updateMs << " ms\n";
    out << std::setprecision(3);
    out << "  pair     flicker %   V changed %   |dS|>1/8 %   mean |dS|   measured   views\n";
    for (const FlickerPair& p : r.pairs) {
        const FlickerCounts& c = p.counts;
        out << "  " << std::setw(3) << p.from << "-" << std::left << std::setw(3) << p.from + 1 << std::right
            << std::setw(10) << c.flickerPercent << std::setw(14) << c.vChangedPercent << std::setw(13)
            << c.visibleDeltaPercent << std::setw(12) << std::setprecision(5) << c.meanAbsDeltaS
            << std::setprecision(3) << std::setw(11) << c.measured << std::setw(8) << p.shadowViewsRendered
            << (p.from == r.worstPair ? "   <- worst" : "") << "\n";
    }
    out.unsetf(std::ios::floatfield);
}

nlohmann::json flickerToJson(const FlickerReport& r) {
    nlohmann::json pairs = nlohmann::json::array();
    for (const FlickerPair& p : r.pairs) {
        nlohmann::json j = countsToJson(p.counts);
        j["from"] = p.from;
        j["shadowViewsRendered"] = p.shadowViewsRendered;
        pairs.push_back(std::move(j));
    }
    nlohmann::json frames = nlohmann::json::array();
    for (const FlickerFrame& f : r.frames) {
        nlohmann::json j = numbersToJson(f.numbers);
        j["shadowViewsRendered"] = f.shadowViewsRendered;
        j["reference"] = {{"bvhReused", f.cost.bvhReused}, {"bvhUpdated", f.cost.bvhUpdated},
                          {"bvhBuildMs", f.cost.bvhBuildMs}, {"bvhUpdateMs", f.cost.bvhUpdateMs},
                          {"instancesMoved", f.cost.instancesMoved}};
        frames.push_back(std::move(j));
    }
    return {{"metricsVersion", kMetricsVersion},
            {"width", r.width},
            {"height", r.height},
            {"motion", motionName(r.motion.kind)},
            {"step", r.motion.step},
            {"stepUnit", motionInfo(r.motion.kind).unit},
            {"stepTexels", r.stepTexels},
            {"texelWorldSize", r.texelWorldSize},
            {"cascadeStepTexels", r.cascadeStepTexels},
            {"frames", r.motion.frames},
            {"light", r.lightIndex},
            {"flickerPercent", {{"max", r.maxFlickerPercent}, {"mean", r.meanFlickerPercent}}},
            {"vChangedPercent", {{"max", r.maxVChangedPercent}, {"mean", r.meanVChangedPercent}}},
            {"visibleDeltaPercent", {{"max", r.maxVisibleDeltaPercent}, {"mean", r.meanVisibleDeltaPercent}}},
            {"meanAbsDeltaS", {{"max", r.maxMeanAbsDeltaS}, {"mean", r.meanMeanAbsDeltaS}}},
            {"worstPair", r.worstPair},
            {"pairs", pairs},
            {"perFrame", frames},
            {"warnings", r.warnings}};
}

}  // namespace shadowlab::cli
