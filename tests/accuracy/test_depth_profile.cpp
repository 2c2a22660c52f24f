// Issue 13, "Depth profile": along a line across the grazing floor, zero bias shows the staircase of texels dipping
// below the receiver (acne samples, each one really shadowed by the GPU); the shipped bias shows none. Across the
// box's shadow, the Peter Panning preset's bias hides the caster near its foot. The chart is a real, non-blank PNG.
#include "gl_fixture.h"
#include "image/image_io.h"
#include "probe/depth_profile_output.h"

#include <filesystem>
#include <set>

namespace shadowlab::test {
namespace {

class DepthProfileTest : public GlTest {};

constexpr int kWidth = 640, kHeight = 360;

DepthProfile profileOf(const std::string& sceneName, const Settings& settings, glm::ivec2 from, glm::ivec2 to) {
    const Scene scene = loadBuiltin(sceneName);
    Renderer renderer;
    PixelProbe probe;
    const Camera camera = cameraFor(settings.camera, scene, double(kWidth) / kHeight);
    EXPECT_EQ(probe.capture(renderer, scene, settings, camera, kWidth, kHeight), "");
    return depthProfile(probe, from, to);
}

// No bias at all: zeroBias, and no receiver plane (the default compares each tap with the receiver's plane).
Settings noBiasAtAll(Settings s) {
    s = zeroBias(s);
    s.lights[0].shadow.receiverPlaneBias = false;
    return s;
}

TEST_F(DepthProfileTest, ZeroBiasOnAGrazingFloorShowsAcneTheDefaultNone) {
    const glm::ivec2 from{200, 250}, to{260, 250};  // across the open floor, away from the box's shadow
    const DepthProfile acne = profileOf("grazing", noBiasAtAll(loadShippedPreset("default")), from, to);
    ASSERT_TRUE(acne.ok) << acne.error;
    EXPECT_EQ(acne.samples.size(), 61u);
    EXPECT_EQ(acne.surfaces, 61);
    EXPECT_GT(acne.acne, 30) << "zero bias: most receivers meet their own surface in the map";
    EXPECT_EQ(acne.peterPanning, 0);
    for (const ProfileSample& s : acne.samples) {
        EXPECT_DOUBLE_EQ(s.bias, 0.0);
        if (s.acne) EXPECT_LT(s.shadow, 1.0) << "an acne sample is darkened on screen, at " << s.x << "," << s.y;
    }
    const DepthProfile biased = profileOf("grazing", loadShippedPreset("default"), from, to);
    ASSERT_TRUE(biased.ok) << biased.error;
    EXPECT_EQ(biased.acne, 0);
    EXPECT_EQ(biased.peterPanning, 0);
    for (const ProfileSample& s : biased.samples) {
        EXPECT_GT(s.bias, 0.0);
        EXPECT_DOUBLE_EQ(s.shadow, 1.0) << "open floor, lit at " << s.x << "," << s.y;
        EXPECT_LE(s.receiver, s.stored) << "the comparison passes where no acne is reported";
    }

    // The chart: the requested size, and the three series' colours are on it (not a blank page).
    const std::string path = std::string(SHADOWLAB_TEST_OUTPUT) + "/depth-profile-acne.png";
    std::filesystem::create_directories(SHADOWLAB_TEST_OUTPUT);
    std::filesystem::remove(path);
    const LinePlot plot = depthProfilePlot(acne);
    const PlotImage image = drawLinePlot(plot, 800, 400);
    ASSERT_EQ(writePng(path, image.width, image.height, 4, image.rgba.data(), false), "");
    std::string error;
    const std::optional<PngImage> png = readPng(path, &error);
    ASSERT_TRUE(png) << error;
    EXPECT_EQ(png->width, 800);
    EXPECT_EQ(png->height, 400);
    std::set<std::array<int, 3>> colours;
    int ink = 0;
    for (std::size_t i = 0; i + 3 < png->pixels.size(); i += std::size_t(png->channels)) {
        const std::array<int, 3> c{png->pixels[i], png->pixels[i + 1], png->pixels[i + 2]};
        colours.insert(c);
        ink += c != std::array<int, 3>{255, 255, 255};
    }
    for (const PlotSeries& s : plot.series)
        if (s.label != "receiver depth")  // zero bias: receiver - bias is drawn over it
            EXPECT_TRUE(colours.count({s.color[0], s.color[1], s.color[2]})) << s.label << " not drawn";
    EXPECT_GT(ink, 800 * 400 / 10) << "the chart is nearly blank";
}

TEST_F(DepthProfileTest, PeterPanningWhereTheBiasHidesTheBox) {
    // Down the screen from the box onto the floor behind it: with the Peter Panning preset's bias the floor next to
    // the box is lit though the box is in front of it in the map; with the default none is.
    const glm::ivec2 from{320, 150}, to{320, 260};
    const DepthProfile panning = profileOf("grazing", loadShippedPreset("peter-panning"), from, to);
    ASSERT_TRUE(panning.ok) << panning.error;
    EXPECT_GT(panning.peterPanning, 5);
    for (const ProfileSample& s : panning.samples)
        if (s.peterPanning) {
            EXPECT_DOUBLE_EQ(s.shadow, 1.0);
            EXPECT_LT(s.stored - s.bias, s.receiver) << "a caster in front, hidden by less than the bias";
        }
    const DepthProfile tight = profileOf("grazing", loadShippedPreset("default"), from, to);
    ASSERT_TRUE(tight.ok) << tight.error;
    EXPECT_LT(tight.peterPanning, panning.peterPanning / 5);
}

TEST_F(DepthProfileTest, RefusesALineOutsideTheView) {
    const DepthProfile p = profileOf("grazing", loadShippedPreset("default"), {10, 10}, {640, 10});
    EXPECT_FALSE(p.ok);
    EXPECT_NE(p.error.find("to point 640,10 is outside the 640x360 view"), std::string::npos) << p.error;
}

}  // namespace
}  // namespace shadowlab::test
