// Issue 19: leaving auto-fit starts manual tuning from the volume auto-fit chose. "edit these values" used to copy a
// directional fit's near plane 0, which the key table refuses (near >= 1e-4), and unticking auto-fit jumped to the
// preset's old manual volume (an ortho size of 20 on a 0.9-unit helmet).
#include "editor_harness.h"

#include "settings/settings_fields.h"

namespace shadowlab::editor::test {

namespace {

// The selected light's first view as the last frame fitted it.
LightSpace fittedView(EditorHarness& h) {
    const std::vector<const ShadowViewStats*> views = h.state().selectedLightViews();
    EXPECT_FALSE(views.empty()) << "the selected light has no view";
    return views.empty() ? LightSpace{} : views.front()->space;
}

double leastNear() { return findSettingsField("lights.0.projection.near")->min; }

void expectManualFrom(EditorHarness& h, const LightSpace& fitted) {
    const LightSettings& light = *h.state().selected();
    const Message* said = h.state().lastMessage();
    EXPECT_FALSE(light.projection.autoFit) << (said ? said->text : "no message");
    if (!fitted.perspective) EXPECT_FLOAT_EQ(light.projection.orthoSize, float(fitted.orthoSize));
    EXPECT_FLOAT_EQ(light.projection.nearPlane, float(std::max(fitted.nearPlane, leastNear())));
    EXPECT_FLOAT_EQ(light.projection.farPlane, float(fitted.farPlane));
    EXPECT_TRUE(h.state().fieldErrors.empty());
    EXPECT_TRUE(h.state().settings.validate().empty());
    // The next frame's volume is the fitted one: nothing jumped.
    h.frame(2);
    const LightSpace now = fittedView(h);
    if (!fitted.perspective) EXPECT_NEAR(now.orthoSize, fitted.orthoSize, 1e-4 * fitted.orthoSize);
    EXPECT_NEAR(now.farPlane, fitted.farPlane, 1e-4 * fitted.farPlane);
}

}  // namespace

TEST(EditorProjectionIssue19, EditTheseValuesStartsFromAFittedDirectionalVolumeWhoseNearIsZero) {
    EditorHarness h(testOptions(testFolder("projection-edit-fitted")));
    h.settle();
    ASSERT_TRUE(h.state().selected()->projection.autoFit);
    const LightSpace fitted = fittedView(h);
    ASSERT_FALSE(fitted.perspective);
    ASSERT_EQ(fitted.nearPlane, 0.0) << "a directional fit starts at the bounding sphere: below the key's least near";
    h.click("projection.useFitted");
    h.frame();
    expectManualFrom(h, fitted);
}

TEST(EditorProjectionIssue19, UntickingAutoFitKeepsTheFittedVolumeOfEveryLightType) {
    EditorHarness h(testOptions(testFolder("projection-untick")));
    h.settle();
    h.click("lights.add.spot");
    h.click("lights.add.point");
    h.settle();
    ASSERT_EQ(h.state().settings.lights.size(), 3u);
    for (std::size_t light = 0; light < 3; ++light) {
        SCOPED_TRACE("light " + std::to_string(light));
        h.click("lights.select." + std::to_string(light));
        h.frame(2);
        ASSERT_TRUE(h.state().selected()->projection.autoFit);
        const LightSpace fitted = fittedView(h);
        const ProjectionSettings manualBefore = h.state().selected()->projection;
        // The preset's manual values are far from the fit: unticking used to jump to them.
        EXPECT_GT(std::abs(manualBefore.farPlane - fitted.farPlane), 0.1 * fitted.farPlane);
        h.click("projection.autoFit");
        h.frame();
        expectManualFrom(h, fitted);
    }
}

}  // namespace shadowlab::editor::test
