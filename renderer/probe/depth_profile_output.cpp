#include "probe/depth_profile_output.h"

#include <limits>

namespace shadowlab {

LinePlot depthProfilePlot(const DepthProfile& profile) {
    LinePlot plot;
    plot.title = "Depth profile " + std::to_string(profile.from.x) + "," + std::to_string(profile.from.y) + " -> " +
                 std::to_string(profile.to.x) + "," + std::to_string(profile.to.y) + ": " +
                 std::to_string(profile.acne) + " acne, " + std::to_string(profile.peterPanning) +
                 " Peter Panning of " + std::to_string(profile.surfaces) + " surface samples";
    plot.xLabel = "distance along the line (pixels)";
    plot.yLabel = "light depth";
    PlotSeries receiver{"receiver depth", {40, 90, 220, 255}, false, {}, {}};
    PlotSeries threshold{"receiver - bias", {230, 130, 0, 255}, false, {}, {}};
    PlotSeries stored{"map texel - bias (staircase)", {20, 20, 20, 255}, true, {}, {}};
    const double gap = std::numeric_limits<double>::quiet_NaN();  // breaks the lines over background
    for (const ProfileSample& s : profile.samples) {
        for (PlotSeries* series : {&receiver, &threshold, &stored}) series->x.push_back(s.t);
        receiver.y.push_back(s.surface ? s.receiver : gap);
        threshold.y.push_back(s.surface ? s.threshold : gap);
        stored.y.push_back(s.surface ? s.stored - s.bias : gap);
    }
    plot.series = {receiver, threshold, stored};
    // One band per run of neighbouring marked samples, so a long run reads as one region.
    const double half = profile.samples.size() > 1 ? 0.5 * profile.samples[1].t : 0.5;
    auto bands = [&](bool ProfileSample::*flag, const std::string& label, PlotColor color) {
        for (std::size_t i = 0; i < profile.samples.size();) {
            if (!(profile.samples[i].*flag)) {
                ++i;
                continue;
            }
            std::size_t end = i;
            while (end + 1 < profile.samples.size() && profile.samples[end + 1].*flag) ++end;
            plot.spans.push_back({label, color, profile.samples[i].t - half, profile.samples[end].t + half});
            i = end + 1;
        }
    };
    bands(&ProfileSample::acne, "acne (self-shadowed)", {230, 30, 30, 60});
    bands(&ProfileSample::peterPanning, "Peter Panning (gap < bias)", {150, 40, 200, 60});
    return plot;
}

nlohmann::json depthProfileToJson(const DepthProfile& profile) {
    nlohmann::json samples = nlohmann::json::array();
    for (const ProfileSample& s : profile.samples) {
        nlohmann::json j = {{"t", s.t}, {"x", s.x}, {"y", s.y}, {"surface", s.surface}};
        if (s.surface) {
            j["receiverDepth"] = s.receiver;
            j["storedDepth"] = s.stored;
            j["bias"] = s.bias;
            j["receiverMinusBias"] = s.threshold;
            j["selfReach"] = s.selfReach;
            j["shadow"] = s.shadow;
            j["acne"] = s.acne;
            j["peterPanning"] = s.peterPanning;
        }
        samples.push_back(std::move(j));
    }
    return {{"from", {profile.from.x, profile.from.y}},
            {"to", {profile.to.x, profile.to.y}},
            {"surfaceSamples", profile.surfaces},
            {"acneSamples", profile.acne},
            {"peterPanningSamples", profile.peterPanning},
            {"samples", std::move(samples)}};
}

}  // namespace shadowlab
