#include "shadow/shadow_map.h"

#include "settings/settings_fields.h"

#include <algorithm>

#include "gl/gl_errors.h"
#include "shading/filter_taps.h"

namespace shadowlab {

GLenum depthInternalFormat(DepthFormat format) {
    switch (format) {
        case DepthFormat::D16: return GL_DEPTH_COMPONENT16;
        case DepthFormat::D24: return GL_DEPTH_COMPONENT24;
        case DepthFormat::D32F: return GL_DEPTH_COMPONENT32F;
    }
    return GL_DEPTH_COMPONENT32F;
}

const char* depthFormatName(DepthFormat format) {
    switch (format) {
        case DepthFormat::D16: return "D16";
        case DepthFormat::D24: return "D24";
        case DepthFormat::D32F: return "D32F";
    }
    return "?";
}

int depthFormatBytes(DepthFormat format) {
    switch (format) {
        case DepthFormat::D16: return 2;
        case DepthFormat::D24: return 4;  // stored padded to 32 bits by every driver we know
        case DepthFormat::D32F: return 4;
    }
    return 4;
}

std::string ShadowMap::ensure(int resolution, DepthFormat format, int maxTextureSize) {
    if (texture_ && resolution == resolution_ && format == format_) return {};
    // The key's own range, narrowed by the GPU: the same bounds the preset table states.
    const SettingsField& key = *findSettingsField("shadow.resolution");
    const int lo = int(key.min), hi = std::min(int(key.max), maxTextureSize);
    if (resolution < lo || resolution > hi)
        return "shadow.resolution: " + std::to_string(resolution) + " is outside what this GPU allows [" +
               std::to_string(lo) + ", " + std::to_string(hi) + "] (GL_MAX_TEXTURE_SIZE " +
               std::to_string(maxTextureSize) + "); " +
               (texture_ ? "keeping the " + std::to_string(resolution_) + "² map" : std::string("no shadow map yet"));

    gl::drainErrors();
    gl::Texture texture = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.id(), 1, depthInternalFormat(format), resolution, resolution);
    // The debug callback also records these; a refused allocation is a user-facing message, not a bug.
    if (std::string error = gl::drainErrors(); !error.empty()) {
        gl::takeDebugErrors();
        return "shadow map " + std::to_string(resolution) + "² " + depthFormatName(format) + " could not be allocated (" +
               error + "); keeping the previous map";
    }
    gl::Framebuffer framebuffer = gl::createFramebuffer();
    glNamedFramebufferTexture(framebuffer.id(), GL_DEPTH_ATTACHMENT, texture.id(), 0);
    glNamedFramebufferDrawBuffer(framebuffer.id(), GL_NONE);
    glNamedFramebufferReadBuffer(framebuffer.id(), GL_NONE);
    const GLenum status = glCheckNamedFramebufferStatus(framebuffer.id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return "shadow map framebuffer incomplete (status 0x" + std::to_string(status) + "); keeping the previous map";

    texture_ = std::move(texture);
    framebuffer_ = std::move(framebuffer);
    resolution_ = resolution;
    format_ = format;
    ++generation_;
    if (!compareSampler_) compareSampler_ = gl::createSampler();
    return {};
}

void ShadowMap::configureSamplers(const SamplerSettings& sampler, FilterKind filter) {
    if (!compareSampler_) compareSampler_ = gl::createSampler();
    if (samplerState_ && samplerState_->first == sampler && samplerState_->second == filter) return;
    samplerState_ = std::make_pair(sampler, filter);
    const GLuint s = compareSampler_.id();
    GLint wrap = GL_CLAMP_TO_BORDER;
    switch (sampler.addressMode) {
        case AddressMode::Wrap: wrap = GL_REPEAT; break;
        case AddressMode::ClampToEdge: wrap = GL_CLAMP_TO_EDGE; break;
        case AddressMode::ClampToBorder: wrap = GL_CLAMP_TO_BORDER; break;
    }
    glSamplerParameteri(s, GL_TEXTURE_WRAP_S, wrap);
    glSamplerParameteri(s, GL_TEXTURE_WRAP_T, wrap);
    const float border[4] = {sampler.borderDepth, sampler.borderDepth, sampler.borderDepth, sampler.borderDepth};
    glSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, border);
    // Hardware 2x2 and Poisson taps use the comparison's bilinear filter; point and grid PCF compare single texels.
    const bool linear = filterIsBilinear(filter);
    glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, linear ? GL_LINEAR : GL_NEAREST);
    glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, linear ? GL_LINEAR : GL_NEAREST);
    glSamplerParameteri(s, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(s, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

std::vector<float> ShadowMap::readDepth() const {
    std::vector<float> depth(std::size_t(resolution_) * resolution_);
    if (!texture_) return depth;
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(depth.size() * sizeof(float)),
                      depth.data());
    return depth;
}

}  // namespace shadowlab
