#include "overlay/map_zoom_pan.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

// Map uv per view pixel: at zoom 1 the view's shorter side spans the whole map.
double uvPerPixel(double zoom, int viewWidth, int viewHeight) {
    return 1.0 / (zoom * double(std::max(1, std::min(viewWidth, viewHeight))));
}

}  // namespace

UvRect MapZoomPan::visibleRect(int viewWidth, int viewHeight) const {
    const double s = uvPerPixel(zoom_, viewWidth, viewHeight);
    const glm::dvec2 half(0.5 * s * std::max(1, viewWidth), 0.5 * s * std::max(1, viewHeight));
    return {center_ - half, center_ + half};
}

void MapZoomPan::zoomAt(double viewX, double viewY, double factor, int viewWidth, int viewHeight, int resolution) {
    if (!(factor > 0.0) || !std::isfinite(factor)) return;
    const glm::dvec2 anchor = viewToUv(visibleRect(viewWidth, viewHeight), viewX, viewY, viewWidth, viewHeight);
    const double maxZoom =
        std::max(1.0, kMaxTexelPixels * std::max(1, resolution) / double(std::max(1, std::min(viewWidth, viewHeight))));
    zoom_ = std::clamp(zoom_ * factor, kMinZoom, maxZoom);
    // Put the anchor back under the cursor at the new scale.
    const double s = uvPerPixel(zoom_, viewWidth, viewHeight);
    center_ = anchor - glm::dvec2((viewX - 0.5 * viewWidth) * s, (0.5 * viewHeight - viewY) * s);
}

void MapZoomPan::focus(const glm::dvec2& uv, double zoom, int viewWidth, int viewHeight, int resolution) {
    zoom_ = 1.0;
    zoomAt(0.5 * viewWidth, 0.5 * viewHeight, zoom, viewWidth, viewHeight, resolution);
    center_ = glm::clamp(uv, glm::dvec2(0.0), glm::dvec2(1.0));
}

void MapZoomPan::pan(double dx, double dy, int viewWidth, int viewHeight) {
    const double s = uvPerPixel(zoom_, viewWidth, viewHeight);
    // The map follows the mouse; view y grows downward, uv v upward. The centre stays on the map.
    center_ = glm::clamp(center_ - glm::dvec2(dx * s, -dy * s), glm::dvec2(0.0), glm::dvec2(1.0));
}

glm::dvec2 viewToUv(const UvRect& rect, double viewX, double viewY, int viewWidth, int viewHeight) {
    const double fx = viewX / double(std::max(1, viewWidth));
    const double fy = viewY / double(std::max(1, viewHeight));
    return {rect.min.x + fx * (rect.max.x - rect.min.x), rect.max.y - fy * (rect.max.y - rect.min.y)};
}

glm::dvec2 uvToView(const UvRect& rect, const glm::dvec2& uv, int viewWidth, int viewHeight) {
    const double fx = (uv.x - rect.min.x) / (rect.max.x - rect.min.x);
    const double fy = (rect.max.y - uv.y) / (rect.max.y - rect.min.y);
    return {fx * std::max(1, viewWidth), fy * std::max(1, viewHeight)};
}

std::optional<glm::ivec2> texelAtView(const UvRect& rect, double viewX, double viewY, int viewWidth, int viewHeight,
                                      int resolution) {
    const glm::dvec2 uv = viewToUv(rect, viewX, viewY, viewWidth, viewHeight);
    if (!(uv.x >= 0.0 && uv.x < 1.0 && uv.y >= 0.0 && uv.y < 1.0)) return std::nullopt;
    const int last = std::max(0, resolution - 1);
    return glm::ivec2(std::min(int(uv.x * resolution), last), std::min(int(uv.y * resolution), last));
}

double texelPixels(const UvRect& rect, int viewWidth, int resolution) {
    const double span = (rect.max.x - rect.min.x) * std::max(1, resolution);
    return span > 0.0 ? viewWidth / span : 0.0;
}

}  // namespace shadowlab
