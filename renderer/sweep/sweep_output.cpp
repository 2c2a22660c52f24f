#include "sweep/sweep_output.h"

#include "accuracy/accuracy_meter.h"
#include "settings/preset_io.h"
#include "settings/settings_fields.h"
#include "shadow/shadow_map.h"

#include <cmath>
#include <sstream>

namespace shadowlab {

namespace {

// A light with a size: the soft numbers against the soft reference; null for a hard light.
nlohmann::json softToJson(const SoftAccuracy& soft) {
    if (!soft.measured) return nullptr;
    return {{"metricsVersion", soft.metricsVersion},
            {"size", soft.size},
            {"sizeUnit", soft.sizeUnit},
            {"rays", soft.rays},
            {"wrongPixelsPercent", soft.wrongPercent},
            {"meanError", soft.meanError},
            {"bleedingPercent", soft.bleedingPercent},
            {"overDarkeningPercent", soft.overDarkeningPercent},
            {"penumbraWidthErrorWorld", soft.penumbra.errorWorld},
            {"penumbraWidthErrorTexels", soft.penumbra.errorTexels}};
}

nlohmann::json pointToJson(const SweepResult& result, const SweepPointResult& p) {
    nlohmann::json values = nlohmann::json::object();
    for (std::size_t a = 0; a < result.axes.size() && a < p.values.size(); ++a) values[result.axes[a].key] = p.values[a];
    const AccuracyNumbers& n = p.accuracy;
    nlohmann::json point = {{"label", p.label},
            {"values", values},
            {"shadowPassMs", p.shadowMs},
            {"momentsPassMs", p.momentsMs},
            {"blurPassMs", p.blurMs},
            {"mipsPassMs", p.mipsMs},
            {"mainPassMs", p.mainMs},
            {"costMs", p.costMs},
            {"shadowPassMinMs", p.shadowMinMs},
            {"mainPassMinMs", p.mainMinMs},
            {"wallMsPerFrame", p.wallMsPerFrame},
            {"resolution", p.resolution},
            {"depthFormat", depthFormatName(p.format)},
            {"shadowMapBytes", p.mapBytes},
            {"bareDrawMs", p.bareDrawMs},
            {"shadowPassOverBareDraw", p.shadowOverBare},
            {"wrongPixelsPercent", n.wrongPercent},
            {"meanError", n.meanError},
            {"acnePercent", n.acnePercent},
            {"acneSeverity", n.acneSeverity},
            {"leakPercent", n.leakPercent},
            {"edgeErrorP95Texels", n.edgeErrorP95Texels},
            {"edgeErrorP95World", n.edgeErrorP95World},
            {"edgeErrorP95ScreenPixels", n.edgeErrorP95ScreenPixels},
            {"soft", softToJson(p.soft)},
            {"kTexels", p.kTexels},
            {"coarseMap", p.coarseMap},
            {"paretoFront", p.onFront},
            {"referenceReused", p.referenceReused},
            {"measureMs", p.measureMs},
            {"warnings", p.warnings},
            {"error", p.error},
            {"settings", presetToJson(p.settings)}};
    if (result.playFrames > 0) {
        point["playedTime"] = p.playedTime;
        point["viewsRenderedPerFrame"] = p.viewsRenderedPerFrame;
    }
    return point;
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

}  // namespace

nlohmann::json sweepToJson(const SweepResult& result) {
    nlohmann::json axes = nlohmann::json::array();
    for (const SweepAxis& axis : result.axes) axes.push_back({{"key", axis.key}, {"keys", axis.keys}, {"values", axis.values}});
    nlohmann::json bare = nlohmann::json::array();
    for (const BareDrawTiming& b : result.bareDraws)
        bare.push_back({{"resolution", b.resolution}, {"depthFormat", depthFormatName(b.format)}, {"ms", b.ms}});
    nlohmann::json points = nlohmann::json::array();
    for (const SweepPointResult& p : result.points) points.push_back(pointToJson(result, p));
    nlohmann::json front = nlohmann::json::array();
    for (std::size_t k = 0; k < result.front.size(); ++k) {
        const SweepPointResult& p = result.points[result.front[k]];
        nlohmann::json step = {{"point", result.front[k]}, {"label", p.label}, {"costMs", p.costMs},
                               {"wrongPixelsPercent", p.accuracy.wrongPercent},
                               {"error", sweepError(p, sweepSoftError(result))}};
        if (k > 0) step["stepUp"] = frontStepText(result.points[result.front[k - 1]], p);
        front.push_back(step);
    }
    nlohmann::json doc = {{"metricsVersion", kMetricsVersion},
                          {"glRenderer", result.glRenderer},
                          {"timingSource", result.timingSource},
                          {"width", result.width},
                          {"height", result.height},
                          {"frames", result.frames},
                          {"triangles", result.triangles},
                          {"axes", axes},
                          {"bareDraws", bare},
                          {"points", points},
                          {"paretoFront", front},
                          {"frontError", sweepErrorName(sweepSoftError(result))},
                          {"referenceMs", result.referenceMs},
                          {"wallMs", result.wallMs}};
    if (result.playFrames > 0) doc["play"] = {{"frames", result.playFrames}, {"step", result.playStep}};
    if (result.presetPoint < result.points.size())
        doc["presetPoint"] = result.presetPoint;
    else if (result.preset)
        doc["preset"] = pointToJson(result, *result.preset);
    return doc;
}

std::string sweepToCsv(const SweepResult& result) {
    std::ostringstream out;
    out << "label,preset,paretoFront,shadowPassMs,momentsPassMs,blurPassMs,mipsPassMs,mainPassMs,costMs,bareDrawMs,"
           "shadowPassOverBareDraw,resolution,depthFormat,shadowMapBytes,wrongPixelsPercent,meanError,acnePercent,"
           "acneSeverity,leakPercent,edgeErrorP95Texels,edgeErrorP95World,edgeErrorP95ScreenPixels,"
           "softWrongPixelsPercent,softMeanError,softBleedingPercent,softOverDarkeningPercent,"
           "softPenumbraWidthErrorWorld,kTexels,coarseMap,error";
    // A column per key of the settings with the most lights (a light axis may add lights).
    const Settings* widest = nullptr;
    for (const SweepPointResult& p : result.points)
        if (!widest || p.settings.lights.size() > widest->lights.size()) widest = &p.settings;
    const std::vector<const SettingsField*> columns = widest ? settingsFieldsOf(*widest)
                                                             : std::vector<const SettingsField*>{};
    for (const SettingsField* field : columns) out << "," << field->key;
    out << "\n";
    auto row = [&](const SweepPointResult& p, bool preset) {
        const AccuracyNumbers& n = p.accuracy;
        out << csvField(p.label) << "," << (preset ? 1 : 0) << "," << (p.onFront ? 1 : 0) << "," << p.shadowMs << ","
            << p.momentsMs << "," << p.blurMs << "," << p.mipsMs << "," << p.mainMs << "," << p.costMs << "," << p.bareDrawMs << ","
            << p.shadowOverBare << "," << p.resolution << "," << depthFormatName(p.format) << "," << p.mapBytes
            << "," << n.wrongPercent << "," << n.meanError << "," << n.acnePercent << "," << n.acneSeverity << ","
            << n.leakPercent << "," << n.edgeErrorP95Texels << "," << n.edgeErrorP95World << ","
            << n.edgeErrorP95ScreenPixels << ",";
        if (p.soft.measured)  // empty cells for a hard light
            out << p.soft.wrongPercent << "," << p.soft.meanError << "," << p.soft.bleedingPercent << ","
                << p.soft.overDarkeningPercent << "," << p.soft.penumbra.errorWorld;
        else
            out << ",,,,";
        out << "," << p.kTexels << "," << (p.coarseMap ? 1 : 0) << "," << csvField(p.error);
        for (const SettingsField* field : columns) {
            const nlohmann::json value = field->get(p.settings);
            out << "," << csvField(value.is_string() ? value.get<std::string>() : value.dump());
        }
        out << "\n";
    };
    for (std::size_t i = 0; i < result.points.size(); ++i) row(result.points[i], i == result.presetPoint);
    if (result.preset) row(*result.preset, true);
    return out.str();
}

LinePlot sweepChart(const SweepResult& result) {
    LinePlot plot;
    std::string axes;
    for (const SweepAxis& a : result.axes) axes += (axes.empty() ? "" : " x ") + a.key;
    plot.title = "What accuracy costs: " + axes + " (" + std::to_string(result.width) + "x" +
                 std::to_string(result.height) + ", median of " + std::to_string(result.frames) + " frames)";
    const bool cpu = result.softwareRasterizer();
    plot.xLabel = std::string("cost: shadow pass + moments + blur + mips + main pass, ms") +
                  (cpu ? " (CPU time, software rasterizer)" : " (GPU)");
    const bool soft = sweepSoftError(result);
    plot.yLabel = sweepErrorName(soft);
    PlotSeries front;
    front.label = "Pareto front";
    front.color = {220, 60, 40, 255};
    for (std::size_t i : result.front) {
        front.x.push_back(result.points[i].costMs);
        front.y.push_back(sweepError(result.points[i], soft));
    }
    PlotPoints points;
    points.label = "points (axis values)";
    points.color = {70, 110, 200, 255};
    for (const SweepPointResult& p : result.points) {
        if (p.failed()) continue;  // no numbers to place
        points.x.push_back(p.costMs);
        points.y.push_back(sweepError(p, soft));
        points.labels.push_back(p.label);
    }
    PlotPoints preset;
    preset.label = "current preset";
    preset.color = {20, 150, 60, 255};
    preset.radius = 9;
    preset.ring = true;
    const bool extra = result.presetPoint >= result.points.size() && result.preset;
    const SweepPointResult* base = result.presetPoint < result.points.size() ? &result.points[result.presetPoint]
                                   : extra                                  ? &*result.preset
                                                                            : nullptr;
    if (base && !base->failed()) {
        preset.x.push_back(base->costMs);
        preset.y.push_back(sweepError(*base, soft));
        preset.labels.push_back(extra ? base->label : "");
    }
    plot.series = {front};
    plot.points = {points, preset};
    return plot;
}

std::size_t sweepPointAt(const SweepResult& result, int width, int height, double x, double y, double radius) {
    const PlotFrame frame = plotFrame(sweepChart(result), width, height);
    std::size_t best = result.points.size();
    double bestDistance = radius;
    const bool soft = sweepSoftError(result);
    for (std::size_t i = 0; i < result.points.size(); ++i) {
        if (result.points[i].failed()) continue;  // not drawn
        const double d = std::hypot(frame.px(result.points[i].costMs) - x,
                                    frame.py(sweepError(result.points[i], soft)) - y);
        if (d <= bestDistance) best = i, bestDistance = d;
    }
    return best;
}

}  // namespace shadowlab
