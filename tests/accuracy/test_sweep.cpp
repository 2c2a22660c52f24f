// The cost-vs-accuracy sweep (issue 11): axes are preset keys checked by the key table before any work; a two-axis
// sweep of a built-in scene shows what a user expects — error falls as the map grows, cost rises with the kernel —
// against one reference computed once; a bare draw stands beside every map size; the front holds exactly the points
// nothing beats; the chart is drawn and a point is found under its own marker.
#include "gl_fixture.h"
#include "scene/gltf_loader.h"
#include "scene/scene_animation.h"
#include "settings/settings_fields.h"
#include "shading/filters/filter_technique.h"
#include "sweep/pareto_front.h"
#include "sweep/sweep_output.h"
#include "sweep/sweep_runner.h"

#include <filesystem>
#include <map>
#include <set>
#include <sstream>

namespace shadowlab::test {
namespace {

class SweepTest : public GlTest {};

// A small sweep's run: a width x height view, `frames` timed frames a point, the preset measured as a marker or not.
SweepRunOptions smallRun(int width, int height, int frames, bool measurePreset = SweepRunOptions{}.measurePreset) {
    SweepRunOptions options;
    options.width = width;
    options.height = height;
    options.frames = frames;
    options.measurePreset = measurePreset;
    return options;
}

bool dominates(const SweepPointResult& a, const SweepPointResult& b) {
    return a.costMs <= b.costMs && a.accuracy.wrongPercent <= b.accuracy.wrongPercent &&
           (a.costMs < b.costMs || a.accuracy.wrongPercent < b.accuracy.wrongPercent);
}

TEST(SweepPlan, IsTheCartesianProductOfValuesTheKeyTableAccepts) {
    const Settings base = loadShippedPreset("default");
    const SweepPlan plan =
        planSweep(base, {"shadow.resolution=512, 1024,2048", "filter.kind=point,pcf", "light.direction=[0,-1,0.2],[1,-1,0]"});
    ASSERT_EQ(plan.error, "");
    ASSERT_EQ(plan.points.size(), 12u);
    EXPECT_EQ(plan.axes[2].values.size(), 2u) << "commas inside [...] belong to the vector";
    EXPECT_EQ(plan.points[0].label(), "512 point [0.0,-1.0,0.2]");
    EXPECT_EQ(plan.points[11].settings.lights[0].shadow.resolution, 2048);
    EXPECT_EQ(plan.points[11].settings.filter.kind, FilterKind::Pcf);
    EXPECT_EQ(plan.points[1].values[2], "[1.0,-1.0,0.0]") << "the last axis runs fastest, values as the key table writes them";
    // The default preset is 2048 pcf: where it sits on axes that include its own values.
    const SweepPlan own = planSweep(base, {"shadow.resolution=1024,2048", "filter.kind=point,pcf"});
    ASSERT_EQ(own.error, "");
    EXPECT_EQ(own.points[own.basePoint].label(), "2048 pcf");
}

TEST(SweepPlan, AJointAxisMovesSeveralKeysTogether) {
    const Settings base = loadShippedPreset("default");
    const SweepPlan plan =
        planSweep(base, {"filter.kind,filter.kernel=point:1,hardware2x2:1,pcf:3,pcf:5,pcf:9,poisson:1", "shadow.depthFormat=d16,d32f"});
    ASSERT_EQ(plan.error, "");
    ASSERT_EQ(plan.points.size(), 12u);
    EXPECT_EQ(plan.axes[0].keys, (std::vector<std::string>{"filter.kind", "filter.kernel"}));
    EXPECT_EQ(plan.points[4].label(), "pcf:3 d16");
    EXPECT_EQ(plan.points[4].settings.filter.kind, FilterKind::Pcf);
    EXPECT_EQ(plan.points[4].settings.filter.kernel, 3);
    EXPECT_EQ(plan.points[8].settings.filter.kernel, 9);
    EXPECT_EQ(plan.baseValues[0], "pcf:3") << "the default preset's place on the joint axis";
    EXPECT_NE(planSweep(base, {"filter.kind,filter.kernel=pcf"}).error.find("needs 2 parts"), std::string::npos);
    EXPECT_NE(planSweep(base, {"filter.kind,filter.kernel=pcf:4"}).error.find("filter.kernel"), std::string::npos);
    EXPECT_NE(planSweep(base, {"filter.kind,filter.kernel=pcf:3", "filter.kernel=1"}).error.find("already an axis"),
              std::string::npos);
}

TEST(SweepPlan, RefusesABadKeyOrValueNamingTheKey) {
    const Settings base = loadShippedPreset("default");
    const SweepPlan typo = planSweep(base, {"shadow.resolutoin=512,1024"});
    EXPECT_NE(typo.error.find("shadow.resolutoin"), std::string::npos) << typo.error;
    EXPECT_NE(typo.error.find("did you mean shadow.resolution"), std::string::npos) << typo.error;
    EXPECT_TRUE(typo.points.empty());
    const SweepPlan small = planSweep(base, {"shadow.resolution=512,8"});
    EXPECT_NE(small.error.find("shadow.resolution"), std::string::npos) << small.error;
    EXPECT_NE(small.error.find("8"), std::string::npos) << small.error;
    const SweepPlan kind = planSweep(base, {"filter.kind=point,gaussian"});
    EXPECT_NE(kind.error.find("filter.kind"), std::string::npos) << kind.error;
    EXPECT_NE(kind.error.find("gaussian"), std::string::npos) << kind.error;
    EXPECT_NE(planSweep(base, {"filter.kernel=2"}).error.find("filter.kernel"), std::string::npos);
    EXPECT_NE(planSweep(base, {"filter.kind=pcf", "filter.kind=point"}).error.find("already an axis"),
              std::string::npos);
    EXPECT_NE(planSweep(base, {"shadow.resolution=512,,1024"}).error.find("empty value"), std::string::npos);
    EXPECT_NE(planSweep(base, {"shadow.resolution"}).error.find("KEY=V1,V2"), std::string::npos);
    EXPECT_NE(planSweep(base, {}).error, "");
}

TEST(ParetoFront, KeepsOnlyPointsNothingBeatsOnBothInOrderOfCost) {
    //                 0    1    2    3    4    5
    const std::vector<double> cost{5.0, 1.0, 3.0, 4.0, 2.0, 3.0};
    const std::vector<double> error{1.0, 9.0, 4.0, 4.0, 5.0, 4.0};
    // 3 is beaten by 2 (cheaper, as good); 2 and 5 are equal, both kept.
    EXPECT_EQ(paretoFront(cost, error), (std::vector<std::size_t>{1, 4, 2, 5, 0}));
    EXPECT_TRUE(paretoFront({}, {}).empty());
}

TEST_F(SweepTest, ErrorFallsWithResolutionCostRisesWithKernelOneReference) {
    const Scene scene = loadBuiltin("textbook");
    Settings base = loadShippedPreset("default");
    ASSERT_EQ(applySettingOverride(base, "filter.kind=pcf"), "");
    const SweepPlan plan = planSweep(base, {"shadow.resolution=32,128,1024", "filter.kernel=1,9"});
    ASSERT_EQ(plan.error, "");
    const SweepRunOptions options = smallRun(320, 180, 7);
    std::size_t calls = 0;
    const SweepResult r = runSweep(scene, base, plan, options,
                                   [&](const SweepPointResult&, std::size_t done, std::size_t total) {
                                       ++calls;
                                       EXPECT_EQ(done, calls);
                                       EXPECT_EQ(total, 7u) << "six points and the preset (2048, kernel 3)";
                                   });
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(r.points.size(), 6u);
    ASSERT_TRUE(r.preset.has_value());
    EXPECT_EQ(r.preset->resolution, 2048);
    auto at = [&](int resolution, int kernel) -> const SweepPointResult& {
        for (const SweepPointResult& p : r.points)
            if (p.settings.lights[0].shadow.resolution == resolution && p.settings.filter.kernel == kernel) return p;
        ADD_FAILURE() << "no point " << resolution << " " << kernel;
        return r.points[0];
    };
    for (int kernel : {1, 9}) {
        // A 32² map loses the small shadows; 1024² keeps nearly all of them.
        EXPECT_GT(at(32, kernel).accuracy.wrongPercent, at(128, kernel).accuracy.wrongPercent) << "kernel " << kernel;
        EXPECT_GT(at(128, kernel).accuracy.wrongPercent, at(1024, kernel).accuracy.wrongPercent) << "kernel " << kernel;
        EXPECT_GT(at(32, kernel).accuracy.wrongPercent, 3.0 * at(1024, kernel).accuracy.wrongPercent);
    }
    // 81 taps against 1. On llvmpipe these are CPU times, and other processes on the machine only ever add time:
    // the fastest of 7 frames is the least disturbed one (the median is what the report shows).
    for (int resolution : {32, 128, 1024}) {
        EXPECT_GT(at(resolution, 9).mainMinMs, 1.5 * at(resolution, 1).mainMinMs) << resolution;
        EXPECT_LE(at(resolution, 1).mainMinMs, at(resolution, 1).mainMs);
    }
    // The reference is computed once: only the first point traces rays.
    EXPECT_FALSE(r.points[0].referenceReused);
    for (std::size_t i = 1; i < r.points.size(); ++i) EXPECT_TRUE(r.points[i].referenceReused) << r.points[i].label;
    // A bare draw per map size and format, timed, and each point set against its own size's.
    std::set<int> sizes;
    for (const BareDrawTiming& b : r.bareDraws) {
        EXPECT_TRUE(b.ok);
        EXPECT_GT(b.ms, 0.0);
        EXPECT_TRUE(sizes.insert(b.resolution).second) << "one bare draw per size";
    }
    EXPECT_EQ(sizes, (std::set<int>{32, 128, 1024, 2048}));
    for (const SweepPointResult& p : r.points) {
        const auto bare = std::find_if(r.bareDraws.begin(), r.bareDraws.end(),
                                       [&](const BareDrawTiming& b) { return b.resolution == p.resolution; });
        ASSERT_NE(bare, r.bareDraws.end());
        EXPECT_EQ(p.bareDrawMs, bare->ms);
        EXPECT_NEAR(p.shadowOverBare, p.shadowMs / bare->ms, 1e-9);
        EXPECT_EQ(p.mapBytes, std::size_t(p.resolution) * std::size_t(p.resolution) * 4u);
    }
    // The front: exactly the points nothing beats, in order of cost.
    ASSERT_FALSE(r.front.empty());
    for (std::size_t i = 0; i < r.points.size(); ++i) {
        bool beaten = false;
        for (const SweepPointResult& other : r.points) beaten = beaten || dominates(other, r.points[i]);
        EXPECT_EQ(r.points[i].onFront, !beaten) << r.points[i].label;
    }
    for (std::size_t k = 1; k < r.front.size(); ++k)
        EXPECT_LE(r.points[r.front[k - 1]].costMs, r.points[r.front[k]].costMs);

    // The files: every point in the JSON and CSV, the chart drawn, a point found under its marker.
    const nlohmann::json json = sweepToJson(r);
    ASSERT_EQ(json["points"].size(), 6u);
    std::size_t flagged = 0;
    for (const nlohmann::json& p : json["points"]) flagged += p["paretoFront"].get<bool>() ? 1 : 0;
    EXPECT_EQ(flagged, r.front.size());
    EXPECT_EQ(json["points"][0]["settings"]["lights"][0]["shadow"]["resolution"], 32);
    EXPECT_TRUE(json.contains("preset"));
    std::istringstream csv(sweepToCsv(r));
    std::string line;
    std::size_t lines = 0;
    while (std::getline(csv, line)) ++lines;
    EXPECT_EQ(lines, 1u + 6u + 1u) << "header, points, preset";
    const LinePlot chart = sweepChart(r);
    const PlotImage image = drawLinePlot(chart, 900, 500);
    const std::filesystem::path dir = std::filesystem::path(SHADOWLAB_TEST_OUTPUT) / "accuracy";
    std::filesystem::create_directories(dir);
    EXPECT_EQ(writePng((dir / "sweep-chart.png").string(), image.width, image.height, 4, image.rgba.data(), false), "");
    const PlotFrame frame = plotFrame(chart, 900, 500);
    const SweepPointResult& last = r.points.back();
    EXPECT_EQ(sweepPointAt(r, 900, 500, frame.px(last.costMs) + 1.0, frame.py(last.accuracy.wrongPercent), 6.0),
              r.points.size() - 1);
    EXPECT_EQ(sweepPointAt(r, 900, 500, 1.0, 1.0, 6.0), r.points.size()) << "nothing in the corner";
}

TEST_F(SweepTest, ALightAxisComputesTheReferenceOncePerLightAndDrawsTheBareDrawFromEachLight) {
    const Scene scene = loadBuiltin("textbook");
    const Settings base = loadShippedPreset("default");
    // The light axis runs fastest in the plan; the sweep still computes each light's reference only once.
    const SweepPlan plan = planSweep(base, {"filter.kind=point,pcf,poisson", "light.type=directional,spot"});
    ASSERT_EQ(plan.error, "");
    const SweepRunOptions options = smallRun(96, 54, 1);
    const SweepResult r = runSweep(scene, base, plan, options);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.references, 2);
    ASSERT_EQ(r.points.size(), 6u);
    for (std::size_t i = 0; i < r.points.size(); ++i)
        EXPECT_EQ(r.points[i].label, plan.points[i].label()) << "results come back in plan order";
    EXPECT_EQ(r.bareDraws.size(), 2u) << "one 2048² D32F draw per light";
    EXPECT_NE(r.bareDraws[0].lightViewProjection, r.bareDraws[1].lightViewProjection);
}

TEST_F(SweepTest, AMapAboveTheGpuLimitIsRefusedBeforeAnyWork) {
    const Scene scene = loadBuiltin("textbook");
    const Settings base = loadShippedPreset("default");
    const SweepPlan plan = planSweep(base, {"shadow.resolution=256,32768"});
    if (!plan.error.empty()) GTEST_SKIP() << "the key table already refuses 32768: " << plan.error;
    std::size_t calls = 0;
    const SweepRunOptions options = smallRun(64, 36, 1);
    const SweepResult r = runSweep(scene, base, plan, options, [&](const SweepPointResult&, std::size_t, std::size_t) {
        ++calls;
    });
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("shadow.resolution"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("GL_MAX_TEXTURE_SIZE"), std::string::npos) << r.error;
    EXPECT_EQ(calls, 0u) << "no point was run";
}

// A point that fails is kept with its reason and the sweep goes on; after each point the sweep so far (plan order,
// failed points included, the front among the measured) is handed on for the files.
TEST_F(SweepTest, AFailingPointIsKeptWithItsReasonAndTheOthersAreMeasured) {
    const Scene scene = loadBuiltin("textbook");
    const Settings base = loadShippedPreset("default");
    const SweepPlan plan = planSweep(base, {"lights.0.castsShadows=false,true", "shadow.resolution=64,256"});
    ASSERT_EQ(plan.error, "");
    SweepRunOptions options = smallRun(64, 36, 1, false);
    std::vector<std::size_t> sizes;
    options.onResult = [&](const SweepResult& soFar) {
        sizes.push_back(soFar.points.size());
        for (std::size_t k : soFar.front) EXPECT_FALSE(soFar.points[k].failed()) << soFar.points[k].label;
    };
    const SweepResult r = runSweep(scene, base, plan, options);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(sizes, (std::vector<std::size_t>{1, 2, 3, 4}));
    ASSERT_EQ(r.points.size(), 4u);
    for (const SweepPointResult& p : r.points) {
        const bool casts = p.values[0] == "true";
        EXPECT_EQ(p.failed(), !casts) << p.label << ": " << p.error;
        if (casts) {
            EXPECT_GT(p.costMs, 0.0) << p.label;
        } else {
            EXPECT_NE(p.error.find("no light casts a shadow with these values"), std::string::npos) << p.error;
            EXPECT_EQ(p.costMs, 0.0);
            EXPECT_FALSE(p.onFront);
        }
    }
    EXPECT_FALSE(r.front.empty());
    const LinePlot chart = sweepChart(r);
    EXPECT_EQ(chart.points[0].x.size(), 2u) << "failed points are not drawn";
}

}  // namespace
TEST_F(SweepTest, AnAxisOnTheAnimationTimePosesEachPointAtItsTime) {
    // animated_boxes' Move carries a box across the floor: at 0 s and 1.5 s its shadow falls elsewhere. The scene
    // comes posed at the base's time (0 s), as every command loads it; each point must be drawn and measured at
    // its own time, as one measurement of the scene posed there gives.
    const std::string path = std::string(SHADOWLAB_SOURCE_DIR) + "/tests/data/scenes/animated_boxes.gltf";
    SceneLoadResult loaded = loadGltfScene(path);
    ASSERT_TRUE(loaded.scene) << loaded.error;
    Scene scene = std::move(*loaded.scene);
    Settings base = loadShippedPreset("default");
    ASSERT_EQ(applySettingOverride(base, "animation.play=Move"), "");
    ASSERT_EQ(applySettingOverride(base, "shadow.resolution=512"), "");
    ASSERT_EQ(poseScene(scene, base.animation), "");
    const SweepPlan plan = planSweep(base, {"animation.time=0,1.5"});
    ASSERT_EQ(plan.error, "");
    const SweepRunOptions options = smallRun(160, 90, 1, false);
    const SweepResult r = runSweep(scene, base, plan, options);
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(r.points.size(), 2u);
    EXPECT_EQ(r.references, 2) << "the reference follows the pose";
    std::vector<AccuracyCounts> alone;
    for (const SweepPointResult& p : r.points) {
        ASSERT_FALSE(p.failed()) << p.label << ": " << p.error;
        Scene posed = loadGltfScene(path).scene.value();
        ASSERT_EQ(poseScene(posed, p.settings.animation), "");
        AccuracyMeter meter;
        const Camera camera = cameraFor(p.settings.camera, posed, 160.0 / 90.0);
        const AccuracyReport report = meter.measure(posed, p.settings, camera, 160, 90);
        ASSERT_TRUE(report.ok) << report.error;
        EXPECT_EQ(p.accuracy.counts.lit, report.counts.lit) << p.label;
        EXPECT_EQ(p.accuracy.counts.shadowed, report.counts.shadowed) << p.label;
        EXPECT_EQ(p.accuracy.counts.wrong, report.counts.wrong) << p.label;
        EXPECT_DOUBLE_EQ(p.accuracy.meanError, report.meanError) << p.label;
        alone.push_back(report.counts);
    }
    EXPECT_NE(alone[0].shadowed, alone[1].shadowed) << "the two times must differ for this test to tell them apart";
}

