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
};

struct PlotImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // width*height*4, row 0 = top
};

// Draws `plot` into a width x height image; the y range fits every series (with a margin), x every series' x.
PlotImage drawLinePlot(const LinePlot& plot, int width, int height);

// "Nice" tick values (1, 2 or 5 x 10^k apart) covering [low, high], about `count` of them.
std::vector<double> niceTicks(double low, double high, int count);

}  // namespace shadowlab
