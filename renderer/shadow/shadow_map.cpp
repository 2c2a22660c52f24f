#include "shadow/shadow_map.h"

#include "settings/settings_fields.h"

#include <algorithm>

#include "gl/gl_errors.h"
#include "light/light_space.h"
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

namespace {

std::uint64_t nextGeneration() {
    static std::uint64_t generation = 0;
    return ++generation;
}

}  // namespace

std::string ShadowMapArray::ensure(bool cube, int resolution, DepthFormat format, int layers, int maxTextureSize,
                                   int maxArrayLayers) {
    if (texture_ && cube == cube_ && resolution == resolution_ && format == format_ && layers == layers_) return {};
    const std::string kept = texture_ ? "keeping the " + std::to_string(resolution_) + "² map" : "no shadow map yet";
    if (std::string refusal = shadowResolutionRefusal(resolution, maxTextureSize, kept); !refusal.empty()) return refusal;
    if (layers < 1 || layers > maxArrayLayers)
        return "shadow maps: " + std::to_string(layers) + " layers of " + std::to_string(resolution) +
               "² exceed this GPU's GL_MAX_ARRAY_TEXTURE_LAYERS " + std::to_string(maxArrayLayers) + "; " + kept;

    gl::drainErrors();
    gl::Texture texture = gl::createTexture(cube ? GL_TEXTURE_CUBE_MAP_ARRAY : GL_TEXTURE_2D_ARRAY);
    glTextureStorage3D(texture.id(), 1, depthInternalFormat(format), resolution, resolution, layers);
    // The debug callback also records these; a refused allocation is a user-facing message, not a bug.
    if (std::string error = gl::drainErrors(); !error.empty()) {
        gl::takeDebugErrors();
        return "shadow map " + std::to_string(resolution) + "² " + depthFormatName(format) + " x " +
               std::to_string(layers) + " could not be allocated (" + error + "); " + kept;
    }
    texture_ = std::move(texture);
    cube_ = cube;
    resolution_ = resolution;
    format_ = format;
    layers_ = layers;
    generation_ = nextGeneration();
    return {};
}

std::string ShadowMap::ensure(int resolution, DepthFormat format, int maxTextureSize) {
    if (own_ && own_->valid() && own_->resolution() == resolution && own_->format() == format) return {};
    const std::string kept = texture_ ? "keeping the " + std::to_string(resolution_) + "² map" : "no shadow map yet";
    if (std::string refusal = shadowResolutionRefusal(resolution, maxTextureSize, kept); !refusal.empty()) return refusal;
    auto array = std::make_unique<ShadowMapArray>();
    if (std::string error = array->ensure(false, resolution, format, 1, maxTextureSize, 1); !error.empty()) return error;
    if (std::string error = attach(*array, 0); !error.empty()) return error;
    own_ = std::move(array);
    return {};
}

std::string ShadowMap::attach(const ShadowMapArray& array, int layer) {
    reversedZ_ = array.reversedZ();
    if (texture_ && arrayGeneration_ == array.generation() && layer_ == layer) return {};
    // A view must be a name that was never bound: glGenTextures, not glCreateTextures.
    GLuint id = 0;
    glGenTextures(1, &id);
    gl::Texture view(id);
    glTextureView(view.id(), GL_TEXTURE_2D, array.texture(), depthInternalFormat(array.format()), 0, 1,
                  GLuint(layer), 1);
    gl::Framebuffer framebuffer = gl::createFramebuffer();
    // The pass renders into the array's layer itself, not through the view: NVIDIA's driver mishandles a 2D view
    // of a cube-map-array layer as an attachment and in reads (builtin:room lost part of its pillar's shadow).
    glNamedFramebufferTextureLayer(framebuffer.id(), GL_DEPTH_ATTACHMENT, array.texture(), 0, layer);
    glNamedFramebufferDrawBuffer(framebuffer.id(), GL_NONE);
    glNamedFramebufferReadBuffer(framebuffer.id(), GL_NONE);
    const GLenum status = glCheckNamedFramebufferStatus(framebuffer.id(), GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        return "shadow map framebuffer incomplete (status 0x" + std::to_string(status) + "); keeping the previous map";
    texture_ = std::move(view);
    framebuffer_ = std::move(framebuffer);
    arrayTexture_ = array.texture();
    arrayGeneration_ = array.generation();
    layer_ = layer;
    resolution_ = array.resolution();
    format_ = array.format();
    generation_ = nextGeneration();
    return {};
}

void ShadowSampler::configure(const SamplerSettings& sampler, FilterKind filter) {
    if (!sampler_) sampler_ = gl::createSampler();
    if (state_ && state_->first == sampler && state_->second == filter) return;
    state_ = std::make_pair(sampler, filter);
    const GLuint s = sampler_.id();
    GLint wrap = GL_CLAMP_TO_BORDER;
    switch (sampler.addressMode) {
        case AddressMode::Wrap: wrap = GL_REPEAT; break;
        case AddressMode::ClampToEdge: wrap = GL_CLAMP_TO_EDGE; break;
        case AddressMode::ClampToBorder: wrap = GL_CLAMP_TO_BORDER; break;
    }
    glSamplerParameteri(s, GL_TEXTURE_WRAP_S, wrap);
    glSamplerParameteri(s, GL_TEXTURE_WRAP_T, wrap);
    // The user's border depth means the normal convention's depth (1 = lit outside); reversed-Z stores 1 - it.
    const float depth = conventionBorderDepth(sampler.borderDepth, reversedZ_);
    const float border[4] = {depth, depth, depth, depth};
    glSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, border);
    // Hardware 2x2 and Poisson taps use the comparison's bilinear filter; point and grid PCF compare single texels.
    const bool linear = filterIsBilinear(filter);
    glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, linear ? GL_LINEAR : GL_NEAREST);
    glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, linear ? GL_LINEAR : GL_NEAREST);
    glSamplerParameteri(s, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glSamplerParameteri(s, GL_TEXTURE_COMPARE_FUNC, reversedZ_ ? GL_GEQUAL : GL_LEQUAL);
}

std::vector<float> ShadowMap::readDepth() const { return readDepthRect(0, 0, resolution_, resolution_); }

std::vector<float> ShadowMap::readDepthRect(int x0, int y0, int w, int h) const {
    std::vector<float> depth(std::size_t(std::max(w, 0)) * std::size_t(std::max(h, 0)));
    if (!texture_ || depth.empty()) return depth;
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureSubImage(arrayTexture_, 0, x0, y0, layer_, w, h, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                         GLsizei(depth.size() * sizeof(float)), depth.data());
    return depth;
}

}  // namespace shadowlab
