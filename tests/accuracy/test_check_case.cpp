// `shadowlab check`'s cases without GL (renderer/accuracy/check_case.h, check_limits.h): what a case file becomes,
// and each light's figures against the limits.
#include "accuracy/check_case.h"
#include "accuracy/check_limits.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace shadowlab;

namespace {

std::vector<CheckCase> parse(const std::string& text, std::string& error) {
    error.clear();
    return parseCheckCases(text, "c.json", error).value_or(std::vector<CheckCase>{});
}

}  // namespace

TEST(CheckCase, ACaseFileBecomesCasesWithTheirOverridesLimitsAndDefaults) {
    std::string error;
    const std::vector<CheckCase> cases = parse(R"({"cases": [
        {"scene": "builtin:textbook", "preset": "default", "maxAcnePercent": 0.1},
        {"name": "spot", "scene": "builtin:courtyard", "width": 320, "height": 180,
         "set": {"filter.kind": "poisson", "lights.1.position": [2, 3, 1], "shadow.depthBias": 0},
         "maxEdgePixels": 4, "maxFlickerPercent": 0.5, "motion": "camera", "frames": 4}]})",
                                               error);
    ASSERT_EQ(error, "");
    ASSERT_EQ(cases.size(), 2u);
    EXPECT_EQ(cases[0].name, "builtin:textbook default");
    EXPECT_EQ(cases[0].width, kCheckDefaultWidth);
    EXPECT_EQ(cases[0].limits.maxAcnePercent, 0.1);
    EXPECT_FALSE(cases[0].limits.maxLeakPercent.has_value());
    // Object values go to the override as JSON text, so a string stays a string and an array a vector.
    EXPECT_EQ(cases[1].overrides,
              (std::vector<std::string>{"filter.kind=\"poisson\"", "lights.1.position=[2,3,1]", "shadow.depthBias=0"}));
    EXPECT_EQ(cases[1].motion, MotionKind::Camera);
    EXPECT_EQ(cases[1].frames, 4);
    EXPECT_FALSE(cases[1].step.has_value());
}

TEST(CheckCase, EveryProblemNamesTheFileTheCaseAndTheKey) {
    std::string error;
    parse(R"({"cases": [{"name": "a", "scene": "s", "maxAcnePercent": 1},
                        {"name": "b", "scene": "s", "maxAcnePercent": 1, "height": 0}]})", error);
    EXPECT_EQ(error, "c.json: case 2 (\"b\"): height: 0 is outside [1, 16384]");
    parse(R"({"cases": [{"scene": "s", "maxFlickerPercent": 101}]})", error);
    EXPECT_EQ(error, "c.json: case 1: maxFlickerPercent: 101 is more than 100 (a limit in percent is in [0, 100])");
    parse(R"({"cases": [{"scene": "s", "maxAcnePercent": 1, "motion": "light"}]})", error);
    EXPECT_NE(error.find("c.json: case 1: motion: describes how flicker is measured"), std::string::npos) << error;
    parse(R"({"cases": [{"scene": "s", "maxFlickerPercent": 1, "motion": "wobble"}]})", error);
    EXPECT_NE(error.find("c.json: case 1: motion: 'wobble' is not a motion"), std::string::npos) << error;
    parse(R"({"cases": [{"scene": "s", "maxAcnePercent": 1, "set": [1]}]})", error);
    EXPECT_EQ(error, "c.json: case 1: set[0]: expected \"key=value\", got a number");
    parse(R"({"cases": []})", error);
    EXPECT_EQ(error, "c.json: cases: the list is empty, so nothing would be checked");
    parse(R"({"case": []})", error);
    EXPECT_NE(error.find("c.json: unknown key 'case' at the top"), std::string::npos) << error;
}

TEST(CheckLimits, EachLightsFiguresAreJudgedAndTheWholePictureOnlyOnItsOwnFigures) {
    CheckLimits limits;
    limits.maxAcnePercent = 0.1;
    limits.maxEdgePixels = 2.0;
    AccuracyNumbers light;
    light.acnePercent = 0.25;
    light.edgeErrorP95ScreenPixels = 1.5;
    const std::vector<CheckFigure> figures = accuracyFigures(limits, "lights.1 (spot)", light);
    ASSERT_EQ(figures.size(), 2u);
    EXPECT_TRUE(figures[0].broken());
    EXPECT_FALSE(figures[1].broken());
    EXPECT_EQ(describeFigure(figures[0]), "acne 0.250 % (limit 0.100 %: BROKEN)");
    EXPECT_EQ(describeFigure(figures[1]), "edge error 1.50 px (limit 2.00 px)");
    // The whole picture's edge error is the largest light's: judged per light, not again.
    const std::vector<CheckFigure> whole = wholePictureFigures(limits, light);
    ASSERT_EQ(whole.size(), 1u);
    EXPECT_EQ(whole[0].subject, "whole picture");
    EXPECT_STREQ(whole[0].limit->key, "maxAcnePercent");
}

TEST(CheckLimits, AFigureThatCannotBeJudgedOrOnlyJustBrokenIsShownAsBroken) {
    CheckLimits limits;
    limits.maxLeakPercent = 0.1;
    AccuracyNumbers n;
    n.leakPercent = std::nan("");
    EXPECT_TRUE(accuracyFigures(limits, "lights.0 (directional)", n).front().broken());
    // 0.1004 prints as 0.100 to three places: a broken figure gets the digits that show why.
    n.leakPercent = 0.1004;
    EXPECT_EQ(describeFigure(accuracyFigures(limits, "lights.0 (directional)", n).front()),
              "leak 0.1004 % (limit 0.100 %: BROKEN)");
}
