#include "cli/sweep_command.h"

#include "accuracy/motion.h"
#include "cli/command_input.h"
#include "cli/measure_motion.h"
#include "cli/progress.h"
#include "cli/settings_from_cli.h"
#include "context/headless_context.h"
#include "image/image_io.h"
#include "settings/atomic_file.h"
#include "sweep/sweep_output.h"
#include "sweep/sweep_runner.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace shadowlab::cli {

namespace {

std::string formatted(const char* format, double value) {
    char text[64];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// One table row (also the header): columns of fixed width, the label column as wide as the longest label.
void printRow(std::ostream& out, std::size_t labelWidth, const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) {
        const std::size_t width = i == 0 ? labelWidth + 2 : 11;
        std::string cell = cells[i];
        if (cell.size() < width) cell.append(width - cell.size(), ' ');
        out << cell;
    }
    out << "\n";
}

std::vector<std::string> rowCells(const SweepPointResult& p, bool soft) {
    if (p.failed()) return {p.label, "failed: " + p.error};
    const AccuracyNumbers& n = p.accuracy;
    std::vector<std::string> cells = {p.label + (p.onFront ? " *" : ""),
            std::to_string(p.resolution) + " " + depthFormatName(p.format),
            formatted("%.1f", double(p.mapBytes) / (1024.0 * 1024.0)),
            formatted("%.3f", p.shadowMs),
            formatted("%.3f", p.momentsMs),
            formatted("%.3f", p.blurMs),
            formatted("%.3f", p.mipsMs),
            formatted("%.3f", p.mainMs),
            formatted("%.3f", p.costMs),
            formatted("%.2fx", p.shadowOverBare),
            formatted("%.3f", n.wrongPercent),
            formatted("%.4f", n.meanError),
            formatted("%.3f", n.acnePercent),
            formatted("%.3f", n.leakPercent),
            formatted("%.2f", n.edgeErrorP95Texels),
            formatted("%.3g", n.edgeErrorP95World),
            formatted("%.1f", n.edgeErrorP95ScreenPixels)};
    if (soft) {  // against the soft reference (the light has a size)
        cells.push_back(formatted("%.5f", p.soft.meanError));
        cells.push_back(formatted("%.3f", p.soft.wrongPercent));
        cells.push_back(formatted("%.3f", p.soft.bleedingPercent));
        cells.push_back(formatted("%.3f", p.soft.overDarkeningPercent));
        cells.push_back(formatted("%.3g", p.soft.penumbra.errorWorld));
    }
    return cells;
}

// --json and --csv from the sweep as it stands (each rewritten whole, atomically): "" or why not.
std::string writeTables(const SweepOptions& options, const SweepResult& result) {
    if (!options.json.empty()) {
        nlohmann::json doc = sweepToJson(result);
        doc["scene"] = options.scene;
        doc["preset"] = options.preset;
        const std::string text = doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
        if (std::string error = writeFileAtomically(options.json, text); !error.empty())
            return "--json " + options.json + ": " + error;
    }
    if (!options.csv.empty())
        if (std::string error = writeFileAtomically(options.csv, sweepToCsv(result)); !error.empty())
            return "--csv " + options.csv + ": " + error;
    return {};
}

}  // namespace

