#pragma once
// The shadow map: a square depth texture and the framebuffer that renders into it, plus the two samplers that
// read it (comparison for shading, raw depth for viewing/exporting). Reallocated only when size or format change;
// a size or format the GPU refuses keeps the previous map.
#include "gl/gl_objects.h"
#include "settings/settings.h"

#include <cstdint>
#include <optional>
#include <utility>
#include <string>
#include <vector>

namespace shadowlab {

GLenum depthInternalFormat(DepthFormat format);
const char* depthFormatName(DepthFormat format);
int depthFormatBytes(DepthFormat format);

class ShadowMap {
public:
    // Returns "" on success (or when nothing changed), else why the new map could not be made; the old one stays.
    std::string ensure(int resolution, DepthFormat format, int maxTextureSize);

    // Sampler state from the settings (address mode, border depth, comparison filter); no GL calls if unchanged.
    void configureSamplers(const SamplerSettings& sampler, FilterKind filter);

    bool valid() const { return bool(texture_); }
    std::uint64_t generation() const { return generation_; }  // bumped at each (re)allocation
    int resolution() const { return resolution_; }
    DepthFormat format() const { return format_; }
    GLuint framebuffer() const { return framebuffer_.id(); }
    GLuint texture() const { return texture_.id(); }
    GLuint compareSampler() const { return compareSampler_.id(); }
    std::size_t memoryBytes() const { return std::size_t(resolution_) * resolution_ * depthFormatBytes(format_); }

    // Reads the stored depth (row 0 = bottom, as GL stores it) as floats in [0,1].
    std::vector<float> readDepth() const;

private:
    gl::Texture texture_;
    gl::Framebuffer framebuffer_;
    gl::Sampler compareSampler_;
    std::optional<std::pair<SamplerSettings, FilterKind>> samplerState_;  // what compareSampler_ is set to
    int resolution_ = 0;
    std::uint64_t generation_ = 0;
    DepthFormat format_ = DepthFormat::D32F;
};

}  // namespace shadowlab
