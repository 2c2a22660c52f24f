// The Accuracy panel, driven through ImGui's IO at its real widgets: Measure gives numbers while UI frames keep being
// built (the work runs on the editor's accuracy worker, in its own EGL context), an edit makes them stale, Auto
// measures once after the view is still, Suggest bias finds and applies a bias, the overlay view shows acne in red,
// Cancel stops a job, and a scene switch during a measurement is safe.
#include "accuracy/accuracy_overlay.h"
#include "editor_harness.h"
#include "settings/preset_io.h"
#include "settings/settings_fields.h"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <functional>
#include <mutex>
#include <thread>

namespace shadowlab::editor::test {

namespace {

// The smallest first-run layout: a viewport of about 650x450 keeps measurements quick on llvmpipe.
constexpr int kWidth = 1280, kHeight = 720;

// Holds a bias search on its worker thread after its first candidate until the job is cancelled (the worker's step
// hook), so a test acts while the search certainly runs.
class SearchGate {
public:
    explicit SearchGate(AccuracyWorker& worker) {
        worker.setStepHook([this](const AccuracyProgress& progress) {
            {
                std::lock_guard<std::mutex> lock(mutex_);
                held_ = true;
            }
            signal_.notify_all();
            const auto start = std::chrono::steady_clock::now();
            while (!progress.cancel.load() &&
                   std::chrono::steady_clock::now() - start < std::chrono::duration<double>(kWorkerCeilingSeconds))
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
        });
    }
    bool waitUntilHeld() {
        std::unique_lock<std::mutex> lock(mutex_);
        return signal_.wait_for(lock, std::chrono::duration<double>(kWorkerCeilingSeconds), [this] { return held_; });
    }

private:
    std::mutex mutex_;
    std::condition_variable signal_;
    bool held_ = false;
};

class EditorAccuracy : public ::testing::Test {
protected:
    void SetUp() override {
        folder = testFolder(::testing::UnitTest::GetInstance()->current_test_info()->name());
    }
    void open(const std::string& preset = "default", int width = kWidth, int height = kHeight) {
        EditorOptions options = testOptions(folder);
        options.preset = preset;
        harness = std::make_unique<EditorHarness>(options, width, height);
        harness->settle();
    }
    // Auto's delay on the editor's clock: the view counts as still once the clock has moved this far.
    void letTheViewBeStill() { harness->advanceClock(AccuracyState::kAutoDelaySeconds); }
    std::filesystem::path folder;
    std::unique_ptr<EditorHarness> harness;
};

}  // namespace

TEST_F(EditorAccuracy, MeasureGivesNumbersWhileTheUiKeepsDrawing) {
    open();
    EditorHarness& h = *harness;
    const AccuracyState& a = h.state().accuracy;
    EXPECT_FALSE(a.report.has_value());
    h.click("accuracy.measure");
    const long framesBefore = h.state().renderedFrames + h.state().idleFrames;
    const int framesDuring = harness->waitForAccuracyJob();
    EXPECT_GT(h.state().renderedFrames + h.state().idleFrames, framesBefore);
    EXPECT_GE(framesDuring, 1) << "the UI thread must keep building frames while the worker measures";
    ASSERT_TRUE(a.report.has_value()) << a.error;
    EXPECT_TRUE(a.report->ok);
    EXPECT_EQ(a.error, "");
    const ControlRect view = h.rect("viewport.image");
    EXPECT_EQ(a.report->width, int(view.w));
    EXPECT_EQ(a.report->height, int(view.h));
    EXPECT_EQ(a.report->counts.pixels, std::size_t(view.w) * std::size_t(view.h));
    EXPECT_GT(a.report->counts.lit, 1000u);
    EXPECT_GT(a.report->cost.rays, 0u);
    // The default preset is free of acne on the textbook; the numbers are shown, and they are current.
    EXPECT_LT(a.report->acnePercent, 0.1);
    EXPECT_EQ(a.stale, "");
    EXPECT_TRUE(h.reveal("accuracy.acne"));
    EXPECT_FALSE(h.hasControl("accuracy.stale"));
    EXPECT_EQ(a.measurements, 1);
    h.saveWindow("accuracy-measured");
    // The counts and the cost are one click away (pictures to look at).
    h.click("accuracy.tab.counts");
    h.saveWindow("accuracy-counts");
    h.click("accuracy.tab.cost");
    h.saveWindow("accuracy-cost");
}

TEST_F(EditorAccuracy, AnEditOrACameraMoveMakesTheNumbersStale) {
    open();
    EditorHarness& h = *harness;
    const AccuracyState& a = h.state().accuracy;
    h.click("accuracy.measure");
    harness->waitForAccuracyJob();
    ASSERT_TRUE(a.report.has_value());
    ASSERT_EQ(a.stale, "");
    h.drag("shadow.depthBias", 60.0f, 0.0f);
    h.frame();
    EXPECT_NE(a.stale.find("shadow.depthBias changed"), std::string::npos) << a.stale;
    EXPECT_TRUE(h.reveal("accuracy.stale"));
    h.drag("viewport.image", 60.0f, 10.0f);
    EXPECT_NE(a.stale.find("the camera moved"), std::string::npos) << a.stale;
    // The view mode is not part of what was measured.
    h.click("accuracy.measure");
    harness->waitForAccuracyJob();
    EXPECT_EQ(a.stale, "");
    h.click("view");
    h.click("view=shadow");
    EXPECT_EQ(a.stale, "");
}

TEST_F(EditorAccuracy, AutoMeasuresOnceTheViewIsStillAndNeverTwiceForTheSameView) {
    open();
    EditorHarness& h = *harness;
    const AccuracyState& a = h.state().accuracy;
    constexpr double kHalf = AccuracyState::kAutoDelaySeconds / 2.0;  // exact in binary: no rounding at the edge
    h.click("accuracy.auto");
    ASSERT_TRUE(a.autoMeasure);
    // Frames alone do not move the editor's clock: however many are drawn (however slowly), the view has not yet
    // been still for Auto's delay.
    h.frame(5);
    EXPECT_FALSE(a.running) << "Auto measured before the view was still for its delay";
    // Still for the delay: the first measurement comes without a click, on that frame.
    h.advanceClock(AccuracyState::kAutoDelaySeconds);
    h.frame();
    ASSERT_TRUE(a.running) << "the view was still for Auto's delay, and no measurement started";
    harness->waitForAccuracyJob();
    ASSERT_EQ(a.measurements, 1);
    EXPECT_EQ(a.stale, "");

    // An edit: a live count follows it, but no full measure while it is fresh; then one once the view has been still
    // for the delay.
    h.drag("shadow.depthBias", 60.0f, 0.0f);
    h.framesUntil([&] { return !a.liveRunning; }, "Auto's live count after the edit");
    EXPECT_FALSE(a.running) << "Auto waits until the view is still";
    EXPECT_EQ(a.measurements, 1);
    h.advanceClock(kHalf);
    h.frame();
    EXPECT_FALSE(a.running) << "half of Auto's delay after the edit";
    h.advanceClock(kHalf);
    h.frame();
    EXPECT_TRUE(a.running) << "Auto's delay after the edit: the full measure starts";
    harness->waitForAutoMeasurements(2);
    EXPECT_EQ(a.measurements, 2);
    EXPECT_EQ(a.stale, "");
    // Still: never again for the same view and settings, however long it stays so.
    h.advanceClock(3600.0);
    h.frame(5);
    EXPECT_FALSE(a.running);
    EXPECT_EQ(a.measurements, 2);
}

// Live accuracy: with Auto on and a full measure done, dragging a bias slider re-counts on the GPU while the mouse
// button is still down — the acne number follows the slider — and the full measure (causes, overlay) runs once,
// after the release, agreeing with the last live count of the same view.
TEST_F(EditorAccuracy, AutoUpdatesTheNumbersLiveWhileASliderIsDragged) {
    open("acne");
    EditorHarness& h = *harness;
    const AccuracyState& a = h.state().accuracy;
    h.click("accuracy.auto");
    letTheViewBeStill();
    harness->waitForAutoMeasurements(1);
    ASSERT_EQ(a.measurements, 1);
    ASSERT_TRUE(a.report.has_value());
    ASSERT_FALSE(a.report->live);
    ASSERT_GT(a.report->acnePercent, 1.0) << "no slope bias: acne";

    // Press at the slider's left end (slope bias ~0) and move right, holding the button.
    const ControlRect slider = h.rect("shadow.slopeScaledDepthBias");
    const float y = slider.centerY();
    h.moveMouse(slider.x + 2.0f, y);
    ImGui::GetIO().MouseDown[0] = true;
    h.frame();
    struct Seen {
        float slope;
        std::size_t acne;
    };
    std::vector<Seen> seen;
    for (int step = 0; step < 6; ++step) {
        h.moveMouse(slider.x + 2.0f + 6.0f * float(step), y);
        h.frame();  // the slider's edit happened in the UI, after this frame's accuracy bookkeeping
        // Frames until the numbers describe exactly this view (the slider at its left end may still read 0: the
        // full measure's view).
        h.framesUntil([&] { return a.stale.empty(); }, "a live count of the slider's step " + std::to_string(step));
        ASSERT_EQ(a.stale, "") << "no live count during the drag, step " << step;
        const float slope = findSettingsField("shadow.slopeScaledDepthBias")->get(h.state().settings).get<float>();
        if (slope != 0.0f) EXPECT_TRUE(a.report->live) << "step " << step;
        EXPECT_TRUE(ImGui::GetIO().MouseDown[0]);
        EXPECT_FALSE(a.running) << "no full measure while the slider is held";
        EXPECT_EQ(a.measurements, 1);
        seen.push_back({slope, a.report->counts.acne});
        if (step == 2) {
            EXPECT_TRUE(h.reveal("accuracy.live"));
            h.saveWindow("accuracy-live-drag");
        }
    }
    ASSERT_GE(a.liveMeasurements, 5);
    std::string trail;
    for (const Seen& s : seen) trail += std::to_string(s.slope) + ": " + std::to_string(s.acne) + " acne; ";
    std::printf("live counts during the drag: %s\n", trail.c_str());
    // The slider moved up, and the acne the live counts saw fell with it.
    EXPECT_GT(seen.back().slope, seen.front().slope);
    EXPECT_LT(seen.back().acne, seen.front().acne / 2) << seen.front().acne << " -> " << seen.back().acne;
    std::size_t distinct = 1;
    for (std::size_t i = 1; i < seen.size(); ++i) distinct += seen[i].acne != seen[i - 1].acne;
    EXPECT_GE(distinct, 3u) << "the numbers must follow the slider, not jump once";

    // Release: the full measure of the same view runs once, and agrees with the live count.
    const AccuracyCounts live = a.report->counts;
    ImGui::GetIO().MouseDown[0] = false;
    h.frame(2);
    // Auto's full measure runs once the view has been still for its delay.
    auto waitForMeasurements = [&](long n) {
        letTheViewBeStill();
        harness->waitForAutoMeasurements(n);
    };
    waitForMeasurements(2);
    ASSERT_EQ(a.measurements, 2);
    ASSERT_FALSE(a.report->live);
    EXPECT_EQ(a.stale, "");
    EXPECT_EQ(a.report->counts.acne, live.acne);
    EXPECT_EQ(a.report->counts.wrong, live.wrong);
    EXPECT_EQ(a.report->counts.mismatched, live.mismatched);
    ASSERT_TRUE(h.reveal("accuracy.measure"));
    EXPECT_FALSE(h.hasControl("accuracy.live"));

    // A camera move needs new rays: no live count, the full measure follows once still.
    const long liveBefore = a.liveMeasurements;
    h.drag("viewport.image", 40.0f, 0.0f);
    h.frame(3);
    EXPECT_EQ(a.liveMeasurements, liveBefore);
    waitForMeasurements(3);
    EXPECT_EQ(a.measurements, 3);
    EXPECT_EQ(a.liveMeasurements, liveBefore);
}

TEST_F(EditorAccuracy, SuggestBiasFromZeroBiasReachesTheAcneLimitAndAppliesItToThePreset) {
    // A user preset with every bias off (and the default's other settings): opening it leaves nothing unsaved.
    const PresetLoadResult base = loadPresetFile(std::string(SHADOWLAB_SOURCE_DIR) + "/presets/default.json");
    ASSERT_TRUE(base.settings.has_value());
    Settings zero = *base.settings;
    zero.lights[0].shadow.depthBias = 0.0f;
    zero.lights[0].shadow.slopeScaledDepthBias = 0.0f;
    zero.lights[0].shadow.normalOffset = 0.0f;
    const std::string path = (folder / "zero-bias.json").string();
    ASSERT_EQ(savePresetFile(path, zero, "zero-bias"), "");
    open(path);
    EditorHarness& h = *harness;
    const AccuracyState& a = h.state().accuracy;
    ASSERT_EQ(h.state().settings.lights[0].shadow.depthBias, 0.0f);
    ASSERT_FALSE(h.state().preset.dirty(h.state().settings));

    h.click("accuracy.measure");
    harness->waitForAccuracyJob();
    ASSERT_TRUE(a.report.has_value());
    EXPECT_GT(a.report->acnePercent, 1.0) << "zero bias should show acne";

    h.click("accuracy.suggest");
    std::size_t liveSteps = 0;  // the path table fills while the search runs
    float liveProgress = 0.0f;
    const int frames = harness->waitForAccuracyJob([&](const AccuracyState& s) {
        liveSteps = std::max(liveSteps, s.steps.size());
        liveProgress = std::max(liveProgress, s.progress);
    });
    EXPECT_GE(frames, 1);
    EXPECT_GT(liveSteps, 0u) << "no candidate reached the table while the search ran";
    EXPECT_GT(liveProgress, 0.0f);
    ASSERT_TRUE(a.tune.has_value()) << a.error;
    ASSERT_TRUE(a.tune->ok) << a.tune->error;
    EXPECT_TRUE(a.tune->reachedLimit);
    EXPECT_LE(a.report->acnePercent, 0.1);
    EXPECT_GE(a.steps.size(), 3u);
    EXPECT_EQ(a.steps.size(), a.tune->path.size());
    // Applied through the key table: the settings carry the result and the preset shows unsaved changes.
    const ShadowMapSettings& best = a.tune->best.lights[0].shadow;
    EXPECT_EQ(h.state().settings.lights[0].shadow.depthBias, best.depthBias);
    EXPECT_EQ(h.state().settings.lights[0].shadow.slopeScaledDepthBias, best.slopeScaledDepthBias);
    EXPECT_EQ(h.state().settings.lights[0].shadow.normalOffset, best.normalOffset);
    EXPECT_GT(best.depthBias + best.slopeScaledDepthBias + best.normalOffset, 0.0f);
    EXPECT_TRUE(h.state().preset.dirty(h.state().settings));
    EXPECT_NE(h.editor().windowTitle().find(" *"), std::string::npos);
    EXPECT_EQ(a.stale, "") << "the numbers describe the applied settings";
    EXPECT_TRUE(h.reveal("accuracy.result"));
    h.saveWindow("accuracy-suggested");

    // Save as preset... opens the preset session's Save As, and the saved preset carries the bias.
    h.click("accuracy.saveAs");
    h.frame(2);
    ASSERT_TRUE(h.reveal("saveAs.name"));
    h.selectAllAndType("suggested");
    const std::filesystem::path saved = folder / "user-presets" / "suggested.json";
    ASSERT_TRUE(std::filesystem::exists(saved));
    const PresetLoadResult back = loadPresetFile(saved.string());
    ASSERT_TRUE(back.settings.has_value());
    EXPECT_EQ(back.settings->lights[0].shadow.depthBias, best.depthBias);
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings));
}

