#pragma once
// A small UI-free chart: polylines and staircases over one x/y range, shaded x spans (markers), axes with tick
// labels and a legend, drawn into an RGBA8 buffer (row 0 = top) for writePng. Text is stb_easy_font's.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

using PlotColor = std::array<std::uint8_t, 4>;

struct PlotSeries {
    std::string label;
    PlotColor color{0, 0, 0, 255};
    bool staircase = false;  // each y holds over its x's cell (halfway to the neighbours), else straight segments
    std::vector<double> x, y;
};

// Points drawn as markers (a scatter), each with an optional label written beside it (where it covers no other).
struct PlotPoints {
    std::string label;
    PlotColor color{0, 0, 0, 255};
    int radius = 4;
    bool ring = false;  // a ring instead of a dot (drawn around another point, e.g. "the current preset")
    std::vector<double> x, y;
    std::vector<std::string> labels;  // empty, or one per point
};

// A vertical band over [x0, x1] (e.g. the samples with acne), listed in the legend once per label.
struct PlotSpan {
    std::string label;
    PlotColor color{255, 0, 0, 60};
    double x0 = 0.0, x1 = 0.0;
};

struct LinePlot {
    std::string title, xLabel, yLabel;
    std::vector<PlotSeries> series;
    std::vector<PlotSpan> spans;
    std::vector<PlotPoints> points;  // drawn over the series
};

struct PlotImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // width*height*4, row 0 = top
};

// Where the data lands in a width x height image: the plot area in pixels and the data range it shows. The editor
// uses it to find the point under the mouse on the same picture.
struct PlotFrame {
    bool drawable = false;  // false when the image is too small for a plot area
    int left = 0, right = 0, top = 0, bottom = 0;
    double xMin = 0.0, xMax = 1.0, yMin = 0.0, yMax = 1.0;
    double xSpacing = 1.0, ySpacing = 1.0;  // between ticks
    std::vector<double> xTicks, yTicks;
    double px(double x) const { return left + (x - xMin) / (xMax - xMin) * (right - left); }
    double py(double y) const { return bottom - (y - yMin) / (yMax - yMin) * (bottom - top); }
};
PlotFrame plotFrame(const LinePlot& plot, int width, int height);

// Draws `plot` into a width x height image; the y range fits every series (with a margin), x every series' x.
PlotImage drawLinePlot(const LinePlot& plot, int width, int height);

// "Nice" tick values (1, 2 or 5 x 10^k apart) covering [low, high], about `count` of them.
std::vector<double> niceTicks(double low, double high, int count);

}  // namespace shadowlab
