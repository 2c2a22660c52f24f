#include "image/line_plot.h"

// stb is third-party: its warnings are silenced for this include only.
#pragma GCC diagnostic push
#ifdef __clang__
#pragma clang diagnostic ignored "-Wunknown-warning-option"
#endif
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wuseless-cast"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace shadowlab {

namespace {

class Canvas {
public:
    Canvas(int w, int h) : w_(w), h_(h), rgba_(std::size_t(w) * std::size_t(h) * 4, 255) {}

    void blend(int x, int y, const PlotColor& c) {
        if (x < 0 || y < 0 || x >= w_ || y >= h_) return;
        std::uint8_t* p = &rgba_[(std::size_t(y) * std::size_t(w_) + std::size_t(x)) * 4];
        const int a = c[3];
        for (int k = 0; k < 3; ++k) p[k] = std::uint8_t((c[std::size_t(k)] * a + p[k] * (255 - a)) / 255);
        p[3] = 255;
    }
    void fill(int x0, int y0, int x1, int y1, const PlotColor& c) {
        for (int y = std::max(y0, 0); y < std::min(y1, h_); ++y)
            for (int x = std::max(x0, 0); x < std::min(x1, w_); ++x) blend(x, y, c);
    }
    // A 2-pixel wide line (Bresenham with a thickening pixel below), thick enough to read in a PNG.
    void line(double ax, double ay, double bx, double by, const PlotColor& c, int thickness = 2) {
        const int steps = int(std::ceil(std::max(std::abs(bx - ax), std::abs(by - ay)))) + 1;
        for (int i = 0; i <= steps; ++i) {
            const double t = double(i) / steps;
            const int x = int(std::lround(ax + (bx - ax) * t)), y = int(std::lround(ay + (by - ay) * t));
            for (int d = 0; d < thickness; ++d) setPixel(x, y + d, c);
        }
    }
    void text(int x, int y, const std::string& s, const PlotColor& c) {
        // stb_easy_font emits quads (4 vertices of 16 bytes: x, y, z floats and a colour) at scale 1 (7 px tall).
        static char buffer[99999];
        const int quads = stb_easy_font_print(float(x), float(y), const_cast<char*>(s.c_str()), nullptr, buffer,
                                              int(sizeof(buffer)));
        for (int q = 0; q < quads; ++q) {
            const float* v = reinterpret_cast<const float*>(buffer + q * 64);
            fill(int(v[0]), int(v[1]), int(v[8]), int(v[9]), c);
        }
    }
    // A filled disc (or a 2-pixel ring) of radius r centred on (cx, cy).
    void disc(double cx, double cy, double r, bool ring, const PlotColor& c) {
        for (int y = int(std::floor(cy - r - 1)); y <= int(std::ceil(cy + r + 1)); ++y)
            for (int x = int(std::floor(cx - r - 1)); x <= int(std::ceil(cx + r + 1)); ++x) {
                const double d = std::hypot(double(x) - cx, double(y) - cy);
                if (d <= r && (!ring || d >= r - 2.0)) blend(x, y, c);
            }
    }
    static int textWidth(const std::string& s) { return stb_easy_font_width(const_cast<char*>(s.c_str())); }
    std::vector<std::uint8_t> take() { return std::move(rgba_); }

private:
    void setPixel(int x, int y, const PlotColor& c) { blend(x, y, c); }
    int w_, h_;
    std::vector<std::uint8_t> rgba_;
};

std::string tickText(double v, double spacing) {
    const int decimals = std::clamp(int(std::ceil(-std::log10(spacing))), 0, 9);
    char text[64];
    std::snprintf(text, sizeof(text), "%.*f", decimals, v);
    return text;
}

}  // namespace

std::vector<double> niceTicks(double low, double high, int count) {
    if (!(high > low) || count < 1) return {low};
    const double raw = (high - low) / count;
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * magnitude >= raw) {
            step = m * magnitude;
            break;
        }
    std::vector<double> ticks;
    for (double v = std::ceil(low / step) * step; v <= high + step * 1e-9; v += step) ticks.push_back(v);
    return ticks;
}

