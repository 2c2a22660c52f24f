// The editor's side of accuracy measuring: starting jobs on the worker, taking their results (a bias search's
// result goes into the settings through the key table), knowing when the numbers are stale, measuring automatically
// (live counts on the GPU after every edit, a full measure once the view has been still), and uploading the overlay
// picture once per full report.
#include "editor/editor.h"
#include "accuracy/light_isolation.h"
#include "settings/settings_fields.h"
#include "shading/filters/filter_technique.h"
#include "gl/gl.h"

#include <algorithm>
#include <cstdio>

namespace shadowlab::editor {

std::optional<AccuracyViewKey> Editor::accuracyKey() const {
    if (!state_.scene || !orbit_) return std::nullopt;
    const int w = int(viewportRect_.z), h = int(viewportRect_.w);
    if (w < 16 || h < 16) return std::nullopt;
    return AccuracyViewKey{effectiveSettings(), orbit_->toCamera(), state_.scene.get(), w, h, state_.selectedLight};
}

void Editor::measureAccuracy() { startAccuracyJob(AccuracyJobKind::Measure); }
void Editor::suggestBias() { startAccuracyJob(AccuracyJobKind::SuggestBias); }
void Editor::measureFlicker() { startAccuracyJob(AccuracyJobKind::Flicker); }

void Editor::cancelAccuracy() {
    if (!accuracyWorker_->running()) return;
    accuracyWorker_->cancel();
    state_.accuracy.stage = "cancelling...";
}

void Editor::startAccuracyJob(AccuracyJobKind kind, bool automatic) {
    AccuracyState& a = state_.accuracy;
    const std::optional<AccuracyViewKey> key = accuracyKey();
    if (!key) {
        state_.say("accuracy: nothing to measure yet (no scene or no viewport)", true);
        return;
    }
    if (a.liveRunning) {
        queuedJob_ = kind;  // the worker is busy for a frame or so: start right after
        return;
    }
    keepSession();  // the worker compiles and allocates its own frame: keep the unsaved work first
    AccuracyJob job;
    job.kind = kind;
    job.scene = state_.scene;  // shared: a scene switch meanwhile cannot free what the worker reads
    job.settings = key->settings;
    job.light = key->light;
    job.camera = key->camera;
    job.width = key->width;
    job.height = key->height;
    job.maxAcnePercent = a.maxAcnePercent;
    job.search = a.search;
    job.motion = a.flickerMotion;
    if (accuracyWorker_->start(std::move(job)) == 0) {
        state_.say("accuracy: a job is still running (Cancel it first)", true);
        return;
    }
    accuracyJobKey_ = key;
    accuracyJobAutomatic_ = automatic;
    a.running = true;
    a.runningTune = kind == AccuracyJobKind::SuggestBias;
    a.runningFlicker = kind == AccuracyJobKind::Flicker;
    a.progress = 0.0f;
    a.stage = "starting";
    a.error.clear();
    if (a.runningTune) {
        a.steps.clear();
        a.tune.reset();
        // What this search varies, said while it runs (the tuner resolves auto the same way).
        const TuneScope scope{a.search, true};
        a.searched = resolveTuneSearch(scope, key->settings.filter.kind);
        a.searchedLight = key->light;
        a.searchedTechnique = filterTechnique(key->settings.filter.kind).name;
        a.searchedKeys.clear();
        if (a.searched != TuneSearch::Bias)
            for (std::string k : tradeOffKeysOf(scope, key->settings.filter.kind)) {
                if (const std::size_t at = k.find('#'); at != std::string::npos) k.replace(at, 1, std::to_string(key->light));
                a.searchedKeys.push_back(k);
            }
    }
}

void Editor::startLiveJob(const AccuracyViewKey& key) {
    AccuracyJob job;
    job.kind = AccuracyJobKind::Live;
    job.scene = state_.scene;
    job.settings = key.settings;
    job.light = key.light;
    job.camera = key.camera;
    job.width = key.width;
    job.height = key.height;
    if (accuracyWorker_->start(std::move(job)) == 0) return;
    liveJobKey_ = key;
    state_.accuracy.liveRunning = true;
}

void Editor::adoptLiveResult(AccuracyJobResult result) {
    AccuracyState& a = state_.accuracy;
    a.liveRunning = false;
    std::optional<AccuracyViewKey> key = std::move(liveJobKey_);
    liveJobKey_.reset();
    if (!result.report.ok) {
        // No reference for this light (or another refusal): wait for the full measure once the view is still.
        a.liveBlocked = true;
        if (!result.report.needsReference) state_.say("accuracy (live): " + result.report.error, true);
        return;
    }
    result.report.cost.totalMs = result.seconds * 1e3;  // as the panel's cost tab shows it: the job's wall time
    a.report = std::move(result.report);
    a.reportKey = std::move(key);
    a.reportSeconds = result.seconds;
    a.reportFromSearch = false;
    ++a.liveMeasurements;
}

void Editor::pollAccuracy() {
    AccuracyState& a = state_.accuracy;
    if (a.running) {
        a.progress = accuracyWorker_->progress();
        if (a.stage != "cancelling...") a.stage = accuracyWorker_->stage();
        if (a.runningTune) a.steps = accuracyWorker_->steps();
        if (std::optional<AccuracyJobResult> done = accuracyWorker_->poll()) adoptAccuracyResult(std::move(*done));
    } else if (a.liveRunning) {
        if (std::optional<AccuracyJobResult> done = accuracyWorker_->poll()) adoptLiveResult(std::move(*done));
        if (!a.liveRunning && queuedJob_) {
            const AccuracyJobKind kind = *queuedJob_;
            queuedJob_.reset();
            startAccuracyJob(kind);
        }
    }

    const std::optional<AccuracyViewKey> now = accuracyKey();
    if (!now) {
        autoDue_ = false;  // nothing to measure: no timer either
        return;
    }
    if (!lastSeenAccuracyKey_ || !(*lastSeenAccuracyKey_ == *now)) {
        lastSeenAccuracyKey_ = now;
        lastAccuracyChange_ = state_.time;
    }
    a.stale = a.reportKey ? staleReason(*a.reportKey, *now) : std::string();

    // Auto, live: after an edit, while the reference of the newest full measure serves this view, count on the GPU
    // (every frame the previous count has finished, so while a slider moves too).
    if (a.autoMeasure && !a.running && !a.liveRunning && !queuedJob_ && !a.liveBlocked && a.fullKey &&
        sameReferenceView(*a.fullKey, *now) && !(a.reportKey && *a.reportKey == *now))
        startLiveJob(*now);

    // Auto, full: once the view has been still for a moment, measure it (causes, overlay), unless this exact view
    // was already measured in full (or attempted) — never twice for the same view and settings.
    const bool measuredAlready = (a.fullKey && *a.fullKey == *now) || (autoMeasured_ && *autoMeasured_ == *now);
    autoDue_ = a.autoMeasure && !measuredAlready;
    // A slider held still is still being dragged: the full measure waits for the release.
    if (autoDue_ && !a.running && !a.liveRunning && !ImGui::IsAnyMouseDown() &&
        state_.time - lastAccuracyChange_ >= AccuracyState::kAutoDelaySeconds) {
        autoMeasured_ = now;
        startAccuracyJob(AccuracyJobKind::Measure, /*automatic=*/true);
    }
}

void Editor::adoptAccuracyResult(AccuracyJobResult result) {
    AccuracyState& a = state_.accuracy;
    a.running = false;
    a.progress = 1.0f;
    std::optional<AccuracyViewKey> key = std::move(accuracyJobKey_);
    accuracyJobKey_.reset();
    if (result.tune) a.steps = accuracyWorker_->steps();
    if (!result.report.ok) {
        a.error = result.report.error.empty() ? "failed" : result.report.error;
        a.stage = result.report.cancelled ? "cancelled" : "failed";
        state_.say("accuracy: " + a.error, !result.report.cancelled);
        return;
    }
    a.stage = "done";
    for (const std::string& w : result.report.warnings) state_.say("accuracy: " + w, true);
    if (result.flicker) {
        adoptFlickerResult(std::move(*result.flicker), result.seconds);
        return;
    }

    if (result.tune) {
        const TuneResult& tune = *result.tune;
        const ShadowMapSettings& best = tune.best.lights[0].shadow;
        // A result goes into the edited settings through the key table, like a slider would (the preset shows
        // its unsaved marker); the numbers then describe exactly these settings. No result within the acne limit:
        // nothing is applied, and the settings keep what the user had.
        const ShadowMapSettings& closest = tune.closest.lights[0].shadow;
        // The light the search tuned (tune.best holds it alone), even if another light is selected by now.
        const std::size_t light = key ? key->light : state_.selectedLight;
        const std::string prefix = "lights." + std::to_string(light) + ".shadow.";
        const bool biasSearched = std::any_of(tune.path.begin(), tune.path.end(),
                                              [](const TuneStep& s) { return !s.tradeOffStep; });
        // The technique's keys as the tuner chose them, as keys of the whole preset (tune_command's chosen values).
        std::vector<std::pair<std::string, nlohmann::json>> chosen;
        if (tune.tradeOffSearched)
            for (const std::string& k : tune.tradeOffKeys)
                chosen.emplace_back(keyOfLight(k, light), findSettingsField(k)->get(tune.closest));
        bool applied = false;
        if (tune.reachedLimit) {
            applied = true;
            if (biasSearched)
                applied = state_.edit(prefix + "depthBias", best.depthBias) &&
                          state_.edit(prefix + "slopeScaledDepthBias", best.slopeScaledDepthBias) &&
                          state_.edit(prefix + "normalOffset", best.normalOffset) &&
                          state_.edit(prefix + "cullMode", cullModeName(best.cullMode)) &&
                          state_.edit(prefix + "receiverPlaneBias", best.receiverPlaneBias);
            for (const auto& [k, value] : chosen) applied = applied && state_.edit(k, value);
        }
        // The report describes the best (reached) or the closest candidate (then stale against the settings kept).
        if (key) {
            setLightShadow(key->settings, light, tune.reachedLimit ? best : closest);
            for (const auto& [k, value] : chosen) findSettingsField(k)->set(key->settings, value);
        }
        std::string text;
        char number[320];
        if (tune.reachedLimit) {
            text = "suggested for light " + std::to_string(light) + ":";
            if (biasSearched) {
                std::snprintf(number, sizeof number,
                              " DepthBias %g, SlopeScaledDepthBias %g, normal offset %g texels, cull %s%s",
                              double(best.depthBias), double(best.slopeScaledDepthBias), double(best.normalOffset),
                              cullModeName(best.cullMode).c_str(), best.receiverPlaneBias ? ", receiver-plane bias" : "");
                text += number;
            }
            for (std::size_t i = 0; i < chosen.size(); ++i)
                text += std::string(i || biasSearched ? ", " : " ") + chosen[i].first + " " + chosen[i].second.dump();
            std::snprintf(number, sizeof number, " (acne %.3f %%, wrong pixels %.3f %%, %zu candidates, %.1f s)%s",
                          tune.report.acnePercent, tune.report.wrongPercent, tune.path.size(), tune.seconds,
                          applied ? ", applied" : ", NOT applied");
            text += number;
        } else {
            std::snprintf(number, sizeof number,
                          "NO setting reached the acne limit for light %zu (stopped by %s; least acne %.3f %% at DepthBias %g, slope "
                          "%g, normal offset %g",
                          light, causeInfo(tune.blockingCause).name, tune.report.acnePercent, double(closest.depthBias),
                          double(closest.slopeScaledDepthBias), double(closest.normalOffset));
            text = number;
            for (const auto& [k, value] : chosen) text += ", " + k + " " + value.dump();
            text += "); nothing applied";
        }
        state_.say(text, !tune.reachedLimit || !applied);
        a.tune = std::move(result.tune);
    }
    if (!result.tune) {
        char text[220];
        std::snprintf(text, sizeof text,
                      "accuracy of light %zu: acne %.3f %%, leak %.3f %%, wrong pixels %.3f %%, mean error %.4f (%dx%d, %.2f s)",
                      key ? key->light : state_.selectedLight, result.report.acnePercent, result.report.leakPercent, result.report.wrongPercent,
                      result.report.meanError, result.report.width, result.report.height, result.seconds);
        // Auto's measurement is news, not an answer: it does not hide the result of what the user just did.
        if (accuracyJobAutomatic_)
            state_.sayAutomatic(text);
        else
            state_.say(text);
    }
    a.report = std::move(result.report);
    a.reportKey = key;
    a.fullKey = std::move(key);
    a.liveBlocked = false;  // a new reference: live counts may follow edits again
    a.reportSeconds = result.seconds;
    a.reportFromSearch = result.kind == AccuracyJobKind::SuggestBias;
    ++a.measurements;
    uploadAccuracyOverlay();
}

void Editor::adoptFlickerResult(FlickerReport flicker, double seconds) {
    AccuracyState& a = state_.accuracy;
    for (const std::string& w : flicker.warnings) state_.say("flicker: " + w, true);
    char text[240];
    std::snprintf(text, sizeof text,
                  "flicker: max %.3f %% (mean %.3f %%) beside V changed max %.3f %%, %s step %g = %.3g texels, %d "
                  "frames (%.2f s)",
                  flicker.maxFlickerPercent, flicker.meanFlickerPercent, flicker.maxVChangedPercent,
                  motionName(flicker.motion.kind), flicker.motion.step, flicker.stepTexels, flicker.motion.frames,
                  seconds);
    state_.say(text);
    const std::size_t bytes = std::size_t(flicker.width) * std::size_t(flicker.height) * 4;
    if (flicker.width > 0 && flicker.height > 0 && flicker.overlayRgba.size() == bytes) {
        a.flickerTexture = gl::createTexture(GL_TEXTURE_2D);
        const GLuint id = a.flickerTexture.id();
        glTextureStorage2D(id, 1, GL_RGBA8, flicker.width, flicker.height);
        glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTextureSubImage2D(id, 0, 0, 0, flicker.width, flicker.height, GL_RGBA, GL_UNSIGNED_BYTE,
                            flicker.overlayRgba.data());
    }
    a.flicker = std::move(flicker);
    a.flickerSeconds = seconds;
}

void Editor::uploadAccuracyOverlay() {
    AccuracyState& a = state_.accuracy;
    const AccuracyReport& r = *a.report;
    if (r.width < 1 || r.height < 1 || r.overlayRgba.size() != std::size_t(r.width) * r.height * 4) return;
    if (!a.overlayTexture || a.overlayWidth != r.width || a.overlayHeight != r.height) {
        a.overlayTexture = gl::createTexture(GL_TEXTURE_2D);
        const GLuint id = a.overlayTexture.id();
        glTextureStorage2D(id, 1, GL_RGBA8, r.width, r.height);
        glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        a.overlayWidth = r.width;
        a.overlayHeight = r.height;
    }
    // Row 0 of the picture is the view's top; it lands in the texture's row 0, which the UI maps to v = 0 (top).
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    const std::vector<std::uint8_t>& rgba = a.overlayKind == OverlayKind::Cause  ? r.causeOverlayRgba
                                            : a.overlayKind == OverlayKind::Soft ? r.softOverlayRgba
                                                                                 : r.overlayRgba;
    if (rgba.size() != r.overlayRgba.size()) {
        a.overlayUploaded = false;  // the texture holds another picture: not shown as this one
        return;
    }
    glTextureSubImage2D(a.overlayTexture.id(), 0, 0, 0, r.width, r.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    a.uploadedKind = a.overlayKind;
    a.overlayUploaded = true;
}

std::optional<double> Editor::secondsUntilNextFrame() const {
    if (busy()) return 0.0;
    // A worker's progress is redrawn at a modest rate (drawing flat out on llvmpipe starves the worker; a sweep times
    // passes, and a faster UI would disturb its timings); its end wakes the host through options.wake at once.
    if (state_.accuracy.running || state_.accuracy.liveRunning) return 0.05;
    if (state_.sweep.running) return 0.25;
    if (loader_.busy()) return 0.1;
    // Auto's full measure falls due once the view has been still for kAutoDelaySeconds (a held mouse button waits
    // for its release, which is input).
    if (autoDue_ && !ImGui::IsAnyMouseDown())
        return std::max(0.0, lastAccuracyChange_ + AccuracyState::kAutoDelaySeconds - now());
    return std::nullopt;  // nothing running or due: only input or a worker's wake brings the next frame
}

}  // namespace shadowlab::editor
