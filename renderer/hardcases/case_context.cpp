#include "hardcases/hard_case.h"

#include "accuracy/gbuffer_pass.h"
#include "frame/render_target.h"
#include "image/image_io.h"
#include "scene/scene_source.h"
#include "settings/settings_fields.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace shadowlab::hardcases {

const char* verdictName(Verdict verdict) {
    switch (verdict) {
        case Verdict::Pass: return "pass";
        case Verdict::Fail: return "FAIL";
        case Verdict::NotRun: return "not run";
        case Verdict::Info: return "info";
    }
    return "?";
}

void CaseResult::check(std::string measured, std::string fig, std::string threshold, bool pass) {
    rows.push_back({std::move(measured), std::move(fig), std::move(threshold), pass ? Verdict::Pass : Verdict::Fail});
}

void CaseResult::notRun(std::string measured, std::string threshold, std::string why) {
    rows.push_back({std::move(measured), "not run (" + why + ")", std::move(threshold), Verdict::NotRun});
}

void CaseResult::info(std::string measured, std::string fig, std::string note) {
    rows.push_back({std::move(measured), std::move(fig), std::move(note), Verdict::Info});
}

bool CaseResult::failed() const {
    if (!error.empty()) return true;
    for (const CaseRow& row : rows)
        if (row.verdict == Verdict::Fail) return true;
    return false;
}

std::string figure(double value, const char* unit, int digits) {
    char text[64];
    if (!std::isfinite(value))
        std::snprintf(text, sizeof text, "%f", value);
    else
        std::snprintf(text, sizeof text, "%.*g", digits, value);
    std::string out = text;
    if (*unit) out += std::string(" ") + unit;
    return out;
}

std::string percent(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f %%", value);
    return text;
}

CaseContext::CaseContext(const HardCaseOptions& options, AccuracyMeter& meter, Renderer& renderer)
    : options_(options), meter_(meter), renderer_(renderer) {}

namespace {
constexpr const char* kReversedZKey = "lights.0.shadow.reversedZ";
}

std::string CaseContext::reversedZMissing() {
    if (findSettingsField(kReversedZKey)) return "";
    return "needs lights.N.shadow.reversedZ (issue 14, reversed-Z)";
}

std::string CaseContext::applyConvention(Settings& settings) const {
    if (!reversedZ) return "";
    if (std::string missing = reversedZMissing(); !missing.empty()) return missing;
    for (std::size_t i = 0; i < settings.lights.size(); ++i) {
        const std::string set = "lights." + std::to_string(i) + ".shadow.reversedZ=" + (*reversedZ ? "true" : "false");
        if (std::string error = applySettingOverride(settings, set); !error.empty()) return error;
    }
    return "";
}

AccuracyReport CaseContext::measure(const Scene& scene, Settings settings, int width, int height,
                                    const std::string& picture) {
    if (std::string error = applyConvention(settings); !error.empty()) {
        AccuracyReport failed;
        failed.error = error;
        return failed;
    }
    const Camera camera = cameraFor(settings.camera, scene, double(width) / double(height));
    AccuracyReport report = meter_.measure(scene, settings, camera, width, height);
    if (report.ok && !picture.empty()) writePicture(picture, report.width, report.height, report.overlayRgba);
    if (report.ok && recordMasks && result) {
        std::vector<std::uint8_t> mask(report.pixelShadow.size(), 2);
        for (std::size_t i = 0; i < mask.size(); ++i)
            if (report.pixelMeasured[i]) mask[i] = report.pixelShadow[i] >= 0.5f ? 1 : 0;
        masks[conventionName()][std::to_string(result->number) + "/" +
                                                     std::to_string(measureIndex_++)] = std::move(mask);
    }
    return report;
}

