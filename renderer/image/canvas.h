#pragma once
// A small RGBA8 raster (row 0 = top) with the few primitives the charts and labelled pictures need: blended
// pixels, rectangles, 2-pixel lines, discs and stb_easy_font text (7 px tall at scale 1).
#include <stb_easy_font.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

using CanvasColor = std::array<std::uint8_t, 4>;  // RGBA; A blends over what is there

class Canvas {
public:
    // A white canvas.
    Canvas(int w, int h) : w_(w), h_(h), rgba_(std::size_t(w) * std::size_t(h) * 4, 255) {}
    // Drawing over an existing RGBA8 picture (row 0 = top), e.g. labels on a rendered view.
    Canvas(int w, int h, std::vector<std::uint8_t> rgba) : w_(w), h_(h), rgba_(std::move(rgba)) {}

    void blend(int x, int y, const CanvasColor& c) {
        if (x < 0 || y < 0 || x >= w_ || y >= h_) return;
        std::uint8_t* p = &rgba_[(std::size_t(y) * std::size_t(w_) + std::size_t(x)) * 4];
        const int a = c[3];
        for (int k = 0; k < 3; ++k) p[k] = std::uint8_t((c[std::size_t(k)] * a + p[k] * (255 - a)) / 255);
        p[3] = 255;
    }
    void fill(int x0, int y0, int x1, int y1, const CanvasColor& c) {
        for (int y = std::max(y0, 0); y < std::min(y1, h_); ++y)
            for (int x = std::max(x0, 0); x < std::min(x1, w_); ++x) blend(x, y, c);
    }
    // A 2-pixel wide line (Bresenham with a thickening pixel below), thick enough to read in a PNG.
    void line(double ax, double ay, double bx, double by, const CanvasColor& c, int thickness = 2) {
        const int steps = int(std::ceil(std::max(std::abs(bx - ax), std::abs(by - ay)))) + 1;
        for (int i = 0; i <= steps; ++i) {
            const double t = double(i) / steps;
            const int x = int(std::lround(ax + (bx - ax) * t)), y = int(std::lround(ay + (by - ay) * t));
            for (int d = 0; d < thickness; ++d) setPixel(x, y + d, c);
        }
    }
    void text(int x, int y, const std::string& s, const CanvasColor& c) {
        // stb_easy_font emits quads (4 vertices of 16 bytes: x, y, z floats and a colour) at scale 1 (7 px tall).
        static thread_local char buffer[99999];
        const int quads = stb_easy_font_print(float(x), float(y), const_cast<char*>(s.c_str()), nullptr, buffer,
                                              int(sizeof(buffer)));
        for (int q = 0; q < quads; ++q) {
            const float* v = reinterpret_cast<const float*>(buffer + q * 64);
            fill(int(v[0]), int(v[1]), int(v[8]), int(v[9]), c);
        }
    }
    // A filled disc (or a 2-pixel ring) of radius r centred on (cx, cy).
    void disc(double cx, double cy, double r, bool ring, const CanvasColor& c) {
        for (int y = int(std::floor(cy - r - 1)); y <= int(std::ceil(cy + r + 1)); ++y)
            for (int x = int(std::floor(cx - r - 1)); x <= int(std::ceil(cx + r + 1)); ++x) {
                const double d = std::hypot(double(x) - cx, double(y) - cy);
                if (d <= r && (!ring || d >= r - 2.0)) blend(x, y, c);
            }
    }
    static int textWidth(const std::string& s) { return stb_easy_font_width(const_cast<char*>(s.c_str())); }
    std::vector<std::uint8_t> take() { return std::move(rgba_); }

private:
    void setPixel(int x, int y, const CanvasColor& c) { blend(x, y, c); }
    int w_, h_;
    std::vector<std::uint8_t> rgba_;
};


}  // namespace shadowlab
