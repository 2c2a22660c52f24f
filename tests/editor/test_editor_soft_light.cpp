// A soft light in the editor, driven through ImGui's IO: the Light panel's size field and the Accuracy panel's soft
// rays field set their keys, and Measure shows the light's soft numbers (version 3) under the light they describe.
#include "editor_harness.h"

namespace shadowlab::editor::test {

TEST(EditorSoftLight, TheLightsSizeAndTheRayCountGiveSoftNumbers) {
    EditorHarness h(testOptions(testFolder("EditorSoftLight")), 1280, 720);
    h.settle();
    const Settings& s = h.state().settings;
    ASSERT_EQ(s.lights[0].size, 0.0f) << "a hard light by default";

    ASSERT_TRUE(h.reveal("light.size"));
    h.ctrlClick("light.size");  // Ctrl+click turns the drag field into a text field
    h.selectAllAndType("3");
    h.settle();
    EXPECT_EQ(s.lights[0].size, 3.0f);

    ASSERT_TRUE(h.reveal("reference.softRays"));
    h.click("reference.softRays");
    h.selectAllAndType("64");
    h.settle();
    EXPECT_EQ(s.reference.softRays, 64);

    h.click("accuracy.measure");
    const AccuracyState& a = h.state().accuracy;
    h.waitForAccuracyJob();
    ASSERT_TRUE(a.report.has_value()) << a.error;
    ASSERT_TRUE(a.report->ok) << a.report->error;
    ASSERT_TRUE(a.reportKey.has_value());
    EXPECT_EQ(a.reportKey->settings.reference.softRays, 64) << "now " << s.reference.softRays;
    const SoftAccuracy& soft = a.report->soft;
    ASSERT_TRUE(soft.measured);
    EXPECT_EQ(soft.light, 0u);
    EXPECT_EQ(soft.size, 3.0);
    EXPECT_EQ(soft.rays, 64);
    EXPECT_GT(soft.counts.penumbra, 0u);
    EXPECT_TRUE(h.reveal("accuracy.soft.light"));
    EXPECT_TRUE(h.reveal("accuracy.soft.bleeding"));
    EXPECT_TRUE(h.reveal("accuracy.soft.penumbra"));
    h.saveWindow("accuracy-soft");
}

}  // namespace shadowlab::editor::test
