#pragma once
// The scrolling cascade cache (issue 22): a stable cascade (projection.cascadeFit stable) follows the camera by whole
// texels of the light's fixed grid, so its new map is its old one moved by those texels, plus the strips that came
// into view. What tells such a move from any other change of the view, and which texels it leaves to draw (no GL).
#include "views/caster_motion.h"

#include <glm/ext/matrix_double4x4.hpp>

#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

// A map's contents moved across the map: the old texel (x, y) holds what the new map has at (x + dx, y + dy).
struct TexelShift {
    int dx = 0, dy = 0;
    bool operator==(const TexelShift&) const = default;
};

struct CascadeScroll {
    std::optional<TexelShift> shift;  // nullopt: the move is no whole-texel scroll (`why` says what else changed)
    std::string why;                  // "its depth range changed", "its size changed", "moved by 2.5 texels", ...
};

// Whether a view drawn through `before` (clip from render-origin-relative world) is drawn through `now` by a whole-
// texel translation across a map of `resolution` texels: the same light rotation, size and depth range (as the shader
// receives them: in float), a clip-space offset of whole texels in x and y, less than the map wide.
CascadeScroll cascadeScroll(const glm::dmat4& before, const glm::dmat4& now, int resolution);

// The texels a shift leaves without old contents (up to two disjoint rectangles: the columns, then the rows beside
// them), and the rectangles an old map's overlap is copied from and to.
std::vector<TexelRect> exposedStrips(const TexelShift& shift, int resolution);
TexelRect scrollSource(const TexelShift& shift, int resolution);  // in the old map
TexelRect scrollTarget(const TexelShift& shift, int resolution);  // in the new map

// Pages: a stable cascade's static depth is drawn in pages of the light's fixed texel grid, each page through its own
// matrix (the cascade's light view and depth range, centred on the page), so that what a texel stores depends on the
// page alone, never on where the cascade stands: a scrolled map and one drawn whole store the same bits (a plain
// draw through the cascade's matrix rounds a vertex's position relative to the cascade's centre, and so differs in
// the last bits from a draw at another centre). A page is kPagesAcross times smaller than the map (the map itself
// when its resolution is not a multiple of that).
inline constexpr int kPagesAcross = 4;
struct CascadePage {
    LightSpace space;  // the page's light space: `resolution` = the page's texels across
    TexelRect inPage;  // the texels of the page to draw (its part of the region asked for)
    TexelRect inMap;   // where they go in the cascade's map (the same size)
};
// The pages that meet `region` (texels of the cascade's map), or nothing when `cascade` is no stable cascade's
// (its centre off the grid of its texels).
std::vector<CascadePage> cascadePages(const LightSpace& cascade, const TexelRect& region);

// "scrolled 3,-1 texels: 99.8 % reused"
std::string describeScroll(const TexelShift& shift, int resolution);

}  // namespace shadowlab