// Suggest with a moments technique: the search combo (tune's --search) chooses the technique's own trade-off, the
// tuner searches VSM's minVariance and bleedReduction (FilterTechnique::tradeOff) and the result goes into the preset;
// the Tune tab says what was searched, for which light, and shows each candidate's keys. A small map keeps it fast.
TEST_F(EditorAccuracy, SuggestWithAMomentsTechniqueSearchesItsTradeOffAndAppliesItToThePreset) {
    const PresetLoadResult base = loadPresetFile(std::string(SHADOWLAB_SOURCE_DIR) + "/presets/default.json");
    ASSERT_TRUE(base.settings.has_value());
    Settings vsm = *base.settings;
    vsm.filter.kind = FilterKind::Vsm;
    vsm.filter.minVariance = 1e-3f;    // far off the best: a search must move a key
    vsm.filter.bleedReduction = 0.6f;
    vsm.lights[0].shadow.resolution = 256;
    const std::string path = (folder / "vsm.json").string();
    ASSERT_EQ(savePresetFile(path, vsm, "vsm"), "");
    open(path, 1024, 576);  // a small window: each candidate measures the viewport's pixels
    EditorHarness& h = *harness;
    const AccuracyState& a = h.state().accuracy;
    ASSERT_FALSE(h.state().preset.dirty(h.state().settings));
    const Settings before = h.state().settings;

    // The combo offers tune's four searches; "technique" = the technique's trade-off alone.
    h.click("accuracy.search");
    h.click("accuracy.search=technique");
    ASSERT_EQ(a.search, TuneSearch::TradeOff);
    h.click("accuracy.suggest");
    h.waitForAccuracyJob();
    ASSERT_TRUE(a.tune.has_value()) << a.error;
    ASSERT_TRUE(a.tune->ok) << a.tune->error;
    EXPECT_EQ(a.searched, TuneSearch::TradeOff);
    EXPECT_EQ(a.searchedLight, 0u);
    ASSERT_TRUE(a.tune->tradeOffSearched);
    EXPECT_EQ(a.tune->tradeOffKeys, (std::vector<std::string>{"filter.minVariance", "filter.bleedReduction"}));
    for (const TuneStep& s : a.tune->path) EXPECT_TRUE(s.tradeOffStep) << "candidate " << s.index << " searched the bias";
    ASSERT_TRUE(a.tune->reachedLimit);
    // Applied through the key table: the chosen values are the preset's, the bias untouched, the preset unsaved.
    const FilterSettings& chosen = a.tune->best.filter;
    EXPECT_EQ(h.state().settings.filter.minVariance, chosen.minVariance);
    EXPECT_EQ(h.state().settings.filter.bleedReduction, chosen.bleedReduction);
    EXPECT_TRUE(chosen.minVariance != before.filter.minVariance || chosen.bleedReduction != before.filter.bleedReduction)
        << "the search kept the start";
    EXPECT_EQ(h.state().settings.lights[0].shadow.depthBias, before.lights[0].shadow.depthBias);
    EXPECT_TRUE(h.state().preset.dirty(h.state().settings));
    EXPECT_EQ(a.stale, "") << "the numbers describe the applied settings";
    // The search's best candidate is no worse than the start by the trade-off's criterion.
    const TuneStep* best = nullptr;
    for (const TuneStep& s : a.tune->path)
        if (s.bestSoFar) best = &s;
    ASSERT_NE(best, nullptr);
    EXPECT_FALSE(betterTradeOff(a.tune->path.front(), *best));
    std::printf("editor technique search at %dx%d: %zu candidates in %.1f s; start minVariance %g bleedReduction %g: error %.5f, "
                "leak %.3f %%; chosen %g, %g: error %.5f, leak %.3f %%\n",
                a.report->width, a.report->height, a.tune->path.size(), a.tune->seconds, double(before.filter.minVariance),
                double(before.filter.bleedReduction), tradeOffError(a.tune->path.front()),
                tradeOffBleeding(a.tune->path.front()), double(chosen.minVariance), double(chosen.bleedReduction),
                tradeOffError(*best), tradeOffBleeding(*best));
    // The panel: what was searched, for which light; the candidates with the keys' values; the status line.
    EXPECT_TRUE(h.reveal("accuracy.searched"));
    EXPECT_TRUE(h.reveal("accuracy.tradeOffSteps"));
    EXPECT_TRUE(h.reveal("accuracy.result"));
    ASSERT_NE(h.state().lastMessage(), nullptr);
    EXPECT_NE(h.state().lastMessage()->text.find("filter.bleedReduction"), std::string::npos)
        << h.state().lastMessage()->text;
    h.saveWindow("accuracy-technique-suggested");
}