int runSweep(const SweepOptions& options) {
    // Everything the user typed is checked before the scene, the context and the reference.
    std::optional<Settings> base = settingsFromCli(options.preset, options.overrides, options.scene);
    if (!base) return 2;
    const SweepPlan plan = planSweep(*base, options.axes);
    if (!plan.error.empty()) {
        std::cerr << "error: " << plan.error << "\n";
        return 2;
    }
    if (options.frames < 1) return fail("--frames must be at least 1");
    // --play K --step S: points evaluated along their animation (sweep/played_point.h).
    std::optional<double> playStep;
    if (!options.step.empty()) {
        std::string error;
        if (options.play == 0) return fail("--step: with --play K only (the seconds between played frames)");
        playStep = parseFiniteOption(options.step, "--step", error);
        if (!playStep) return fail(error);
        if (*playStep < 0.0 || *playStep > kMaxAnimationStepSeconds)
            return fail("--step " + options.step + ": seconds per frame in [0, " +
                        std::to_string(int(kMaxAnimationStepSeconds)) + "]");
    }
    if (std::string error = checkViewSize(options.width, options.height); !error.empty()) return fail(error);
    if (std::string error = checkMeasureMemory(options.width, options.height); !error.empty()) return fail(error);
    if (std::string error = checkOutputs({{options.json, "--json"}, {options.csv, "--csv"}, {options.chart, "--chart"}},
                                         {{options.scene, "--scene"}, {options.preset, "--preset"}});
        !error.empty())
        return fail(error);
    if (std::string error = checkPictureOutput({options.chart, "--chart"}, {options.chartWidth, options.chartHeight, 4, 4, true, {}});
        !error.empty())
        return fail(error);
    SceneLoadResult loaded = loadSceneForCommand(options.scene, {&*base});
    if (!loaded.scene) return fail(loaded.error);
    const Scene& scene = *loaded.scene;

    try {
        HeadlessContext context;
        std::string axes;
        for (const SweepAxis& a : plan.axes) axes += (axes.empty() ? "" : " x ") + a.key + " {" +
                                                    std::to_string(a.values.size()) + "}";
        std::cerr << "sweep: " << plan.points.size() << " points (" << axes << ") on " << scene.name << " ("
                  << scene.triangleCount() << " triangles), view " << options.width << "x" << options.height << ", "
                  << options.frames << " frames per point\n";
        SweepRunOptions run;
        run.width = options.width;
        run.height = options.height;
        run.frames = options.frames;
        run.playFrames = options.play;
        if (!options.step.empty()) run.playStep = *playStep;
        // Each finished point is in the files at once: a point that fails later, or a kill, loses none before it.
        std::string writeError;
        run.onResult = [&](const SweepResult& soFar) {
            if (writeError.empty()) writeError = writeTables(options, soFar);
        };
        AccuracyProgress accuracyProgress;
        std::atomic<std::size_t> points{plan.points.size()};  // the preset's own point may come on top
        ProgressLine progress(
            "sweep", points, "points",
            [&] {
                // The runner's fraction is of the whole sweep: (points done + the share of the one under way) / all.
                const double done = double(accuracyProgress.fraction.load()) * double(points.load());
                return done - std::floor(done);
            },
            [&] { return accuracyProgress.stage(); });
        const SweepResult result = shadowlab::runSweep(
            scene, *base, plan, run,
            [&](const SweepPointResult& p, std::size_t done, std::size_t total) {
                points = total;
                progress.setTotal(total);
                progress.setDone(done);
                progress.above([&] {
                    if (p.failed())
                        std::fprintf(stderr, "[%zu/%zu] %-24s failed: %s\n", done, total, p.label.c_str(),
                                     p.error.c_str());
                    else
                        std::fprintf(stderr,
                                     "[%zu/%zu] %-24s shadow %.3f ms (%.2fx bare)  moments %.3f ms  blur %.3f ms  "
                                     "mips %.3f ms  main %.3f ms  wrong %.3f %%%s%s\n",
                                     done, total, p.label.c_str(), p.shadowMs, p.shadowOverBare, p.momentsMs,
                                     p.blurMs, p.mipsMs, p.mainMs, p.accuracy.wrongPercent,
                                     p.soft.measured ? ("  soft |S-V| " + formatted("%.5f", p.soft.meanError)).c_str()
                                                     : "",
                                     p.referenceReused ? "" : "  (reference computed)");
                });
            },
            &accuracyProgress);
        progress.finish();
        if (!writeError.empty()) return fail(writeError);
        if (!result.ok) return fail(result.error);

        const bool cpu = result.softwareRasterizer();
        std::cout << "sweep: " << scene.name << " (" << result.triangles << " triangles), view " << result.width
                  << "x" << result.height
                  << (result.playFrames > 0
                          ? ", each point played " + std::to_string(result.playFrames) + " frames of " +
                                nlohmann::json(result.playStep).dump() +
                                " s from its animation.time: shadow ms = mean of frames 1.." +
                                std::to_string(result.playFrames - 1) + " as its shadow.update drew them, measured at "
                                "frame " + std::to_string(result.playFrames - 1) + "\n"
                          : ", median of " + std::to_string(result.frames) + " frames per point, shadow pass forced\n")
                  << "gl: " << result.glRenderer << "\ntimes: " << result.timingSource
                  << (cpu ? " -- CPU time of a software rasterizer, not GPU time" : "") << "\n";
        std::size_t labelWidth = 5;
        for (const SweepPointResult& p : result.points) labelWidth = std::max(labelWidth, p.label.size() + 2);
        std::string head;
        for (const SweepAxis& a : result.axes) head += (head.empty() ? "" : " ") + a.key;
        labelWidth = std::max(labelWidth, head.size());
        const bool soft = sweepSoftError(result);
        std::vector<std::string> header = {head,      "map",     "map MiB",  "shadow ms", "moments ms", "blur ms",
                                           "mips ms", "main ms", "cost ms", "x bare",   "wrong %",   "mean|S-V|",  "acne %",
                                           "leak %",  "edge tx", "edge world", "edge px"};
        if (soft)
            for (const char* column : {"soft|S-V|", "soft wrong", "bleed %", "dark %", "penumbra"})
                header.push_back(column);
        printRow(std::cout, labelWidth, header);
        for (const SweepPointResult& p : result.points) printRow(std::cout, labelWidth, rowCells(p, soft));
        if (result.preset) printRow(std::cout, labelWidth, rowCells(*result.preset, soft));
        std::cout << "(* = on the Pareto front; cost = shadow + moments + blur + mips + main; x bare = shadow pass / bare "
                     "depth draw; wrong = |S-V| >= 0.5, edges included; edge = p95 distance of mismatched pixels to "
                     "the true edge"
                  << (soft ? "; soft columns against the soft reference: mean |S-V|, wrong, bleeding (lit umbra), "
                             "over-darkening (darkened full light), penumbra width error in world units"
                           : "")
                  << ")\n";
        if (result.presetPoint < result.points.size())
            std::cout << "current preset: " << result.points[result.presetPoint].label << "\n";

        std::cout << "raster limit: a bare depth-only draw of the same " << result.triangles
                  << " triangles (one buffer, one draw, no bias / culling / alpha) into a map of each size:\n";
        for (const BareDrawTiming& b : result.bareDraws) {
            double lo = 0.0, hi = 0.0;
            bool any = false;
            const SweepPointResult* first = nullptr;
            std::vector<const SweepPointResult*> all;
            for (const SweepPointResult& p : result.points) all.push_back(&p);
            if (result.preset) all.push_back(&*result.preset);
            for (const SweepPointResult* pp : all)
                if (const SweepPointResult& p = *pp;
                    p.resolution == b.resolution && p.format == b.format && p.bareDrawMs == b.ms) {
                    lo = any ? std::min(lo, p.shadowOverBare) : p.shadowOverBare;
                    hi = any ? std::max(hi, p.shadowOverBare) : p.shadowOverBare;
                    if (!any) first = &p;
                    any = true;
                }
            const bool perLight = std::count_if(result.bareDraws.begin(), result.bareDraws.end(), [&](const BareDrawTiming& o) {
                                      return o.resolution == b.resolution && o.format == b.format;
                                  }) > 1;
            std::cout << "  " << b.resolution << "² " << depthFormatName(b.format)
                      << (perLight && first ? " (the light of " + first->label + ")" : std::string()) << ": bare draw "
                      << formatted("%.3f", b.ms) << " ms; the shadow pass takes " << formatted("%.2f", lo) << "x"
                      << (hi > lo ? " to " + formatted("%.2f", hi) + "x" : std::string()) << " of it\n";
        }
        std::cout << "Pareto front (not beaten on both cost and " << sweepErrorName(soft) << "), in order of cost:\n";
        for (std::size_t k = 0; k < result.front.size(); ++k) {
            const SweepPointResult& p = result.points[result.front[k]];
            std::cout << "  " << p.label << ": " << formatted("%.3f", p.costMs) << " ms, " << sweepErrorName(soft)
                      << " " << formatted(soft ? "%.5f" : "%.3f", sweepError(p, soft));
            if (k > 0) std::cout << "   (step up " << frontStepText(result.points[result.front[k - 1]], p) << ")";
            std::cout << "\n";
        }
        std::cout << "reference: computed " << (result.references == 1 ? std::string("once") : std::to_string(result.references) + " times (once per light / camera)")
                  << " (" << formatted("%.0f", result.referenceMs) << " ms: G-buffer + shadow rays); sweep wall time " << formatted("%.1f", result.wallMs / 1000.0)
                  << " s\n";
        for (const SweepPointResult& p : result.points)
            for (const std::string& w : p.warnings) std::cerr << "warning: " << p.label << ": " << w << "\n";

        if (std::string error = writeTables(options, result); !error.empty()) return fail(error);
        for (const std::string& path : {options.json, options.csv})
            if (!path.empty()) std::cout << "wrote " << path << "\n";
        if (!options.chart.empty()) {
            const PlotImage image = drawLinePlot(sweepChart(result), options.chartWidth, options.chartHeight);
            if (std::string error = writePng(options.chart, image.width, image.height, 4, image.rgba.data(), false);
                !error.empty())
                return fail("--chart " + options.chart + ": " + error);
            std::cout << "wrote " << options.chart << "\n";
        }
        // The preset's own row counts as a point here: it ran like one.
        const std::size_t ran = result.points.size() + (result.preset ? 1 : 0);
        const std::size_t failed =
            std::size_t(std::count_if(result.points.begin(), result.points.end(),
                                      [](const SweepPointResult& p) { return p.failed(); })) +
            (result.preset && result.preset->failed() ? 1 : 0);
        if (failed > 0)
            return fail(std::to_string(failed) + " of " + std::to_string(ran) +
                        " points failed (their reasons are in the table" +
                        (options.json.empty() && options.csv.empty() ? "" : " and the files") +
                        "); the others are kept");
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}

}  // namespace shadowlab::cli
