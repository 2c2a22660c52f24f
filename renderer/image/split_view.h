#pragma once
// A/B comparison as one picture: the left part of view A beside the right part of view B at `split` (0..1 of the
// width), a divider between them, and each side's label lines (its name, times, accuracy) in a box at its top corner.
#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

// `a` and `b` are RGBA8 of width x height with row 0 at the top; so is the result.
std::vector<std::uint8_t> composeSplitView(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b,
                                           int width, int height, double split, const std::vector<std::string>& labelA,
                                           const std::vector<std::string>& labelB);

// GL's rows (bottom first, as RenderTarget::readColor gives them) in the order the split view takes (top first).
std::vector<std::uint8_t> topRowFirst(const std::vector<std::uint8_t>& glRows, int width, int height);

// The divider's column for a split fraction (clamped into the picture).
int splitColumn(int width, double split);

}  // namespace shadowlab