FlickerReport CaseContext::flicker(const Scene& scene, Settings settings, int width, int height, const Motion& motion,
                                   const std::string& picture) {
    FlickerReport report;
    if (std::string error = applyConvention(settings); !error.empty()) {
        report.error = error;
        return report;
    }
    const Camera camera = cameraFor(settings.camera, scene, double(width) / double(height));
    report = measureFlicker(meter_, scene, settings, camera, width, height, motion);
    if (report.ok && !picture.empty()) {
        writePicture(picture + "-a", report.width, report.height, report.worstPreviousRgba);
        writePicture(picture + "-b", report.width, report.height, report.worstCurrentRgba);
        writePicture(picture + "-overlay", report.width, report.height, report.overlayRgba);
    }
    return report;
}

RenderedView CaseContext::render(const Scene& scene, Settings settings, int width, int height,
                                 const std::string& picture, Renderer* renderer) {
    RenderedView view;
    if (std::string error = applyConvention(settings); !error.empty()) {
        view.stats.error = error;
        return view;
    }
    RenderTarget target;
    if (std::string error = target.resize(width, height); !error.empty()) {
        view.stats.error = error;
        return view;
    }
    Renderer& r = renderer ? *renderer : renderer_;
    view.stats = r.render(scene, settings, cameraFor(settings.camera, scene, double(width) / double(height)), target);
    view.width = width;
    view.height = height;
    const std::vector<std::uint8_t> bottomUp = target.readColor();
    view.rgba.resize(bottomUp.size());
    const std::size_t row = std::size_t(width) * 4;
    for (int y = 0; y < height; ++y)
        std::copy_n(bottomUp.begin() + std::ptrdiff_t(std::size_t(height - 1 - y) * row), row,
                    view.rgba.begin() + std::ptrdiff_t(std::size_t(y) * row));
    if (!picture.empty() && view.stats.ok) writePicture(picture, width, height, view.rgba);
    return view;
}

SurfaceSamples CaseContext::surfaces(const Scene& scene, const Settings& settings, int width, int height) {
    const RenderedView frame = render(scene, settings, width, height);
    SurfaceSamples samples;
    if (!frame.stats.ok || !renderer_.gpuScene()) return samples;
    const Camera camera = cameraFor(settings.camera, scene, double(width) / double(height));
    GBufferPass pass;
    const std::string error = pass.render(*renderer_.gpuScene(), frame.stats.cameraViewProjection, width, height,
                                          camera.position - frame.stats.renderOrigin, samples);
    if (!error.empty()) return {};
    for (glm::dvec3& p : samples.point) p += frame.stats.renderOrigin;  // back to world
    return samples;
}

std::optional<Scene> CaseContext::sharedScene(const std::string& relative, std::string& why) const {
    const std::string path = options_.sharedScenes + "/" + relative;
    if (!std::filesystem::exists(path)) {
        why = "needs " + path;
        return std::nullopt;
    }
    SceneLoadResult loaded = loadScene(path);
    if (!loaded.scene) why = loaded.error;
    return std::move(loaded.scene);
}

std::optional<Scene> CaseContext::assimpScene(const std::string& relative, std::string& why) const {
    const std::string path = options_.assimpModels + "/" + relative;
    if (!std::filesystem::exists(path)) {
        why = "needs " + path + " (assimp-testmodels)";
        return std::nullopt;
    }
    SceneLoadResult loaded = loadScene(path);
    if (!loaded.scene) why = loaded.error;
    return std::move(loaded.scene);
}

void CaseContext::writePicture(const std::string& name, int width, int height, const std::vector<std::uint8_t>& rgba) {
    if (options_.outDir.empty() || rgba.empty() || !picturesOn) return;
    char prefix[16];
    std::snprintf(prefix, sizeof prefix, "case%02d-", result ? result->number : 0);
    const std::string file = prefix + name + ".png";
    const std::string path = (std::filesystem::path(options_.outDir) / file).string();
    if (writePng(path, width, height, 4, rgba.data(), false).empty() && result) result->pictures.push_back(file);
}

}  // namespace shadowlab::hardcases