PlotFrame plotFrame(const LinePlot& plot, int width, int height) {
    PlotFrame f;
    double xMin = std::numeric_limits<double>::max(), xMax = -xMin, yMin = xMin, yMax = -xMin;
    auto extend = [&](const std::vector<double>& x, const std::vector<double>& y) {
        for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
            if (!std::isfinite(x[i]) || !std::isfinite(y[i])) continue;
            xMin = std::min(xMin, x[i]), xMax = std::max(xMax, x[i]);
            yMin = std::min(yMin, y[i]), yMax = std::max(yMax, y[i]);
        }
    };
    for (const PlotSeries& s : plot.series) extend(s.x, s.y);
    for (const PlotPoints& p : plot.points) extend(p.x, p.y);
    if (xMin > xMax) xMin = 0.0, xMax = 1.0, yMin = 0.0, yMax = 1.0;  // nothing to draw: still axes
    if (xMax - xMin <= 0.0) xMax = xMin + 1.0;
    // Markers and their labels need room at the ends of the x range too.
    if (!plot.points.empty()) {
        const double xSpan = xMax - xMin;
        xMin -= xSpan * 0.04, xMax += xSpan * 0.10;
    }
    // Differences of 1e-6 in depth matter here: keep a span of at least a few float steps around the data.
    const double ySpan = std::max(yMax - yMin, std::max(std::abs(yMax), 1.0) * 1e-7);
    yMin -= ySpan * 0.08, yMax += ySpan * 0.08;
    f.xMin = xMin, f.xMax = xMax, f.yMin = yMin, f.yMax = yMax;
    f.yTicks = niceTicks(yMin, yMax, 6), f.xTicks = niceTicks(xMin, xMax, 8);
    f.ySpacing = f.yTicks.size() > 1 ? f.yTicks[1] - f.yTicks[0] : ySpan;
    f.xSpacing = f.xTicks.size() > 1 ? f.xTicks[1] - f.xTicks[0] : 1.0;
    int labelWidth = 0;
    for (double v : f.yTicks) labelWidth = std::max(labelWidth, Canvas::textWidth(tickText(v, f.ySpacing)));
    f.left = labelWidth + 22, f.right = width - 12, f.top = 26, f.bottom = height - 34;
    f.drawable = f.right - f.left >= 20 && f.bottom - f.top >= 20;
    return f;
}

