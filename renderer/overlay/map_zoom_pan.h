#pragma once
// Zoom and pan of a square map shown in a view of any size: which part of the map (a uv rectangle, v up as GL
// stores it) the view shows, with square texels, zoomed about the cursor and dragged by the mouse. No GL.
#include <glm/ext/vector_double2.hpp>
#include <glm/ext/vector_int2.hpp>

#include <optional>

namespace shadowlab {

struct UvRect {
    glm::dvec2 min{0.0, 0.0};  // map uv at the view's bottom-left corner
    glm::dvec2 max{1.0, 1.0};  // map uv at the view's top-right corner

    bool operator==(const UvRect&) const = default;
};

class MapZoomPan {
public:
    static constexpr double kMinZoom = 0.25;
    static constexpr double kMaxTexelPixels = 64.0;  // zooming stops when one texel covers this many view pixels

    // zoom 1: the whole map fits the view (centred); 2: half of it, and so on.
    double zoom() const { return zoom_; }
    glm::dvec2 center() const { return center_; }
    void reset() { zoom_ = 1.0; center_ = {0.5, 0.5}; }

    UvRect visibleRect(int viewWidth, int viewHeight) const;

    // Multiplies the zoom by `factor` (e.g. 1.25 per wheel step up, 0.8 down), keeping the map point under the
    // view position (x right, y down, in view pixels) where it is. The zoom is clamped to [kMinZoom, the zoom where
    // one of the map's `resolution` texels covers kMaxTexelPixels].
    void zoomAt(double viewX, double viewY, double factor, int viewWidth, int viewHeight, int resolution);

    // Centres the view on map point `uv` at `zoom` (clamped as zoomAt clamps it): "zoom to the probe's taps".
    void focus(const glm::dvec2& uv, double zoom, int viewWidth, int viewHeight, int resolution);

    // Moves the map with the mouse: (dx, dy) in view pixels, y down.
    void pan(double dx, double dy, int viewWidth, int viewHeight);

private:
    glm::dvec2 center_{0.5, 0.5};
    double zoom_ = 1.0;
};

// View pixels (x right, y down, pixel centres at +0.5) -> map uv, through the visible rectangle.
glm::dvec2 viewToUv(const UvRect& rect, double viewX, double viewY, int viewWidth, int viewHeight);

// Map uv -> view pixels (x right, y down): the inverse of viewToUv.
glm::dvec2 uvToView(const UvRect& rect, const glm::dvec2& uv, int viewWidth, int viewHeight);

// The texel (x right, y up: GL's texel addressing, as texelFetch and glGetTextureSubImage use) under a view
// position; nullopt when the position is off the map.
std::optional<glm::ivec2> texelAtView(const UvRect& rect, double viewX, double viewY, int viewWidth, int viewHeight,
                                      int resolution);

// How many view pixels one map texel covers (horizontally).
double texelPixels(const UvRect& rect, int viewWidth, int resolution);

}  // namespace shadowlab
