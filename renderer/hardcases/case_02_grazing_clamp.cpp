// HARD_CASES 2: grazing light, N.L = cos 89.9 deg = 0.0017 on the receiver, map 2048 texels over 20 units and a depth
// range of 20. The depth slope per texel is then 0.28 of the range, so SlopeScaledDepthBias 2 moves a caster that is
// itself at grazing incidence about half the range away from the light: its shadow detaches (light leaks behind it).
// DepthBiasClamp caps the bias. Part A: the document's box on the floor (the floor in front of the box is the grazing
// caster there); part B: a card floating above the floor, itself at grazing incidence (78.7 deg, slope 100).
#include "hardcases/cases.h"

#include "accuracy/accuracy_metrics.h"
#include "hardcases/hard_case_scenes.h"

#include <glm/ext/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace shadowlab::hardcases {

namespace {

// How far light leaks past the contact line x = contactX into the shadow (toward -x), in world units: the 95th
// percentile over leaking pixels (truly shadowed, S visibly above 0) of the strip |z| < halfWidth, 0 when none.
// The metrics' "beyond k" cannot see this leak: in the map the whole 2.9-unit shadow is half a texel tall.
double leakWidth(const AccuracyReport& report, const SurfaceSamples& surfaces, double contactX, double halfWidth) {
    std::vector<double> widths;
    for (std::size_t i = 0; i < report.pixelClass.size() && i < surfaces.size(); ++i) {
        if (report.pixelClass[i] != PixelClass::Shadowed || !visiblyWrong(false, report.pixelShadow[i])) continue;
        const glm::dvec3& p = surfaces.point[i];
        if (!surfaces.isSurface(i) || std::abs(p.z) >= halfWidth || p.x > contactX) continue;
        widths.push_back(contactX - p.x);
    }
    return percentile(widths, 95);
}

}  // namespace

void runGrazingClamp(CaseContext& context, CaseResult& result) {
    if (!context.renderer().glInfo().polygonOffsetClamp) {
        result.notRun("leak with and without a clamp", "", "the GL has no glPolygonOffsetClamp");
        return;
    }
    const int width = context.pick(480, 240), height = context.pick(270, 135);
    // A: the document's configuration, a unit box on the floor, the light 89.9 deg from the floor's normal.
    Scene scene = meshKit("grazing-box");
    addFloor(scene, 20.0f);
    addBox(scene, {0.0f, 0.5f, 0.0f}, glm::vec3(1.0f));
    const double elevation = glm::radians(90.0 - 89.9);
    Settings s;
    LightSettings& light = s.lights[0];
    light.direction = glm::vec3(float(-std::cos(elevation)), float(-std::sin(elevation)), 0.0f);
    // 2048 texels over 20 units, a depth range of 20, also with --quick: which texel row the floor in front of the box
    // writes at the contact depends on the texel size, and at 1024 it happens to be the box's.
    light.shadow.resolution = 2048;
    light.projection.autoFit = false;
    light.projection.orthoSize = 20.0f;
    const float radius = scene.bounds.radius();
    light.projection.nearPlane = radius - 10.0f;
    light.projection.farPlane = radius + 10.0f;
    light.shadow.depthBias = 0.0f;
    light.shadow.slopeScaledDepthBias = 2.0f;
    light.shadow.normalOffset = 0.0f;
    s.filter.kind = FilterKind::Point;
    const double texel = 20.0 / light.shadow.resolution;
    const double clamp = 0.5 * texel / 20.0;  // half a texel's world size, in depth units of the 20-unit range
    light.shadow.depthBiasClamp = float(clamp);
    s.camera.autoFrame = false;  // the box and the floor behind it (the shadow runs toward -x)
    s.camera.position = {-1.5, 4.0, 4.0};
    s.camera.target = {-2.0, 0.0, 0.0};
    const AccuracyReport clamped = context.measure(scene, s, width, height, "box-clamped");
    const SurfaceSamples surfaces = context.surfaces(scene, s, width, height);
    light.shadow.depthBiasClamp = 0.0f;
    const AccuracyReport unclamped = context.measure(scene, s, width, height, "box-unclamped");
    if (!clamped.ok || !unclamped.ok) throw std::runtime_error(clamped.ok ? unclamped.error : clamped.error);
    const double withClamp = leakWidth(clamped, surfaces, -0.5, 0.4) / texel;
    const double without = leakWidth(unclamped, surfaces, -0.5, 0.4) / texel;
    result.check("89.9 deg, box: leak past the contact line, clamp (p95, floor texels)", figure(withClamp, "texels"),
                 "<= 1 texel", withClamp <= 1.0);
    // Without a clamp the floor in front of the box (a caster too, at grazing incidence) is stored 11 units farther
    // from the light: the floor behind the box compares against it and is lit.
    result.check("89.9 deg, box: the same without a clamp", figure(without, "texels"), "grows (> 1 texel)",
                 without > 1.0);
    result.info("89.9 deg, box: acne with the clamp", percent(clamped.acnePercent),
                "a floor texel spans 5.6 units of depth: no bias keeps the contact and ends acne there");

    // B: a caster itself at grazing incidence, a card 1 unit above the floor, the light 78.7 deg from vertical:
    // SlopeScaledDepthBias 100 puts its depth ~7 units back, behind the floor (5.1 away along the light).
    Scene cardScene = meshKit("grazing-card");
    addFloor(cardScene, 20.0f);
    cardScene.materials[0].doubleSided = true;  // the card is seen from below by the light
    cardScene.instances.push_back(
        {0, glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, 1.0f, 0.0f}), glm::vec3(0.1f, 1.0f, 0.1f))});
    cardScene.computeBounds();
    Settings c;
    c.lights[0].direction = glm::vec3(-1.0f, -0.2f, 0.0f);
    c.lights[0].shadow.resolution = context.pick(2048, 1024);
    c.lights[0].shadow.slopeScaledDepthBias = 100.0f;
    c.lights[0].shadow.depthBias = 0.0f;
    c.lights[0].shadow.normalOffset = 0.0f;  // at 78.7 deg a texel of offset moves the shadow 5 texels
    c.lights[0].shadow.depthBiasClamp = 0.001f;  // 0.028 world units over the fitted depth range: about a texel
    c.filter.kind = FilterKind::Point;
    c.camera.autoFrame = false;
    c.camera.position = {-3.0, 8.0, 6.0};
    c.camera.target = {-3.0, 0.0, 0.0};
    const AccuracyReport cardClamped = context.measure(cardScene, c, width, height, "card-clamped");
    c.lights[0].shadow.depthBiasClamp = 0.0f;
    const AccuracyReport cardUnclamped = context.measure(cardScene, c, width, height, "card-unclamped");
    if (!cardClamped.ok || !cardUnclamped.ok)
        throw std::runtime_error(cardClamped.ok ? cardUnclamped.error : cardClamped.error);
    result.check("78.7 deg card, slope 100: leak beyond k, clamp 0.001", percent(cardClamped.leakPercent), "<= 0.1 %",
                 cardClamped.leakPercent <= 0.1);
    result.check("78.7 deg card, slope 100: leak beyond k, no clamp", percent(cardUnclamped.leakPercent),
                 "grows (> 10 %)", cardUnclamped.leakPercent > 10.0);
    result.info("78.7 deg card: acne with the clamp", percent(cardClamped.acnePercent),
                "the clamp also caps the floor's own slope bias");
}

}  // namespace shadowlab::hardcases