TEST_F(EditorAccuracy, OverlayViewShowsAcneInRed) {
    open("acne");
    EditorHarness& h = *harness;
    const AccuracyState& a = h.state().accuracy;
    h.click("view");
    h.click("view=accuracy overlay");
    EXPECT_TRUE(a.showOverlay);
    EXPECT_EQ(h.state().settings.view, ViewMode::Lit) << "the overlay is not a renderer setting";
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings));
    h.click("accuracy.measure");
    harness->waitForAccuracyJob();
    ASSERT_TRUE(a.report.has_value());
    EXPECT_GT(a.report->acnePercent, 1.0);
    ASSERT_NE(a.overlayTexture.id(), 0u);

    const ControlRect view = h.rect("viewport.image");
    auto redFraction = [&] {
        const std::vector<std::uint8_t> window = h.readWindow();
        long red = 0, all = 0;
        for (int y = int(view.y); y < int(view.y + view.h); ++y)
            for (int x = int(view.x); x < int(view.x + view.w); ++x) {
                const std::uint8_t* p = &window[(std::size_t(y) * h.width() + x) * 4];
                red += p[0] > 200 && p[1] < 70 && p[2] < 70;
                ++all;
            }
        return double(red) / double(all);
    };
    const double withOverlay = redFraction();
    h.saveWindow("accuracy-overlay");
    EXPECT_GT(withOverlay, 0.02) << "acne pixels are drawn red";
    // An edit: the overlay stays (the newest measurement) with a stale note over it.
    h.drag("shadow.slopeScaledDepthBias", 30.0f, 0.0f);
    h.frame();
    EXPECT_FALSE(a.stale.empty());
    h.saveWindow("accuracy-overlay-stale");
    EXPECT_GT(redFraction(), withOverlay * 0.8);
    // The lit view has no such red.
    h.click("view");
    h.click("view=lit");
    EXPECT_FALSE(a.showOverlay);
    EXPECT_LT(redFraction(), withOverlay * 0.1);
}