PlotImage drawLinePlot(const LinePlot& plot, int width, int height) {
    PlotImage image{width, height, {}};
    Canvas canvas(width, height);
    const PlotFrame f = plotFrame(plot, width, height);
    if (!f.drawable) {
        image.rgba = canvas.take();
        return image;
    }
    const int left = f.left, right = f.right, top = f.top, bottom = f.bottom;
    auto px = [&](double x) { return f.px(x); };
    auto py = [&](double y) { return f.py(y); };
    const std::vector<double>& yTicks = f.yTicks;
    const std::vector<double>& xTicks = f.xTicks;
    const double ySpacing = f.ySpacing, xSpacing = f.xSpacing;
    const PlotColor axis{40, 40, 40, 255}, grid{0, 0, 0, 28}, ink{20, 20, 20, 255};

    for (const PlotSpan& s : plot.spans)
        canvas.fill(int(std::floor(px(s.x0))), top, int(std::ceil(px(s.x1))) + 1, bottom, s.color);
    for (double v : yTicks) {
        const int y = int(std::lround(py(v)));
        canvas.line(left, y, right, y, grid, 1);
        const std::string t = tickText(v, ySpacing);
        canvas.text(left - 6 - Canvas::textWidth(t), y - 3, t, ink);
    }
    for (double v : xTicks) {
        const int x = int(std::lround(px(v)));
        canvas.line(x, top, x, bottom, grid, 1);
        const std::string t = tickText(v, xSpacing);
        canvas.text(x - Canvas::textWidth(t) / 2, bottom + 6, t, ink);
    }
    canvas.line(left, top, left, bottom, axis, 1);
    canvas.line(left, bottom, right, bottom, axis, 1);

    for (const PlotSeries& s : plot.series) {
        const std::size_t n = std::min(s.x.size(), s.y.size());
        for (std::size_t i = 0; i + 1 < n; ++i) {
            if (!std::isfinite(s.y[i]) || !std::isfinite(s.y[i + 1])) continue;
            if (s.staircase) {  // each y holds over its x's cell, changing halfway to the next x
                const double mid = 0.5 * (s.x[i] + s.x[i + 1]);
                const double start = i == 0 ? s.x[0] : mid - (s.x[i + 1] - s.x[i]);
                canvas.line(px(start), py(s.y[i]), px(mid), py(s.y[i]), s.color);
                canvas.line(px(mid), py(s.y[i]), px(mid), py(s.y[i + 1]), s.color);
                if (i + 2 == n) canvas.line(px(mid), py(s.y[i + 1]), px(s.x[i + 1]), py(s.y[i + 1]), s.color);
            } else {
                canvas.line(px(s.x[i]), py(s.y[i]), px(s.x[i + 1]), py(s.y[i + 1]), s.color);
            }
        }
    }

    // Markers, then labels beside them where they cover no other label or marker (else the label is left out).
    using Box = std::array<int, 4>;  // x0, y0, x1, y1
    std::vector<Box> taken;
    for (const PlotPoints& s : plot.points)
        for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
            if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
            const double cx = px(s.x[i]), cy = py(s.y[i]);
            canvas.disc(cx, cy, double(s.radius), s.ring, s.color);
            taken.push_back({int(cx) - s.radius, int(cy) - s.radius, int(cx) + s.radius + 1, int(cy) + s.radius + 1});
        }
    for (const PlotPoints& s : plot.points)
        for (std::size_t i = 0; i < std::min({s.x.size(), s.y.size(), s.labels.size()}); ++i) {
            if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]) || s.labels[i].empty()) continue;
            const double cx = px(s.x[i]), cy = py(s.y[i]);
            // Clear of every marker drawn on this spot (a ring around the point included).
            int r = s.radius;
            for (const PlotPoints& o : plot.points)
                for (std::size_t j = 0; j < std::min(o.x.size(), o.y.size()); ++j)
                    if (std::abs(px(o.x[j]) - cx) < 1.0 && std::abs(py(o.y[j]) - cy) < 1.0) r = std::max(r, o.radius);
            r += 3;
            const int w = Canvas::textWidth(s.labels[i]);
            const std::array<std::array<int, 2>, 4> places{{{int(cx) + r, int(cy) - 3},
                                                            {int(cx) - r - w, int(cy) - 3},
                                                            {int(cx) - w / 2, int(cy) - r - 8},
                                                            {int(cx) - w / 2, int(cy) + r + 1}}};
            for (const auto& place : places) {
                const Box box{place[0] - 1, place[1] - 1, place[0] + w + 1, place[1] + 8};
                const bool overlaps = std::any_of(taken.begin(), taken.end(), [&](const Box& t) {
                    const bool own = t[0] <= int(cx) && int(cx) < t[2] && t[1] <= int(cy) && int(cy) < t[3];
                    return !own && box[0] < t[2] && t[0] < box[2] && box[1] < t[3] && t[1] < box[3];
                });
                if (overlaps || box[0] < left || box[2] > right || box[1] < top || box[3] > bottom) continue;
                taken.push_back(box);
                canvas.text(place[0], place[1], s.labels[i], ink);
                break;
            }
        }

    canvas.text(left, 8, plot.title, ink);
    canvas.text((left + right) / 2 - Canvas::textWidth(plot.xLabel) / 2, height - 14, plot.xLabel, ink);
    canvas.text(4, 8 + 10, plot.yLabel, ink);
    // Legend: top right, one row per series and per distinct span label.
    std::vector<std::pair<std::string, PlotColor>> entries;
    for (const PlotSeries& s : plot.series)
        if (!s.label.empty()) entries.emplace_back(s.label, s.color);
    for (const PlotPoints& p : plot.points)
        if (!p.label.empty()) entries.emplace_back(p.label, p.color);
    for (const PlotSpan& s : plot.spans)
        if (std::none_of(entries.begin(), entries.end(), [&](const auto& e) { return e.first == s.label; }))
            entries.emplace_back(s.label, PlotColor{s.color[0], s.color[1], s.color[2], 160});
    int legendWidth = 0;
    for (const auto& e : entries) legendWidth = std::max(legendWidth, Canvas::textWidth(e.first));
    const int lx = right - legendWidth - 34, ly = top + 6;
    canvas.fill(lx - 4, ly - 4, right - 4, ly + int(entries.size()) * 12 + 2, {255, 255, 255, 220});
    for (std::size_t k = 0; k < entries.size(); ++k) {
        const int y = ly + int(k) * 12;
        canvas.fill(lx, y + 1, lx + 20, y + 6, entries[k].second);
        canvas.text(lx + 26, y, entries[k].first, ink);
    }
    image.rgba = canvas.take();
    return image;
}

}  // namespace shadowlab
