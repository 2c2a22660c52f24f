// HARD_CASES 13: mirrored instances (a negative determinant, common in exported city and architecture scenes) wind
// their triangles the other way in world space, so a shadow pass that culls must flip its culling with the sign of
// the determinant. Two floating boxes, the one at +x mirrored: with back and front culling, acne and leak around
// the mirrored copy must equal those around the plain one.
#include "hardcases/cases.h"

#include "hardcases/hard_case_scenes.h"

#include <cmath>

namespace shadowlab::hardcases {

namespace {

struct HalfCounts {
    std::size_t lit = 0, shadowed = 0, acne = 0, leak = 0;
    double acnePercent() const { return lit ? 100.0 * double(acne) / double(lit) : 0.0; }
    double leakPercent() const { return shadowed ? 100.0 * double(leak) / double(shadowed) : 0.0; }
};

// Acne on each box's own pixels and leak (DESIGN's, beyond k) on the floor on its side of x = 0: [0] plain,
// [1] mirrored. (Instance 0 is the floor.)
std::array<HalfCounts, 2> bySide(const AccuracyReport& r, const SurfaceSamples& surfaces) {
    std::array<HalfCounts, 2> sides;
    for (std::size_t i = 0; i < r.pixelMark.size() && i < surfaces.size(); ++i) {
        if (!r.pixelMeasured[i] || !surfaces.isSurface(i)) continue;
        HalfCounts& h = sides[surfaces.point[i].x > 0.0 ? 1 : 0];
        const bool lit = r.pixelClass[i] == PixelClass::Lit;
        if (surfaces.instance[i] != 0) {
            h.lit += lit;
            h.acne += r.pixelMark[i] == PixelMark::Acne;
        } else {
            h.shadowed += !lit;
            h.leak += r.pixelMark[i] == PixelMark::Leak;
        }
    }
    return sides;
}

}  // namespace

void runMirroredInstances(CaseContext& context, CaseResult& result) {
    Scene scene = meshKit("mirrored-boxes");
    addFloor(scene, 20.0f);
    addBox(scene, {-4.0f, 1.5f, 0.0f}, {1.0f, 1.0f, 2.0f});
    addBox(scene, {4.0f, 1.5f, 0.0f}, {1.0f, 1.0f, 2.0f}, /*mirrorX=*/true);
    Settings s;
    s.lights[0].direction = {0.0f, -1.0f, -0.3f};  // the same light for both boxes (symmetric about x = 0)
    s.lights[0].shadow.resolution = context.pick(2048, 512);
    // No bias: the faces culling keeps decide whether a box shadows itself, so a wrong winding shows as acne.
    s.lights[0].shadow.depthBias = 0.0f;
    s.lights[0].shadow.slopeScaledDepthBias = 0.0f;
    s.lights[0].shadow.normalOffset = 0.0f;
    s.lights[0].shadow.receiverPlaneBias = false;  // with no bias at all the plane would leave every tap at a tie
    s.camera.autoFrame = false;
    s.camera.position = {0.0, 12.0, 12.0};
    s.camera.target = {0.0, 0.0, 0.0};
    const int width = context.pick(480, 240), height = context.pick(270, 135);
    const SurfaceSamples surfaces = context.surfaces(scene, s, width, height);
    for (CullMode cull : {CullMode::Back, CullMode::Front}) {
        const char* name = cull == CullMode::Back ? "back" : "front";
        s.lights[0].shadow.cullMode = cull;
        const AccuracyReport r = context.measure(scene, s, width, height, std::string("cull-") + name);
        if (!r.ok) throw std::runtime_error(r.error);
        const std::array<HalfCounts, 2> sides = bySide(r, surfaces);
        const double acneGap = std::abs(sides[1].acnePercent() - sides[0].acnePercent());
        const double leakGap = std::abs(sides[1].leakPercent() - sides[0].leakPercent());
        result.check(std::string("cull ") + name + ": acne on the box, mirrored vs plain",
                     percent(sides[1].acnePercent()) + " vs " + percent(sides[0].acnePercent()),
                     "equal (within 0.1 %)", acneGap <= 0.1);
        result.check(std::string("cull ") + name + ": leak on the floor, mirrored vs plain",
                     percent(sides[1].leakPercent()) + " vs " + percent(sides[0].leakPercent()),
                     "equal (within 0.1 %)", leakGap <= 0.1);
    }
}

}  // namespace shadowlab::hardcases
