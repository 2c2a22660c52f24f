// shadowlab: the command line. Each subcommand lives in app/cli; the renderer does the work.
#include "cli/animation_options.h"
#include "cli/bench_animation.h"
#include "cli/bench_command.h"
#include "cli/bench_lights.h"
#include "cli/bench_planner.h"
#include "cli/bench_reference_update.h"
#include "cli/bench_soft_reference.h"
#include "cli/check_command.h"
#include "cli/export_command.h"
#include "cli/hardcases_command.h"
#include "cli/info_command.h"
#include "cli/measure_command.h"
#include "cli/probe_command.h"
#include "cli/profile_command.h"
#include "cli/render_command.h"
#include "cli/sweep_command.h"
#include "cli/tune_command.h"
#include "editor_window/edit_command.h"
#include "settings/settings_reference.h"

#include <CLI/CLI.hpp>

#include <iostream>

// Every command's --preset resolves alike (cli/settings_from_cli.h, settings/preset_catalog.h).
static const char* const kPresetHelp = "a preset JSON path, or the name of a shipped or user preset";

int main(int argc, char** argv) {
    using namespace shadowlab;
    // Named, so that --help and errors say "shadowlab", not the path it was started by (docs/ quote --help).
    CLI::App app{"ShadowLab: tune shadow maps and see what each setting costs", "shadowlab"};
    app.require_subcommand(0, 1);

    cli::RenderOptions render;
    CLI::App* renderCmd = app.add_subcommand("render", "Render one frame headless (no display, no GPU needed)");
    renderCmd->add_option("--scene", render.scene, "a .gltf/.glb path or builtin:NAME (see `shadowlab scenes`)")
        ->capture_default_str();
    renderCmd->add_option("--preset", render.preset, kPresetHelp);
    renderCmd->add_option("--set", render.overrides, "override a setting by its preset key: key=value (repeatable)")
        ->allow_extra_args(false);
    renderCmd->add_option("--width", render.width, "view width in pixels")->capture_default_str();
    renderCmd->add_option("--height", render.height, "view height in pixels")->capture_default_str();
    renderCmd->add_option("--out", render.out, "the camera view as PNG")->capture_default_str();
    renderCmd->add_option("--shadow-map", render.shadowMapExr, "the raw shadow map as a 1-channel float EXR");
    renderCmd->add_option("--shadow-map-png", render.shadowMapPng, "a viewable PNG of the shadow map");
    renderCmd->add_option("--compare", render.compare,
                          "A/B: a second preset, drawn right of the divider from the same camera, each side labelled "
                          "with its pass times");
    renderCmd->add_option("--split", render.split, "with --compare: the divider, 0..1 of the width")->capture_default_str();
    renderCmd->add_flag("--measure", render.measure,
                        "with --compare: each side's acne, leak and wrong pixels against the exact reference");
    renderCmd->add_option("--light", render.light,
                          "whose map --shadow-map / --shadow-map-png write (a point light: its six faces as a cross)")
        ->capture_default_str();
    renderCmd->add_option("--map-view", render.mapView,
                          "which of a cascaded light's maps --shadow-map / --shadow-map-png write: cascade:N "
                          "(default cascade:0)");
    renderCmd->add_option("--view", render.view, "lit | shadow | light-depth | cascades | texel-density")
        ->check(CLI::IsMember({"lit", "shadow", "light-depth", "cascades", "texel-density"}));

    cli::BenchOptions bench;
    CLI::App* benchCmd = app.add_subcommand("bench", "Time the passes per shadow-map resolution and filter");
    benchCmd->add_option("--scene", bench.scene, "a .gltf/.glb path or builtin:NAME")->capture_default_str();
    benchCmd->add_option("--preset", bench.preset, kPresetHelp);
    benchCmd->add_option("--set", bench.overrides, "override a setting: key=value (repeatable)");
    benchCmd->add_option("--width", bench.width, "view width")->capture_default_str();
    benchCmd->add_option("--height", bench.height, "view height")->capture_default_str();
    benchCmd->add_option("--frames", bench.frames, "timed frames per row")->capture_default_str()->check(
        CLI::Range(1, 100000));
    benchCmd->add_option("--resolutions", bench.resolutions, "shadow-map sizes to time")->capture_default_str();
    benchCmd->add_option("--filters", bench.filters, "point, hardware2x2, pcfN, poisson, vsm, evsm2, evsm4, msm (their keys: --set)")->capture_default_str();
    benchCmd->add_option("--json", bench.json, "also write the table as JSON");
    CLI::Option* benchLights = benchCmd->add_flag(
        "--lights", bench.lights,
        "many lights: each view's time, views a static frame and a moved light render, the main pass with 1, 2, 4, "
        "8 ... lights shadowed and not");
    CLI::Option* benchPlanner = benchCmd->add_flag("--planner", bench.planner,
                       "the shadow planner's CPU time per frame with 8 lights (2 cascaded suns, 3 spots, 3 point "
                       "lights; camera moving and still), and each cascade's shadow pass against a bare depth draw of "
                       "the casters it holds (the settings' cascaded lights, else the first sun)")
        ->excludes(benchLights);
    CLI::Option* benchReferenceUpdate = benchCmd->add_flag("--reference-update", bench.referenceUpdate,
                       "the exact reference following an animation step (CPU, Embree): the top level updated after one "
                       "instance and after a whole step moved, against a full rebuild (a scene with an animation: "
                       "builtin:city-traffic)")
        ->excludes(benchLights)
        ->excludes(benchPlanner);
    benchCmd->add_flag("--soft-reference", bench.softReference,
                       "the soft reference's CPU time (Embree) for the first shadow-casting light at its size "
                       "(lights.N.size > 0) and reference.softRays over the view: one query per ray against a pixel's "
                       "rays in one stream query, and how far their V differ")
        ->excludes(benchLights)
        ->excludes(benchPlanner)
        ->excludes(benchReferenceUpdate);
    cli::BenchAnimationOptions benchAnimation;
    cli::addBenchAnimationOptions(*benchCmd, benchAnimation);

    editor_window::EditOptions edit;
    CLI::App* editCmd = app.add_subcommand("edit", "Open the editor window (the default with no command)");
    editCmd->add_option("--scene", edit.scene, "a .gltf/.glb path or builtin:NAME")->capture_default_str();
    editCmd->add_option("--preset", edit.preset, kPresetHelp);
    editCmd->add_option("--width", edit.width, "window width")->capture_default_str()->check(CLI::Range(320, 16384));
    editCmd->add_option("--height", edit.height, "window height")->capture_default_str()->check(CLI::Range(240, 16384));
    editCmd->add_option("--screenshot-dir", edit.screenshotDir,
                        "where F12 writes screenshots (default: $SHADOWLAB_SCREENSHOTS, else "
                        "$XDG_DATA_HOME/shadowlab/screenshots, else ~/.local/share/shadowlab/screenshots)");

    cli::MeasureOptions measure;
    CLI::App* measureCmd = app.add_subcommand("measure", "Measure acne, leak, wrong pixels, edge error and their causes against the exact reference");
    measureCmd->add_option("--scene", measure.scene, "a .gltf/.glb path or builtin:NAME")->capture_default_str();
    measureCmd->add_option("--preset", measure.preset, kPresetHelp);
    measureCmd->add_option("--set", measure.overrides, "override a setting: key=value (repeatable)");
    measureCmd->add_option("--width", measure.width, "view width")->capture_default_str();
    measureCmd->add_option("--height", measure.height, "view height")->capture_default_str();
    measureCmd->add_option("--json", measure.json, "write the numbers, counts and cost as JSON");
    measureCmd->add_option("--overlay", measure.overlay, "write the error overlay as PNG");
    measureCmd->add_option("--cause-overlay", measure.causeOverlay,
                           "write the overlay coloured by cause (why each mismatched pixel is wrong) as PNG");
    measureCmd->add_option("--soft-overlay", measure.softOverlay,
                           "one light with a size: write its light bleeding (cyan) and over-darkening (orange) against "
                           "the soft reference as PNG");
    measureCmd->add_option("--light", measure.light,
                           "measure only light N (default: every shadow-casting light, then the whole picture; the "
                           "overlays show the union, each pixel coloured by its worst light)")
        ->check(CLI::NonNegativeNumber);
    measureCmd->add_option("--remeasure-bench", measure.remeasureBench,
                           "then time N live re-measures after a bias change (GPU count) against the CPU path")
        ->check(CLI::Range(1, 10000));
    measureCmd->add_option("--motion", measure.motion,
                           "measure flicker instead: camera (translate), camera-turn or light (rotate) every frame, or "
                           "animation (the scene's animations advance)");
    measureCmd->add_option("--frames", measure.frames, "with --motion: frames rendered (pairs = frames - 1; default 10)");
    measureCmd->add_option("--step", measure.step,
                           "with --motion: per frame, world units (camera, along its right vector), degrees "
                           "(camera-turn, light) or seconds (animation, from animation.time)");
    measureCmd->add_option("--direction", measure.direction,
                           "with --motion: x,y,z = the camera's direction of travel or the rotation axis");
    measureCmd->add_option("--frames-out", measure.framesOut,
                           "with --motion: write the worst pair's two frames as PNG into this folder");
    measureCmd->add_option("--stale-bounds", measure.staleBounds,
                           "measure instead what depth bounds one frame late cost: the frame after the camera turns "
                           "DEGREES, with this frame's bounds and the frame before's (light 0, cascaded)");

    cli::TuneOptions tune;
    CLI::App* tuneCmd = app.add_subcommand(
        "tune", "Suggest bias (and cull mode) or the technique's own keys: acne <= limit, then the least error");
    tuneCmd->add_option("--scene", tune.scene, "a .gltf/.glb path or builtin:NAME")->capture_default_str();
    tuneCmd->add_option("--preset", tune.preset, kPresetHelp);
    tuneCmd->add_option("--set", tune.overrides, "override a setting: key=value (repeatable)");
    tuneCmd->add_option("--width", tune.width, "view width")->capture_default_str();
    tuneCmd->add_option("--height", tune.height, "view height")->capture_default_str();
    tuneCmd->add_option("--out", tune.out, "the tuned preset")->capture_default_str();
    tuneCmd->add_option("--max-acne", tune.maxAcnePercent, "acne limit in percent")->capture_default_str();
    tuneCmd->add_option("--json", tune.json, "write the search path and result as JSON");
    tuneCmd->add_option("--search", tune.search,
                        "bias, technique (the keys filter.kind declares: VSM minVariance / bleedReduction, EVSM "
                        "exponents, MSM momentBias...), both (bias first), or auto (technique when it declares keys)")
        ->check(CLI::IsMember({"auto", "bias", "technique", "both"}))
        ->capture_default_str();
    tuneCmd->add_option("--light", tune.light,
                        "tune only light N's bias (default: every shadow-casting light in turn, each measured alone)")
        ->check(CLI::NonNegativeNumber);

    cli::ExportOptions exportOptions;
    CLI::App* exportCmd = app.add_subcommand("export", "The shadow state as a D3D12 / D3D11 / Vulkan / OpenGL snippet or JSON");
    exportCmd->add_option("--scene", exportOptions.scene, "the scene the normal offset's world size is computed for")
        ->capture_default_str();
    exportCmd->add_option("--preset", exportOptions.preset, kPresetHelp);
    exportCmd->add_option("--set", exportOptions.overrides, "override a setting: key=value (repeatable)");
    exportCmd->add_option("--format", exportOptions.format, "d3d12 | d3d11 | vulkan | gl | json")->required();
    exportCmd->add_option("--out", exportOptions.out, "write to this file (default: standard output)");
    exportCmd->add_option("--view", exportOptions.view, std::string(cli::kViewOptionHelp) + "; needs --light");
    exportCmd->add_option("--width", exportOptions.width, "the view a cascaded light's cascades are fitted to")
        ->capture_default_str();
    exportCmd->add_option("--height", exportOptions.height, "its height")->capture_default_str();
    exportCmd->add_option("--light", exportOptions.light,
                          "export only light N (an index into the effective lights); default: every light")
        ->check(CLI::NonNegativeNumber);
    cli::ProbeOptions probe;
    CLI::App* probeCmd = app.add_subcommand("probe", "Why is this pixel shadowed: taps, stored depths, bias terms, S on CPU and GPU");
    probeCmd->add_option("--scene", probe.scene, "a .gltf/.glb path or builtin:NAME")->capture_default_str();
    probeCmd->add_option("--preset", probe.preset, kPresetHelp);
    probeCmd->add_option("--set", probe.overrides, "override a setting: key=value (repeatable)");
    probeCmd->add_option("--width", probe.width, "view width")->capture_default_str();
    probeCmd->add_option("--height", probe.height, "view height")->capture_default_str();
    probeCmd->add_option("--pixel", probe.pixel, "X,Y: the pixel, y down from the top")->required();
    probeCmd->add_option("--json", probe.json, "also write the probe as JSON");
    probeCmd->add_option("--light", probe.light,
                         "probe light N only (default: every shadow-casting light, each alone, each with its own S)");
    probeCmd->add_option("--view", probe.view, cli::kViewOptionHelp);
    probeCmd->add_flag("--measure", probe.measure, "also measure the view: the exact visibility and the error's cause");
    cli::ProfileOptions profile;
    CLI::App* profileCmd = app.add_subcommand("profile", "Depth profile along a line: receiver depth, map texels, bias; acne and Peter Panning marked");
    profileCmd->add_option("--scene", profile.scene, "a .gltf/.glb path or builtin:NAME")->capture_default_str();
    profileCmd->add_option("--preset", profile.preset, kPresetHelp);
    profileCmd->add_option("--set", profile.overrides, "override a setting: key=value (repeatable)");
    profileCmd->add_option("--light", profile.light, "the light whose depths the line shows (default: the only shadow-casting light)");
    profileCmd->add_option("--view", profile.view, cli::kViewOptionHelp);
    profileCmd->add_option("--width", profile.width, "view width")->capture_default_str();
    profileCmd->add_option("--height", profile.height, "view height")->capture_default_str();
    profileCmd->add_option("--from", profile.from, "X0,Y0: the line's start, y down from the top")->required();
    profileCmd->add_option("--to", profile.to, "X1,Y1: the line's end")->required();
    profileCmd->add_option("--out", profile.out, "the chart, PNG")->required();
    profileCmd->add_option("--json", profile.json, "also write every sample's numbers as JSON");
    profileCmd->add_option("--plot-width", profile.plotWidth, "chart width")->capture_default_str();
    profileCmd->add_option("--plot-height", profile.plotHeight, "chart height")->capture_default_str();

    // The commands that render a scene at a time of its animations.
    const std::pair<CLI::App*, std::vector<std::string>*> posed[] = {
        {renderCmd, &render.overrides}, {measureCmd, &measure.overrides}, {probeCmd, &probe.overrides},
        {profileCmd, &profile.overrides}, {exportCmd, &exportOptions.overrides}, {tuneCmd, &tune.overrides}};
    for (const auto& [command, overrides] : posed)
        cli::addAnimationOptions(*command, *overrides);

    cli::SweepOptions sweep;
    CLI::App* sweepCmd = app.add_subcommand("sweep", "What accuracy costs: time and measure every point of preset-key axes, with the raster limit and the Pareto front");
    sweepCmd->add_option("--scene", sweep.scene, "a .gltf/.glb path or builtin:NAME")->capture_default_str();
    sweepCmd->add_option("--preset", sweep.preset, kPresetHelp);
    sweepCmd->add_option("--set", sweep.overrides, "override a setting: key=value (repeatable)");
    sweepCmd->add_option("--axis", sweep.axes, "KEY=V1,V2,...: a preset key and its values (repeatable; the points are "
                                               "the cartesian product)")->required();
    sweepCmd->add_option("--width", sweep.width, "view width")->capture_default_str();
    sweepCmd->add_option("--height", sweep.height, "view height")->capture_default_str();
    sweepCmd->add_option("--frames", sweep.frames, "timed frames per point (median)")->capture_default_str()->check(
        CLI::Range(1, 100000));
    sweepCmd->add_option("--play", sweep.play,
                         "play each point's animation K frames from its animation.time, timing the shadow pass as its "
                         "shadow.update draws them and measuring the last frame (shadow.update axes then matter)")
        ->check(CLI::Range(2, 1000))
        ->type_name("K");
    sweepCmd->add_option("--step", sweep.step, "with --play: seconds per frame (default 1/30)")->type_name("SECONDS");
    sweepCmd->add_option("--json", sweep.json, "write every point's numbers and settings as JSON");
    sweepCmd->add_option("--csv", sweep.csv, "write every point's numbers and settings as CSV");
    sweepCmd->add_option("--chart", sweep.chart, "write the chart (cost vs wrong pixels, the front, the preset) as PNG");
    sweepCmd->add_option("--chart-width", sweep.chartWidth, "chart width")->capture_default_str()->check(
        CLI::Range(200, 8192));
    sweepCmd->add_option("--chart-height", sweep.chartHeight, "chart height")->capture_default_str()->check(
        CLI::Range(150, 8192));

    cli::HardCasesOptions hard;
    CLI::App* hardCmd = app.add_subcommand("hardcases", "Run the numerically hard cases of ../shared/HARD_CASES.md: "
                                                        "each figure beside its threshold, pictures, exit 1 on a failure");
    hardCmd->add_option("--case", hard.cases, "run only case N (1..20; repeatable)");
    hardCmd->add_flag("--quick", hard.quick, "small maps and views, fewer sweep steps (ctest)");
    hardCmd->add_option("--json", hard.json, "write every case's rows as JSON");
    hardCmd->add_option("--out-dir", hard.outDir, "write the pictures (overlays, frame pairs) into this folder");
    hardCmd->add_option("--scenes", hard.sharedScenes,
                        "the ../shared/scenes folder (default: the build tree's link to it)");

    cli::CheckOptions check;
    CLI::App* checkCmd = app.add_subcommand("check", "A CI gate: measure cases (a case file, or one from flags) against "
                                                     "limits; one line per case, JUnit XML, exit 1 when a limit is broken");
    checkCmd->add_option("CASES.json", check.file, "the case file (see docs/command-line.md); or one case from the flags");
    checkCmd->add_option("--junit", check.junit, "write the results as JUnit XML (each case's figures and overlay PNG)");
    checkCmd->add_option("--out-dir", check.outDir,
                         "write each case's overlay PNG into this folder (default with --junit: <junit>-overlays/)");
    // One case from flags; each given one is remembered, so a case file beside them is refused.
    std::vector<CLI::Option*> checkCaseFlags = {
        checkCmd->add_option("--scene", check.flagCase.scene, "a .gltf/.glb path or builtin:NAME"),
        checkCmd->add_option("--preset", check.flagCase.preset, kPresetHelp),
        checkCmd->add_option("--set", check.flagCase.overrides, "override a setting: key=value (repeatable)"),
        checkCmd->add_option("--width", check.flagCase.width, "view width")->capture_default_str(),
        checkCmd->add_option("--height", check.flagCase.height, "view height")->capture_default_str(),
        checkCmd->add_option("--motion", check.motion, "with --max-flicker: camera, camera-turn or light (default light)"),
        checkCmd->add_option("--step", check.step,
                             "with --max-flicker: per frame, world units (camera) or degrees (default: a sub-texel step)"),
        checkCmd->add_option("--frames", check.flagCase.frames, "with --max-flicker: frames rendered")
            ->capture_default_str(),
    };
    std::vector<std::pair<CLI::Option*, std::optional<double> CheckLimits::*>> checkLimitFlags;
    std::vector<double> checkLimitValues(checkLimitInfos().size());
    for (std::size_t i = 0; i < checkLimitInfos().size(); ++i) {
        const CheckLimitInfo& info = checkLimitInfos()[i];
        CLI::Option* option = checkCmd->add_option(info.flag, checkLimitValues[i],
                                                   std::string("limit on ") + info.figure + " in " +
                                                       (info.percent ? "percent" : "screen pixels") +
                                                       (info.wholePicture ? " (each light's and the whole picture's)"
                                                                          : " (each light's)"));
        checkLimitFlags.emplace_back(option, info.member);
        checkCaseFlags.push_back(option);
    }

    CLI::App* scenesCmd = app.add_subcommand("scenes", "List the built-in scenes");
    CLI::App* infoCmd =
        app.add_subcommand("info", "Print the shipped data folder, GL vendor / renderer / version and limits");
    CLI::App* keysCmd = app.add_subcommand("keys", "List every setting's preset key, type, default, allowed values, "
                                                   "unit, what a change invalidates and meaning");
    bool keysMarkdown = false;
    keysCmd->add_flag("--markdown", keysMarkdown, "as Markdown tables: the settings reference of docs/settings.md");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }

    if (*renderCmd) return cli::runRender(render);
    if (*benchCmd && benchAnimation.requested(*benchCmd)) return cli::runBenchAnimation(bench, benchAnimation);
    if (*benchCmd)
        return bench.softReference     ? cli::runBenchSoftReference(bench)
               : bench.referenceUpdate ? cli::runBenchReferenceUpdate(bench)
               : bench.planner       ? cli::runBenchPlanner(bench)
               : bench.lights ? cli::runBenchLights(bench)
                              : cli::runBench(bench);
    if (*editCmd) return editor_window::runEdit(edit);
    if (*measureCmd) return cli::runMeasure(measure);
    if (*tuneCmd) return cli::runTune(tune);
    if (*exportCmd) return cli::runExport(exportOptions);
    if (*probeCmd) return cli::runProbe(probe);
    if (*profileCmd) return cli::runProfile(profile);
    if (*sweepCmd) return cli::runSweep(sweep);
    if (*hardCmd) return cli::runHardCases(hard);
    if (*checkCmd) {
        for (std::size_t i = 0; i < checkLimitFlags.size(); ++i)
            if (checkLimitFlags[i].first->count() > 0) check.flagCase.limits.*checkLimitFlags[i].second = checkLimitValues[i];
        for (CLI::Option* option : checkCaseFlags)
            if (option->count() > 0) check.caseFlags.push_back(option->get_name());
        if (checkCmd->get_option("--step")->count() > 0) check.flagCase.step = check.step;
        return cli::runCheck(check);
    }
    if (*scenesCmd) return cli::runScenes();
    if (*infoCmd) return cli::runInfo();
    if (*keysCmd) {
        std::cout << (keysMarkdown ? settingsReferenceMarkdown() : settingsReferenceText());
        return 0;
    }
    // No subcommand: the editor on the built-in default scene.
    return editor_window::runEdit(edit);
}