TEST_F(EditorAccuracy, OverlayViewRunsNoPassForACameraMoveButFollowsAnEdit) {
    open("default");
    EditorHarness& h = *harness;
    const AccuracyState& a = h.state().accuracy;
    h.click("view");
    h.click("view=accuracy overlay");
    h.click("accuracy.measure");
    harness->waitForAccuracyJob();
    ASSERT_NE(a.overlayTexture.id(), 0u);
    // The overlay hides the main view: orbiting only makes the numbers stale, no pass renders a picture nobody sees.
    const long rendered = h.state().renderedFrames;
    h.drag("viewport.image", 60.0f, 10.0f);
    h.frame();
    EXPECT_FALSE(a.stale.empty());
    EXPECT_EQ(h.state().renderedFrames, rendered);
    // A bias edit still renders, so the shadow map (and its viewer) follow it.
    h.drag("shadow.depthBias", 60.0f, 0.0f);
    h.frame();
    EXPECT_GT(h.state().renderedFrames, rendered);
    EXPECT_TRUE(h.state().stats.shadowPass.ran) << h.state().stats.shadowPass.reason;
    // Back to the lit view after another camera move: the moved camera is rendered then.
    const long beforeLit = h.state().renderedFrames;
    h.drag("viewport.image", -40.0f, 0.0f);
    h.frame();
    EXPECT_EQ(h.state().renderedFrames, beforeLit);
    h.click("view");
    h.click("view=lit");
    h.frame();
    EXPECT_GT(h.state().renderedFrames, beforeLit);
}

