#pragma once
// Shadow map storage: arrays of square depth maps per resolution/format group, the per-view 2D map a shadow pass
// renders into, and the comparison sampler the main pass reads them through.
#include "gl/gl_objects.h"
#include "settings/settings.h"
#include "views/map_group.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <string>
#include <vector>

namespace shadowlab {

GLenum depthInternalFormat(DepthFormat format);
const char* depthFormatName(DepthFormat format);
int depthFormatBytes(DepthFormat format);

// The maps of one resolution/format group: a 2D texture array (directional and spot views, a layer each) or a
// cube-map array (point lights, six layers each). Immutable storage, reallocated only when the group's size, format
// or layer count changes; an allocation the GPU refuses keeps the previous one.
class ShadowMapArray {
public:
    // Returns "" on success (or when nothing changed), else why the new array could not be made.
    std::string ensure(bool cube, int resolution, DepthFormat format, int layers, int maxTextureSize,
                       int maxArrayLayers);
    // The depth convention of the maps it holds (reversed-Z: near 1, far 0); a label, no storage change.
    void setReversedZ(bool reversed) { reversedZ_ = reversed; }
    bool reversedZ() const { return reversedZ_; }

    bool valid() const { return bool(texture_); }
    bool cube() const { return cube_; }
    int resolution() const { return resolution_; }
    DepthFormat format() const { return format_; }
    int layers() const { return layers_; }
    GLuint texture() const { return texture_.id(); }
    std::uint64_t generation() const { return generation_; }  // unique across all arrays, bumped at each allocation
    std::size_t memoryBytes() const {
        return std::size_t(resolution_) * std::size_t(resolution_) * std::size_t(layers_) * std::size_t(depthFormatBytes(format_));
    }

private:
    gl::Texture texture_;
    bool cube_ = false;
    int resolution_ = 0;
    int layers_ = 0;
    DepthFormat format_ = DepthFormat::D32F;
    std::uint64_t generation_ = 0;
    bool reversedZ_ = false;
};

// One shadow view's map: one layer of a ShadowMapArray seen as a plain 2D depth texture (a GL texture view, which
// shares the array's storage), with the framebuffer the shadow pass renders that layer through. The map viewer,
// the probe, the exporters and the screenshots read it like any 2D map.
class ShadowMap {
public:
    // A standalone map (tests, tools): its own one-layer array. Returns "" or why it could not be made (the old
    // map stays).
    std::string ensure(int resolution, DepthFormat format, int maxTextureSize);
    // Views layer `layer` of `array` (no GL work when it already does).
    std::string attach(const ShadowMapArray& array, int layer);

    bool valid() const { return bool(texture_); }
    // Changes whenever the storage behind the map changes (a new allocation or another layer).
    std::uint64_t generation() const { return generation_; }
    int resolution() const { return resolution_; }
    DepthFormat format() const { return format_; }
    bool reversedZ() const { return reversedZ_; }  // its array's depth convention (near 1, far 0)
    int layer() const { return layer_; }
    GLuint framebuffer() const { return framebuffer_.id(); }
    GLuint texture() const { return texture_.id(); }
    std::size_t memoryBytes() const { return std::size_t(resolution_) * resolution_ * depthFormatBytes(format_); }

    // Reads the stored depth (row 0 = bottom, as GL stores it) as floats in [0,1]: the whole map, or a rectangle
    // of texels inside it. Reads the array's layer, not the view (NVIDIA returns wrong data for a view of a
    // cube-map-array layer).
    std::vector<float> readDepth() const;
    std::vector<float> readDepthRect(int x0, int y0, int w, int h) const;

private:
    std::unique_ptr<ShadowMapArray> own_;  // set by ensure()
    gl::Texture texture_;                  // the 2D view of the layer
    gl::Framebuffer framebuffer_;
    GLuint arrayTexture_ = 0;              // the array the layer belongs to (owned by it, or by own_)
    std::uint64_t arrayGeneration_ = 0;
    std::uint64_t generation_ = 0;
    int layer_ = -1;
    int resolution_ = 0;
    DepthFormat format_ = DepthFormat::D32F;
    bool reversedZ_ = false;
};

// The comparison sampler shadow lookups of one depth convention go through (address mode, border depth, the
// filter's bilinear or nearest comparison, LEQUAL or reversed-Z's GEQUAL with the border depth mirrored); no GL calls
// when unchanged. Cube maps ignore the address mode (a direction is never outside).
class ShadowSampler {
public:
    explicit ShadowSampler(bool reversedZ = false) : reversedZ_(reversedZ) {}
    void configure(const SamplerSettings& sampler, FilterKind filter);
    GLuint id() const { return sampler_.id(); }
    bool reversedZ() const { return reversedZ_; }

private:
    bool reversedZ_ = false;
    gl::Sampler sampler_;
    std::optional<std::pair<SamplerSettings, FilterKind>> state_;
};

}  // namespace shadowlab
