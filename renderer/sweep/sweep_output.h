#pragma once
// A sweep as files: JSON and CSV with every number of every point and its settings (every preset key; a failed
// point with its "error" and no numbers), and the
// chart (cost in ms against the error: wrong pixels, or a soft light's mean |S-V| (sweepError), points labelled by their axis values, the Pareto front as a line, the
// current preset ringed; failed points are not drawn) as a LinePlot — the one chart code the PNG and the editor's panel both draw with.
#include "image/line_plot.h"
#include "sweep/sweep_runner.h"

#include <nlohmann/json.hpp>

#include <string>

namespace shadowlab {

nlohmann::json sweepToJson(const SweepResult& result);

// One row per point (then the preset's own row when it is not a point): the numbers, then every preset key.
std::string sweepToCsv(const SweepResult& result);

// The chart's series: points (every point, labelled), the front (a line through its points in order of cost) and
// the preset (a ring). `current` (optional) is a marker for settings measured outside the sweep.
LinePlot sweepChart(const SweepResult& result);

// The point drawn nearest (x, y) in pixels of a width x height picture of sweepChart(result), within `radius`
// pixels; result.points.size() when none.
std::size_t sweepPointAt(const SweepResult& result, int width, int height, double x, double y, double radius);

}  // namespace shadowlab