TEST_F(EditorAccuracy, CancelStopsABiasSearchAndKeepsTheSettings) {
    open("acne");
    EditorHarness& h = *harness;
    const AccuracyState& a = h.state().accuracy;
    const Settings before = h.state().settings;
    // The search is held after its first candidate until Cancel arrives: it certainly runs when it does.
    SearchGate gate(h.editor().accuracyWorker());
    h.click("accuracy.suggest");
    ASSERT_TRUE(gate.waitUntilHeld()) << "the search never measured its first candidate";
    ASSERT_TRUE(a.running);
    h.click("accuracy.cancel");
    harness->waitForAccuracyJob();
    EXPECT_FALSE(a.running);
    EXPECT_EQ(a.error, "cancelled");
    EXPECT_TRUE(h.state().settings == before) << "a cancelled search applies nothing";
    EXPECT_FALSE(h.state().preset.dirty(h.state().settings));
    // The worker takes the next job.
    h.click("accuracy.measure");
    harness->waitForAccuracyJob();
    ASSERT_TRUE(a.report.has_value());
    EXPECT_TRUE(a.report->ok);
}

TEST_F(EditorAccuracy, ASceneSwitchWhileMeasuringIsSafeAndMakesTheNumbersStale) {
    open();
    EditorHarness& h = *harness;
    const AccuracyState& a = h.state().accuracy;
    h.click("accuracy.measure");
    h.editor().requestScene("builtin:grazing");
    harness->waitForAccuracyJob();
    h.settle();
    ASSERT_EQ(h.state().sceneSpec, "builtin:grazing");
    ASSERT_TRUE(a.report.has_value()) << a.error;
    EXPECT_NE(a.stale.find("another scene"), std::string::npos) << a.stale;
    h.click("accuracy.measure");
    harness->waitForAccuracyJob();
    EXPECT_EQ(a.stale, "");
}

