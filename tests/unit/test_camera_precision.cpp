// Observation 6 of issue 9: the camera is double precision end to end in settings, `--set` and presets, so a
// scene 1e6 from the origin can be looked at from positions a millimetre apart.
#include "settings/preset_io.h"
#include "settings/settings_fields.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace shadowlab {
namespace {

TEST(CameraPrecision, SetKeepsAMillimetreAtAMillionUnits) {
    Settings s;
    ASSERT_EQ(applySettingOverride(s, "camera.position=[1000000.001, -2000000.0005, 0.1]"), "");
    ASSERT_EQ(applySettingOverride(s, "camera.target=[1000000, -2000000, 0]"), "");
    EXPECT_EQ(s.camera.position.x, 1000000.001);  // a float would hold 1000000.0
    EXPECT_EQ(s.camera.position.y, -2000000.0005);
    EXPECT_EQ(s.camera.position.z, 0.1);
    EXPECT_NE(s.camera.position.x, s.camera.target.x);
}

TEST(CameraPrecision, PresetsRoundTripTheCameraExactly) {
    Settings s;
    s.camera.autoFrame = false;
    s.camera.position = {1000000.001, 123456789.0 / 1024.0, -0.1};
    s.camera.target = {1000000.0, 0.30000000000000004, 1e-300};
    const std::string text = presetToText(s, "far away");
    EXPECT_NE(text.find("1000000.001"), std::string::npos) << text;  // shortest exact decimal, readable
    const PresetLoadResult back = presetFromJson(nlohmann::json::parse(text));
    ASSERT_TRUE(back.settings);
    EXPECT_EQ(back.settings->camera.position, s.camera.position);
    EXPECT_EQ(back.settings->camera.target, s.camera.target);
    EXPECT_TRUE(*back.settings == s);
}

}  // namespace
}  // namespace shadowlab