// Issue 21: the technique and the blur width as axes. Each point's cost counts the moments and blur passes (timed,
// each point re-running them with its own width), and with a light of a size the soft numbers come in every output
// and the chart and front use the soft mean |S-V|.
TEST_F(SweepTest, TechniqueByBlurWidthCostsTheMomentsAndBlurAndShowsTheSoftError) {
    const Scene scene = loadBuiltin("textbook");
    Settings base = loadShippedPreset("default");
    base.lights[0].size = 2.0f;  // degrees: a soft sun
    base.reference.softRays = 64;
    base.lights[0].shadow.resolution = 512;
    const SweepPlan plan = planSweep(base, {"filter.kind=pcf,vsm,evsm4,msm", "filter.blurWidth=3,9"});
    ASSERT_EQ(plan.error, "");
    const SweepRunOptions options = smallRun(160, 90, 2, false);
    const SweepResult r = runSweep(scene, base, plan, options);
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(r.points.size(), 8u);
    std::map<std::pair<FilterKind, float>, double> softError;  // by technique and blur width
    for (const SweepPointResult& p : r.points) {
        SCOPED_TRACE(p.label);
        ASSERT_FALSE(p.failed()) << p.error;
        const bool moments = p.settings.filter.kind != FilterKind::Pcf;
        std::printf("%-10s shadow %.3f moments %.3f blur %.3f main %.3f = %.3f ms; soft |S-V| %.4f, bleeding %.2f %%, "
                    "over-darkening %.2f %%\n",
                    p.label.c_str(), p.shadowMs, p.momentsMs, p.blurMs, p.mainMs, p.costMs, p.soft.meanError,
                    p.soft.bleedingPercent, p.soft.overDarkeningPercent);
        EXPECT_EQ(p.momentsMs > 0.0, moments);
        EXPECT_EQ(p.blurMs > 0.0, moments);
        EXPECT_NEAR(p.costMs, p.shadowMs + p.momentsMs + p.blurMs + p.mainMs, 1e-9);
        ASSERT_TRUE(p.soft.measured);
        softError[{p.settings.filter.kind, p.settings.filter.blurWidth}] = p.soft.meanError;
    }
    // The width changes a moments technique's picture (its blur re-ran per point), not PCF's.
    ASSERT_EQ(softError.size(), 8u);
    auto at = [&](FilterKind kind, float width) { return softError[std::make_pair(kind, width)]; };
    EXPECT_EQ(at(FilterKind::Pcf, 3.0f), at(FilterKind::Pcf, 9.0f));
    for (FilterKind kind : {FilterKind::Vsm, FilterKind::Evsm4, FilterKind::Msm})
        EXPECT_NE(at(kind, 3.0f), at(kind, 9.0f)) << filterTechnique(kind).name;

    EXPECT_TRUE(sweepSoftError(r));
    const LinePlot chart = sweepChart(r);
    EXPECT_NE(chart.yLabel.find("soft reference"), std::string::npos) << chart.yLabel;
    EXPECT_NE(chart.xLabel.find("moments + blur"), std::string::npos) << chart.xLabel;
    ASSERT_EQ(chart.points[0].y.size(), 8u);
    for (std::size_t i = 0; i < 8; ++i) EXPECT_EQ(chart.points[0].y[i], r.points[i].soft.meanError);
    for (std::size_t i : r.front)  // the front is over the soft error: nothing beats a front point on both
        for (const SweepPointResult& q : r.points)
            EXPECT_FALSE(q.costMs < r.points[i].costMs && q.soft.meanError < r.points[i].soft.meanError)
                << q.label << " beats front point " << r.points[i].label;

    const nlohmann::json json = sweepToJson(r);
    EXPECT_EQ(json["frontError"], "mean |S-V| against the soft reference");
    for (const nlohmann::json& p : json["points"]) {
        EXPECT_TRUE(p.contains("momentsPassMs") && p.contains("blurPassMs"));
        ASSERT_TRUE(p["soft"].is_object());
        EXPECT_TRUE(p["soft"].contains("bleedingPercent") && p["soft"].contains("overDarkeningPercent"));
    }
    const std::string csv = sweepToCsv(r);
    const std::string header = csv.substr(0, csv.find('\n'));
    for (const char* column : {"momentsPassMs", "blurPassMs", "softMeanError", "softBleedingPercent",
                               "softOverDarkeningPercent"})
        EXPECT_NE(header.find(column), std::string::npos) << column;
}