TEST_F(EditorAccuracy, ClosingTheEditorDuringASearchCancelsItAndEndsTheWorker) {
    open("acne");
    EditorHarness& h = *harness;
    // The search is held after its first candidate until it is cancelled: the editor certainly goes while the
    // worker is inside the search. It must cancel (else the gate holds the worker, and the join hangs into ctest's
    // timeout), join and free its GL context, and this process's own context keeps working.
    SearchGate gate(h.editor().accuracyWorker());
    h.click("accuracy.suggest");
    ASSERT_TRUE(gate.waitUntilHeld()) << "the search never measured its first candidate";
    ASSERT_TRUE(h.state().accuracy.running);
    harness.reset();
    open();
    EXPECT_TRUE(harness->state().stats.ok);
    harness->click("accuracy.measure");
    harness->waitForAccuracyJob();
    ASSERT_TRUE(harness->state().accuracy.report.has_value());
    EXPECT_TRUE(harness->state().accuracy.report->ok);
}

// The roof (issue 9, observation 3) in the editor: the Causes tab names the culled caster with its remedy and share,
// the overlay by cause paints it, and Suggest bias applies a cull mode that fixes it.
TEST_F(EditorAccuracy, RoofCausesTabNamesTheCulledCasterAndSuggestBiasAppliesACullMode) {
    // Back-face culling drops the single-sided roof (the default, none, keeps it).
    const PresetLoadResult base = loadPresetFile(std::string(SHADOWLAB_SOURCE_DIR) + "/presets/default.json");
    ASSERT_TRUE(base.settings.has_value());
    Settings backCulled = *base.settings;
    backCulled.lights[0].shadow.cullMode = CullMode::Back;
    const std::string path = (folder / "cull-back.json").string();
    ASSERT_EQ(savePresetFile(path, backCulled, "cull-back"), "");
    open(path);
    EditorHarness& h = *harness;
    h.editor().requestScene("builtin:roof");
    h.settle();
    ASSERT_EQ(h.state().sceneSpec, "builtin:roof");
    ASSERT_EQ(h.state().settings.lights[0].shadow.cullMode, CullMode::Back);
    const AccuracyState& a = h.state().accuracy;
    h.click("accuracy.measure");
    harness->waitForAccuracyJob();
    ASSERT_TRUE(a.report.has_value()) << a.error;
    EXPECT_GT(a.report->leakPercent, 50.0);
    EXPECT_EQ(a.report->mainCause(), MismatchCause::CasterCulled);
    h.click("accuracy.tab.causes");
    h.frame(2);
    EXPECT_TRUE(h.reveal("accuracy.causes"));
    h.click("view");
    h.click("view=accuracy overlay by cause");
    h.frame(2);
    EXPECT_TRUE(a.showOverlay);
    EXPECT_EQ(a.uploadedKind, OverlayKind::Cause);
    const CauseInfo& culled = causeInfo(MismatchCause::CasterCulled);
    const ControlRect view = h.rect("viewport.image");
    const std::vector<std::uint8_t> window = h.readWindow();
    long painted = 0;
    for (int y = int(view.y); y < int(view.y + view.h); ++y)
        for (int x = int(view.x); x < int(view.x + view.w); ++x) {
            const std::uint8_t* p = &window[(std::size_t(y) * h.width() + x) * 4];
            painted += isShadeOf({"", culled.red, culled.green, culled.blue}, p);  // at the surface's shading
        }
    EXPECT_GT(painted, 500) << "the culled caster's leak is painted in its cause colour";
    h.saveWindow("accuracy-roof-by-cause");

    h.click("accuracy.suggest");
    harness->waitForAccuracyJob();
    ASSERT_TRUE(a.tune.has_value()) << a.error;
    ASSERT_TRUE(a.tune->reachedLimit);
    EXPECT_NE(h.state().settings.lights[0].shadow.cullMode, CullMode::Back) << "the applied settings carry the new cull mode";
    EXPECT_EQ(h.state().settings.lights[0].shadow.cullMode, a.tune->best.lights[0].shadow.cullMode);
    EXPECT_LT(a.report->leakPercent, 1.0);
    EXPECT_EQ(a.stale, "");
    h.saveWindow("accuracy-roof-suggested");
}

