#include "image/split_view.h"

#include "image/canvas.h"

#include <algorithm>
#include <cmath>

namespace shadowlab {

std::vector<std::uint8_t> topRowFirst(const std::vector<std::uint8_t>& glRows, int width, int height) {
    std::vector<std::uint8_t> out(glRows.size());
    const std::size_t stride = std::size_t(width) * 4;
    for (int y = 0; y < height; ++y)
        std::copy_n(glRows.begin() + std::ptrdiff_t(std::size_t(height - 1 - y) * stride), stride,
                    out.begin() + std::ptrdiff_t(std::size_t(y) * stride));
    return out;
}

int splitColumn(int width, double split) {
    const double f = std::isfinite(split) ? std::clamp(split, 0.0, 1.0) : 0.5;
    return std::clamp(int(std::lround(f * width)), 0, width);
}

std::vector<std::uint8_t> composeSplitView(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                                           int width, int height, double split, const std::vector<std::string>& labelA,
                                           const std::vector<std::string>& labelB) {
    const int column = splitColumn(width, split);
    std::vector<std::uint8_t> out(a.size());
    for (int y = 0; y < height; ++y) {
        const std::size_t row = std::size_t(y) * std::size_t(width) * 4;
        const std::size_t cut = row + std::size_t(column) * 4, end = row + std::size_t(width) * 4;
        std::copy(a.begin() + std::ptrdiff_t(row), a.begin() + std::ptrdiff_t(cut), out.begin() + std::ptrdiff_t(row));
        std::copy(b.begin() + std::ptrdiff_t(cut), b.begin() + std::ptrdiff_t(end), out.begin() + std::ptrdiff_t(cut));
    }
    Canvas canvas(width, height, std::move(out));
    const CanvasColor divider{255, 210, 40, 255}, box{0, 0, 0, 170}, ink{255, 255, 255, 255};
    canvas.fill(column - 1, 0, column + 1, height, divider);
    // Each side's lines in a dark box: A at the top left, B at the top right.
    auto labelBox = [&](const std::vector<std::string>& lines, bool right) {
        int w = 0;
        for (const std::string& line : lines) w = std::max(w, Canvas::textWidth(line));
        if (lines.empty()) return;
        const int boxW = w + 8, boxH = int(lines.size()) * 10 + 6;
        const int x0 = right ? width - boxW - 4 : 4;
        canvas.fill(x0, 4, x0 + boxW, 4 + boxH, box);
        for (std::size_t i = 0; i < lines.size(); ++i) canvas.text(x0 + 4, 8 + int(i) * 10, lines[i], ink);
    };
    labelBox(labelA, false);
    labelBox(labelB, true);
    return canvas.take();
}

}  // namespace shadowlab
