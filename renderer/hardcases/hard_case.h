#pragma once
// One numerically hard case of ../shared/HARD_CASES.md as the suite runs it (`shadowlab hardcases`): what it
// measured, each figure beside the document's threshold, and the pictures that show it. The cases live one per file
// (case_NN_*.cpp); hard_case_runner.h selects, runs and reports them. Knows no window, UI or CLI.
#include "accuracy/accuracy_meter.h"
#include "accuracy/flicker.h"
#include "frame/frame_stats.h"
#include "frame/renderer.h"
#include "reference/surface_samples.h"
#include "scene/scene.h"
#include "settings/settings.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab::hardcases {

// Not run: the sub-check needs something the build lacks (a setting another issue adds, a file that is absent);
// it never counts as passing.
// Info: a figure shown for context, not a criterion of the document.
enum class Verdict { Pass, Fail, NotRun, Info };
const char* verdictName(Verdict verdict);

// One sub-check: what was measured, the figure, the document's threshold, the verdict.
struct CaseRow {
    std::string measured;   // "acne, max over t"
    std::string figure;     // "0.012 %"
    std::string threshold;  // "< 0.1 %"
    Verdict verdict = Verdict::Pass;
};

struct CaseResult {
    int number = 0;
    std::string title;
    std::vector<CaseRow> rows;
    std::vector<std::string> pictures;  // files written into the output folder
    std::string error;                  // the case could not run at all (counts as a failure)
    double seconds = 0.0;

    // Adds a row whose verdict is `pass`.
    void check(std::string measured, std::string figure, std::string threshold, bool pass);
    void notRun(std::string measured, std::string threshold, std::string why);
    void info(std::string measured, std::string figure, std::string note);
    bool failed() const;  // an error or any failing row
};

struct HardCaseOptions {
    bool quick = false;        // small maps and views, fewer sweep steps (ctest)
    std::string outDir;        // "" = write no pictures
    std::string sharedScenes;  // the ../shared/scenes folder
    std::string assimpModels = "/usr/share/assimp/models/glTF2";  // assimp-testmodels (case 16, 17)
};

// A view rendered by the renderer (no reference): its pixels and the frame's stats.
struct RenderedView {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // row 0 = TOP (PNG order)
    FrameStats stats;
    int red(int x, int yTop) const { return rgba[(std::size_t(yTop) * std::size_t(width) + std::size_t(x)) * 4]; }
};

// What a case works with: the options, one accuracy meter and one renderer on the caller's GL context, the
// convention every rendered Settings gets (case 5 re-runs the cases in the reversed-Z convention), the pictures.
class CaseContext {
public:
    CaseContext(const HardCaseOptions& options, AccuracyMeter& meter, Renderer& renderer);

    const HardCaseOptions& options() const { return options_; }
    bool quick() const { return options_.quick; }
    // `full` in the full run, `quickValue` with --quick.
    int pick(int full, int quickValue) const { return options_.quick ? quickValue : full; }
    Renderer& renderer() { return renderer_; }
    AccuracyMeter& meter() { return meter_; }

    // The reversed-Z convention (case 5): nullopt = as the settings say. Applied to every Settings a case
    // renders or measures, through the key table's `lights.N.shadow.reversedZ`.
    std::optional<bool> reversedZ;
    // The key a convention needs ("" when the key table has it): why reversed-Z cannot run in this build.
    static std::string reversedZMissing();
    // Applies the convention to every light; "" or why not.
    std::string applyConvention(Settings& settings) const;

    // AccuracyMeter::measure of light 0 for the settings' camera at width x height; writes the error overlay as
    // `picture`.png into the output folder when a name is given. Records the mask for case 5.
    AccuracyReport measure(const Scene& scene, Settings settings, int width, int height,
                           const std::string& picture = "");
    // The flicker measure (accuracy/flicker.h) of `motion` from the settings' camera; writes the worst pair's two
    // frames as `picture`-a / -b and the flicker overlay as `picture`-overlay when a name is given.
    FlickerReport flicker(const Scene& scene, Settings settings, int width, int height, const Motion& motion,
                          const std::string& picture = "");
    // One frame of `renderer` (the context's own when null) into a fresh target.
    RenderedView render(const Scene& scene, Settings settings, int width, int height, const std::string& picture = "",
                        Renderer* renderer = nullptr);
    // The G-buffer of the settings' camera (world points per pixel, row 0 = top), through the renderer's scene.
    SurfaceSamples surfaces(const Scene& scene, const Settings& settings, int width, int height);

    // A scene under the shared scenes folder ("FlightHelmet_geometry/FlightHelmet.gltf"); nullopt with `why`.
    std::optional<Scene> sharedScene(const std::string& relative, std::string& why) const;
    // A scene of assimp-testmodels ("BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb").
    std::optional<Scene> assimpScene(const std::string& relative, std::string& why) const;

    // Writes an RGBA picture (row 0 = top) as `name`.png into the output folder (nothing without one) and lists it.
    void writePicture(const std::string& name, int width, int height, const std::vector<std::uint8_t>& rgba);

    // The case being run: set by the runner (and case 5's re-runs) through startCase.
    CaseResult* result = nullptr;
    void startCase(CaseResult* running) {
        result = running;
        measureIndex_ = 0;
    }
    // Case 5: the masks (S >= 0.5 per measured pixel, 2 = not measured) of every measurement, by label
    // "case/index" under the convention it ran in ("as set" or "reversed-Z"), recorded while recordMasks is set.
    bool recordMasks = false;
    std::map<std::string, std::map<std::string, std::vector<std::uint8_t>>> masks;
    // Case 5: each case's row verdicts, under the convention it ran in (recorded by runCase with the masks).
    std::map<std::string, std::map<int, std::vector<Verdict>>> verdicts;
    std::string conventionName() const { return reversedZ ? "reversed-Z" : "as set"; }
    // Off: measure / render write no pictures (case 5's re-runs).
    bool picturesOn = true;

private:
    const HardCaseOptions& options_;
    AccuracyMeter& meter_;
    Renderer& renderer_;
    int measureIndex_ = 0;
};

struct HardCase {
    int number = 0;
    const char* title = "";
    std::function<void(CaseContext&, CaseResult&)> run;
};

// The cases of HARD_CASES.md, in order.
const std::vector<HardCase>& hardCaseList();

// Number formatting for figures: "%.*g"-like with a unit.
std::string figure(double value, const char* unit = "", int digits = 3);
std::string percent(double value);  // "0.012 %"

}  // namespace shadowlab::hardcases
