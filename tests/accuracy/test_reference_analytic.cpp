// The reference proven against closed-form answers before it is trusted: the sphere's elliptic shadow, the
// alpha-tested fence, the spot light's cone.
#include "gl_fixture.h"
#include "reference_fixture.h"
#include "scene/builtin_scenes.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <functional>

namespace shadowlab::test {
namespace {

class ReferenceAnalytic : public GlTest {};

// Floor pixels (y = 0, normal up) whose reference verdict disagrees with `inShadow`; each disagreement must lie within
// one pixel of the closed-form boundary (a neighbour within one pixel is classified the other way).
struct FloorCheck {
    long floorPixels = 0;
    long shadowedByFormula = 0;
    long disagreements = 0;
    long disagreementsFarFromEdge = 0;
};

FloorCheck checkFloor(const ReferenceView& view, const std::function<bool(const glm::dvec3&)>& inShadow) {
    FloorCheck check;
    const int w = view.samples.width, h = view.samples.height;
    auto isFloor = [&](std::size_t i) {
        return view.samples.isSurface(i) && view.samples.finite[i] && std::abs(view.world(i).y) < 1e-4 &&
               view.samples.normal[i].y > 0.999;
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            if (!isFloor(i)) continue;
            ++check.floorPixels;
            const bool formula = inShadow(view.world(i));
            check.shadowedByFormula += formula;
            const PixelClass c = view.visibility.classes[i];
            if ((c == PixelClass::Shadowed) == formula && (c == PixelClass::Lit) == !formula) continue;
            ++check.disagreements;
            bool nearEdge = false;
            for (int dy = -1; dy <= 1 && !nearEdge; ++dy)
                for (int dx = -1; dx <= 1 && !nearEdge; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    const std::size_t j = std::size_t(ny) * std::size_t(w) + std::size_t(nx);
                    // The neighbour's world point, or this pixel's ray moved by a pixel on the floor plane.
                    if (isFloor(j) && inShadow(view.world(j)) != formula) nearEdge = true;
                }
            check.disagreementsFarFromEdge += !nearEdge;
        }
    return check;
}

TEST_F(ReferenceAnalytic, SphereShadowIsTheClosedFormEllipseWithinOnePixel) {
    const Scene scene = loadBuiltin("sphere-plane");
    Settings settings = topDownAt(Settings{}, 1.2f, 0.8f, 9.0f);
    const glm::dvec3 lightDirection = glm::normalize(glm::dvec3(0.6, -1.0, 0.4));
    settings.lights[0].direction = glm::vec3(lightDirection);
    const ReferenceView view = traceReference(scene, settings, 640, 360);

    // A floor point is shadowed when its ray toward the light passes within r of the sphere's centre: the cylinder
    // around the light's direction cuts the floor in an ellipse.
    const glm::dvec3 center(builtin::kSpherePlaneCenter);
    const double r = builtin::kSpherePlaneRadius;
    const glm::dvec3 toLight = -lightDirection;
    auto inShadow = [&](const glm::dvec3& p) {
        const double along = glm::dot(center - p, toLight);
        const double miss2 = glm::dot(center - p, center - p) - along * along;
        return along > 0.0 && miss2 < r * r;
    };
    const FloorCheck check = checkFloor(view, inShadow);
    EXPECT_GT(check.floorPixels, 100000);
    EXPECT_GT(check.shadowedByFormula, 5000) << "the ellipse must be visible and large in this view";
    EXPECT_EQ(check.disagreementsFarFromEdge, 0) << check.disagreements << " disagreements in total";
    EXPECT_LT(check.disagreements, 200);
    std::printf("ellipse: %ld floor pixels, %ld inside the closed-form ellipse, %ld disagree (all within 1 px)\n",
                check.floorPixels, check.shadowedByFormula, check.disagreements);
}

TEST_F(ReferenceAnalytic, FenceMaskIsAlphaTestedAtTheHit) {
    const Scene scene = loadBuiltin("fence");
    Settings settings = topDownAt(Settings{}, 0.0f, -1.8f, 9.0f);
    const glm::vec3 lightDirection(-0.3f, -1.0f, -1.0f);
    settings.lights[0].direction = lightDirection;
    const ReferenceView view = traceReference(scene, settings, 640, 360);

    auto inShadow = [&](const glm::dvec3& p) { return builtin::fenceShadowsPoint(glm::vec3(p), lightDirection); };
    const FloorCheck check = checkFloor(view, inShadow);
    EXPECT_EQ(check.disagreementsFarFromEdge, 0) << check.disagreements << " disagreements in total";
    EXPECT_GT(check.shadowedByFormula, 2000);

    // Behind the gaps the light gets through: an opaque-quad reference would shadow all of these.
    long litBehindGaps = 0;
    for (std::size_t i = 0; i < view.samples.size(); ++i) {
        if (view.visibility.classes[i] != PixelClass::Lit) continue;
        const glm::dvec3 p = view.world(i);
        if (std::abs(p.y) > 1e-4) continue;
        const double t = -p.z / double(-lightDirection.z);
        const glm::dvec3 hit = p + t * glm::dvec3(-lightDirection);
        litBehindGaps += t > 0.0 && hit.x > builtin::kFenceXMin && hit.x < builtin::kFenceXMax && hit.y > 0.0 &&
                         hit.y < builtin::kFenceHeight;
    }
    EXPECT_GT(litBehindGaps, 1000);
    std::printf("fence: %ld floor pixels, %ld shadowed by formula, %ld disagree (all within 1 px), %ld lit behind "
                "gaps\n", check.floorPixels, check.shadowedByFormula, check.disagreements, litBehindGaps);
}

TEST_F(ReferenceAnalytic, SpotLightOutsideItsConeIsUnlit) {
    const Scene scene = loadBuiltin("textbook");
    Settings settings = topDownAt(Settings{}, 0.0f, 0.0f, 14.0f);
    settings.lights[0].type = LightType::Spot;
    settings.lights[0].position = glm::vec3(0.5f, 8.0f, 0.5f);
    settings.lights[0].direction = glm::vec3(0.0f, -1.0f, 0.0f);
    settings.lights[0].spotConeDeg = 40.0f;
    const ReferenceView view = traceReference(scene, settings, 320, 240);
    const double halfCone = glm::radians(20.0);
    long inside = 0, outside = 0, shadowed = 0;
    for (std::size_t i = 0; i < view.samples.size(); ++i) {
        const PixelClass c = view.visibility.classes[i];
        if (c == PixelClass::Background || c == PixelClass::FacingAway) continue;
        const glm::dvec3 fromLight = glm::normalize(view.world(i) - glm::dvec3(settings.lights[0].position));
        const double angle = std::acos(std::clamp(fromLight.y * -1.0, -1.0, 1.0));
        if (c == PixelClass::OutsideCone) {
            ++outside;
            EXPECT_GT(angle, halfCone - 1e-6);
        } else {
            ++inside;
            EXPECT_LT(angle, halfCone + 1e-6);
            shadowed += c == PixelClass::Shadowed;
        }
    }
    EXPECT_GT(inside, 5000);
    EXPECT_GT(outside, 5000);
    EXPECT_GT(shadowed, 300) << "the cube shadows the floor under the spot light";
}

TEST_F(ReferenceAnalytic, ReceiversFacingAwayAreNotScoredButUnlit) {
    const Scene scene = loadBuiltin("sphere-plane");
    Settings settings = Settings{};
    settings.camera.autoFrame = false;
    settings.camera.position = glm::vec3(6.0f, 1.0f, 0.0f);  // low, beside the sphere: sees its underside
    settings.camera.target = glm::vec3(0.0f, 2.0f, 0.0f);
    settings.lights[0].direction = glm::vec3(0.0f, -1.0f, 0.0f);
    const ReferenceView view = traceReference(scene, settings, 320, 240);
    long facingAway = 0;
    for (std::size_t i = 0; i < view.samples.size(); ++i) {
        if (view.visibility.classes[i] != PixelClass::FacingAway) continue;
        ++facingAway;
        EXPECT_LE(view.samples.normal[i].y, 1e-9) << "only surfaces turned from the light (below the equator)";
    }
    EXPECT_GT(facingAway, 500);
}

}  // namespace
}  // namespace shadowlab::test
