// Changing the depth format in the editor keeps DepthBias's world size: the bias is re-expressed, the status line
// says so, and its Undo brings the old format and number back.
#include "editor_harness.h"

#include "light/depth_bias.h"

#include <gtest/gtest.h>

namespace shadowlab::editor::test {

TEST(EditorDepthFormat, D32fToD16ReexpressesDepthBiasAndUndoRestoresIt) {
    EditorHarness h(testOptions(testFolder("depth-format-change")));
    h.settle();
    ASSERT_EQ(h.state().settings.lights[0].shadow.format, DepthFormat::D32F);
    ASSERT_TRUE(h.state().stats.bias.valid);
    const Settings before = h.state().settings;
    const BiasReport biasBefore = h.state().stats.bias;

    h.click("shadow.depthFormat");
    h.click("shadow.depthFormat=d16");
    EXPECT_EQ(h.state().settings.lights[0].shadow.format, DepthFormat::D16);
    // Not 2 units of D16 (512x the world bias): the same depth offset at the receivers.
    const double r32 = depthStepAt(DepthFormat::D32F, biasBefore.receiverDepthMedian);
    EXPECT_NEAR(double(h.state().settings.lights[0].shadow.depthBias) / 65535.0, double(before.lights[0].shadow.depthBias) * r32, 1e-12);
    ASSERT_NE(h.state().lastMessage(), nullptr);
    EXPECT_NE(h.state().lastMessage()->text.find("(d32f) -> "), std::string::npos) << h.state().lastMessage()->text;
    EXPECT_NE(h.state().lastMessage()->text.find("(d16), same world bias"), std::string::npos);
    h.settle();
    // The frame's report agrees: D16's constant is the depth D32F's was at the median receiver, so its world size lies
    // within what D32F's was between the nearest and farthest receivers (D32F's r doubles at depth 0.5; D16's is flat).
    const BiasReport& after = h.state().stats.bias;
    EXPECT_NEAR(after.constantNear.depth, double(before.lights[0].shadow.depthBias) * r32, 1e-6 * after.constantNear.depth);
    EXPECT_GE(after.constantNear.world, biasBefore.constantNear.world * (1.0 - 1e-6));
    EXPECT_LE(after.constantNear.world, biasBefore.constantFar.world * (1.0 + 1e-6));
    EXPECT_LT(after.constantNear.world, 2.0 * biasBefore.constantFar.world) << "not 512 times the bias";
    h.saveWindow("depth-format-change");

    // An edit made after the change survives the undo.
    ASSERT_TRUE(h.state().edit("shadow.slopeScaledDepthBias", 3.5));
    h.frame();
    ASSERT_TRUE(h.reveal("status.undo"));
    h.click("status.undo");
    EXPECT_EQ(h.state().settings.lights[0].shadow.slopeScaledDepthBias, 3.5f);
    EXPECT_EQ(h.state().settings.lights[0].shadow.format, DepthFormat::D32F);
    EXPECT_EQ(h.state().settings.lights[0].shadow.depthBias, before.lights[0].shadow.depthBias);
    EXPECT_FALSE(h.state().undo.has_value());
    h.frame(2);
    EXPECT_FALSE(h.hasControl("status.undo")) << "the undo is gone once used";
}

}  // namespace shadowlab::editor::test
