#include "reference/alpha_mask.h"

#include <cmath>

namespace shadowlab {

namespace {

int wrapRepeat(int i, int size) {
    const int m = i % size;
    return m < 0 ? m + size : m;
}

}  // namespace

AlphaMask::AlphaMask(const Material& material, const Image* image, const std::vector<glm::vec2>& uvs,
                     const std::vector<std::uint32_t>& indices)
    : image_(image && image->valid() ? image : nullptr),
      uvs_(&uvs),
      indices_(&indices),
      uvTransform_(material.uvTransform),
      factor_(material.baseColorFactor.a),
      cutoff_(material.alphaCutoff) {}

float AlphaMask::alphaAt(const glm::vec2& uv) const {
    if (!image_) return factor_;
    // GL's bilinear filter at mip 0: texel centres at (i + 0.5) / size; image row 0 is texture t = 0.
    const float x = uv.x * float(image_->width) - 0.5f;
    const float y = uv.y * float(image_->height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float ax = x - fx, ay = y - fy;
    const int x0 = wrapRepeat(int(fx), image_->width), x1 = wrapRepeat(int(fx) + 1, image_->width);
    const int y0 = wrapRepeat(int(fy), image_->height), y1 = wrapRepeat(int(fy) + 1, image_->height);
    auto alpha = [&](int px, int py) {
        return float(image_->rgba[(std::size_t(py) * std::size_t(image_->width) + std::size_t(px)) * 4 + 3]) / 255.0f;
    };
    const float top = alpha(x0, y0) * (1.0f - ax) + alpha(x1, y0) * ax;
    const float bottom = alpha(x0, y1) * (1.0f - ax) + alpha(x1, y1) * ax;
    return factor_ * (top * (1.0f - ay) + bottom * ay);
}

bool AlphaMask::opaqueAt(unsigned primitive, float u, float v) const {
    glm::vec2 uv(0.0f);
    if (!uvs_->empty()) {
        const std::size_t base = std::size_t(primitive) * 3;
        const glm::vec2& t0 = (*uvs_)[(*indices_)[base]];
        const glm::vec2& t1 = (*uvs_)[(*indices_)[base + 1]];
        const glm::vec2& t2 = (*uvs_)[(*indices_)[base + 2]];
        uv = (1.0f - u - v) * t0 + u * t1 + v * t2;
    }
    const glm::vec2 transformed = glm::vec2(uvTransform_ * glm::vec3(uv, 1.0f));
    return alphaAt(transformed) >= cutoff_;
}

}  // namespace shadowlab
