// HARD_CASES 15: degenerate resolutions. 0 and sizes above GL_MAX_TEXTURE_SIZE must be refused with a message (no
// GL_INVALID_VALUE, no incomplete framebuffer, the previous map kept); a non-power-of-two map must work like its
// power-of-two neighbour.
#include "hardcases/cases.h"

#include "gl/gl_errors.h"
#include "scene/builtin_scenes.h"
#include "settings/settings_fields.h"

namespace shadowlab::hardcases {

void runDegenerateResolution(CaseContext& context, CaseResult& result) {
    Settings zero;
    const std::string zeroRefused = applySettingOverride(zero, "lights.0.shadow.resolution=0");
    result.check("resolution 0: refused", zeroRefused.empty() ? "accepted" : zeroRefused,
                 "a message naming lights.0.shadow.resolution",
                 zeroRefused.find("lights.0.shadow.resolution") != std::string::npos);

    const Scene scene = *makeBuiltinScene("textbook");
    const int maxSize = context.renderer().glInfo().maxTextureSize;
    Settings big;
    big.lights[0].shadow.resolution = 1024;
    const int width = context.pick(320, 160), height = context.pick(180, 90);
    const RenderedView before = context.render(scene, big, width, height);
    std::string bigRefused = applySettingOverride(big, "lights.0.shadow.resolution=" + std::to_string(maxSize + 1));
    gl::drainErrors();
    if (bigRefused.empty()) {  // the key table allows it (its limit is above this GPU's): the renderer must refuse
        const RenderedView after = context.render(scene, big, width, height);
        bigRefused = !after.stats.ok ? after.stats.error : after.stats.warnings.empty() ? "" : after.stats.warnings[0];
        const bool kept = after.stats.ok && after.stats.shadowMapResolution == before.stats.shadowMapResolution &&
                          after.rgba == before.rgba;
        result.check("GL_MAX_TEXTURE_SIZE + 1: the previous map kept", kept ? "kept (same picture)" : "not kept",
                     "kept", kept);
    }
    const std::string glError = gl::drainErrors();
    result.check("GL_MAX_TEXTURE_SIZE + 1 = " + std::to_string(maxSize + 1) + ": refused",
                 bigRefused.empty() ? "accepted" : bigRefused, "a message naming the limit",
                 bigRefused.find(std::to_string(maxSize)) != std::string::npos ||
                     bigRefused.find("GL_MAX_TEXTURE_SIZE") != std::string::npos);
    result.check("GL errors after the refusal", glError.empty() ? "none" : glError, "none", glError.empty());

    // A non-power-of-two map next to its power-of-two neighbour.
    Settings s;
    s.lights[0].shadow.normalOffset = 1.0f;
    s.lights[0].shadow.resolution = 1024;
    const AccuracyReport pot = context.measure(scene, s, width, height, "map1024");
    s.lights[0].shadow.resolution = 1000;
    const RenderedView npotFrame = context.render(scene, s, width, height);
    const AccuracyReport npot = context.measure(scene, s, width, height, "map1000");
    if (!pot.ok || !npot.ok) throw std::runtime_error(pot.ok ? npot.error : pot.error);
    result.check("1000^2 map: drawn at its size", std::to_string(npotFrame.stats.shadowMapResolution),
                 "1000", npotFrame.stats.ok && npotFrame.stats.shadowMapResolution == 1000);
    result.check("1000^2 map: wrong pixels (1024^2: " + percent(pot.wrongPercent) + ")", percent(npot.wrongPercent),
                 "<= 1024^2's x 1.1 + 0.02 %", npot.wrongPercent <= pot.wrongPercent * 1.1 + 0.02);
    result.check("1000^2 map: acne / leak", percent(npot.acnePercent) + " / " + percent(npot.leakPercent), "< 0.1 %",
                 npot.acnePercent < 0.1 && npot.leakPercent < 0.1);
    result.info("non-square maps", "not offered", "shadow.resolution is one number: every map is square");
}

}  // namespace shadowlab::hardcases
