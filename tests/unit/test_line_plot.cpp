// The depth profile's chart (renderer/image/line_plot.h): readable tick values, series drawn in their colours where
// their data is, a staircase holding each value over its cell, and an empty chart still a valid image.
#include "image/line_plot.h"

#include <gtest/gtest.h>

namespace shadowlab {
namespace {

bool hasColour(const PlotImage& image, const PlotColor& c, int x0, int x1) {
    for (int y = 0; y < image.height; ++y)
        for (int x = x0; x < x1; ++x) {
            const std::uint8_t* p = &image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
            if (p[0] == c[0] && p[1] == c[1] && p[2] == c[2]) return true;
        }
    return false;
}

TEST(LinePlot, TicksAreOneTwoOrFiveTimesAPowerOfTen) {
    const std::vector<double> unit = niceTicks(0.0, 1.0, 5);
    ASSERT_EQ(unit.size(), 6u);
    for (std::size_t i = 0; i < unit.size(); ++i) EXPECT_NEAR(unit[i], 0.2 * double(i), 1e-12);
    // A depth range of 3.2e-3 in about 6 ticks: the smallest nice step not below 5.3e-4 is 1e-3.
    const std::vector<double> depth = niceTicks(0.6181, 0.6213, 6);
    ASSERT_EQ(depth.size(), 3u);
    EXPECT_NEAR(depth[0], 0.619, 1e-12);
    EXPECT_NEAR(depth[2], 0.621, 1e-12);
}

TEST(LinePlot, DrawsEachSeriesInItsColourOverItsRange) {
    LinePlot plot;
    plot.title = "t";
    PlotSeries left{"left", {200, 10, 10, 255}, false, {0, 1, 2, 3, 4}, {1, 2, 3, 2, 1}};
    PlotSeries steps{"steps", {10, 10, 200, 255}, true, {0, 1, 2, 3, 4}, {0, 0, 4, 4, 0}};
    plot.series = {left, steps};
    plot.spans = {{"band", {0, 200, 0, 255}, 1.5, 2.5}};
    const PlotImage image = drawLinePlot(plot, 400, 200);
    ASSERT_EQ(image.width, 400);
    ASSERT_EQ(image.height, 200);
    ASSERT_EQ(image.rgba.size(), 400u * 200u * 4u);
    EXPECT_TRUE(hasColour(image, left.color, 0, 400));
    EXPECT_TRUE(hasColour(image, steps.color, 0, 400));
    EXPECT_TRUE(hasColour(image, {0, 200, 0, 255}, 0, 400)) << "the band";
    // The band covers the middle of the x range only: none of its colour in the left fifth of the plot area.
    EXPECT_FALSE(hasColour(image, {0, 200, 0, 255}, 0, 120));
    // An empty chart is still a drawn image of the requested size (axes, white page).
    const PlotImage empty = drawLinePlot(LinePlot{}, 300, 150);
    EXPECT_EQ(empty.rgba.size(), 300u * 150u * 4u);
}

}  // namespace
}  // namespace shadowlab