// A coarse map: the Numbers tab warns that acne and leak cannot judge it and points at wrong pixels.
TEST_F(EditorAccuracy, CoarseMapWarningShowsInTheNumbersTab) {
    open();
    EditorHarness& h = *harness;
    ASSERT_TRUE(h.state().edit("shadow.resolution", 16));
    h.frame(2);
    h.click("accuracy.measure");
    harness->waitForAccuracyJob();
    const AccuracyState& a = h.state().accuracy;
    ASSERT_TRUE(a.report.has_value()) << a.error;
    EXPECT_NE(a.report->coarseMapWarning, "");
    h.click("accuracy.tab.numbers");
    h.frame(2);
    EXPECT_TRUE(h.reveal("accuracy.coarseMap"));
    EXPECT_TRUE(h.reveal("accuracy.wrong"));
}

// Flicker from the panel: a light turned by a sub-texel step on a point-filtered 256² map flickers at the shadow
// edges and the tab shows the figures and the overlay; a camera moved by sub-texel steps flickers 0 with no shadow
// view re-rendered.
TEST_F(EditorAccuracy, FlickerTabPlaysAMotionAndShowsItsFigures) {
    open();
    EditorHarness& h = *harness;
    ASSERT_TRUE(h.state().edit("filter.kind", "point"));
    ASSERT_TRUE(h.state().edit("shadow.resolution", 256));
    h.frame(2);
    h.click("accuracy.tab.flicker");
    const AccuracyState& a = h.state().accuracy;
    EXPECT_EQ(a.flickerMotion.kind, MotionKind::Light) << "the tab starts with a light motion";
    h.state().accuracy.flickerMotion.step = 0.4;
    h.state().accuracy.flickerMotion.frames = 3;
    h.click("accuracy.flicker.measure");
    harness->waitForAccuracyJob();
    ASSERT_TRUE(a.flicker.has_value()) << a.error;
    EXPECT_TRUE(a.flicker->ok);
    EXPECT_EQ(a.flicker->pairs.size(), 2u);
    EXPECT_GT(a.flicker->maxFlickerPercent, 0.0);
    EXPECT_LT(a.flicker->stepTexels, 1.0);
    const ControlRect view = h.rect("viewport.image");
    EXPECT_EQ(a.flicker->width, int(view.w));
    h.frame(2);
    EXPECT_TRUE(h.reveal("accuracy.flicker.figure"));
    EXPECT_TRUE(h.reveal("accuracy.flicker.overlay"));
    EXPECT_FALSE(a.report.has_value()) << "flicker keeps its own result; the Numbers tab is not overwritten";
    h.saveWindow("accuracy-flicker-light");

    h.state().accuracy.flickerMotion.kind = MotionKind::Camera;
    h.state().accuracy.flickerMotion.step = 0.02;
    h.state().accuracy.flickerMotion.frames = 4;
    h.click("accuracy.flicker.measure");
    harness->waitForAccuracyJob();
    ASSERT_TRUE(a.flicker.has_value()) << a.error;
    EXPECT_EQ(a.flicker->maxFlickerPercent, 0.0);
    for (const FlickerPair& p : a.flicker->pairs) EXPECT_EQ(p.shadowViewsRendered, 0u);
    h.saveWindow("accuracy-flicker-camera");
}

}  // namespace shadowlab::editor::test