// The mips pass is its own line of the cost split: nonzero with filter.momentMips, zero without, counted in the cost,
// and a column of the JSON and CSV.
TEST_F(SweepTest, MomentMipsAreTheirOwnCostColumn) {
    const Scene scene = loadBuiltin("textbook");
    Settings base = loadShippedPreset("default");
    base.filter.kind = FilterKind::Vsm;
    base.lights[0].shadow.resolution = 512;
    const SweepPlan plan = planSweep(base, {"filter.momentMips=false,true"});
    ASSERT_EQ(plan.error, "");
    SweepRunOptions options;
    options.width = 160;
    options.height = 90;
    options.frames = 2;
    options.measurePreset = false;
    const SweepResult r = runSweep(scene, base, plan, options);
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(r.points.size(), 2u);
    for (const SweepPointResult& p : r.points) {
        SCOPED_TRACE(p.label);
        ASSERT_FALSE(p.failed()) << p.error;
        std::printf("%-22s moments %.3f blur %.3f mips %.3f ms\n", p.label.c_str(), p.momentsMs, p.blurMs, p.mipsMs);
        EXPECT_EQ(p.mipsMs > 0.0, p.settings.filter.momentMips);
        EXPECT_GT(p.blurMs, 0.0);
        EXPECT_NEAR(p.costMs, p.shadowMs + p.momentsMs + p.blurMs + p.mipsMs + p.mainMs, 1e-9);
    }
    const nlohmann::json json = sweepToJson(r);
    EXPECT_EQ(json["points"][0]["mipsPassMs"], 0.0);
    EXPECT_GT(json["points"][1]["mipsPassMs"].get<double>(), 0.0);
    const std::string csv = sweepToCsv(r);
    EXPECT_NE(csv.substr(0, csv.find('\n')).find("blurPassMs,mipsPassMs,mainPassMs"), std::string::npos);
}

}  // namespace shadowlab::test
