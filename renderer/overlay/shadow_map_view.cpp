#include "overlay/shadow_map_view.h"

#include "gl/program.h"

#include <algorithm>

namespace shadowlab {

namespace {

constexpr GLuint kViewerDepthUnit = 0;
constexpr GLuint kMomentsUnit = 1;

int momentChannels(GLenum format) { return format == GL_RG16F || format == GL_RG32F ? 2 : 4; }

bool sameLayer(const MomentsLayer& a, const MomentsLayer& b) {
    return a.texture == b.texture && a.layer == b.layer && a.generation == b.generation;
}

}  // namespace

double linearLightDepth(const LightSpace& light, double storedDepth) {
    if (!light.perspective) return storedDepth;
    const double n = light.nearPlane, f = light.farPlane;
    const double zNdc = storedDepth * 2.0 - 1.0;
    const double viewDepth = 2.0 * n * f / (f + n - zNdc * (f - n));
    return (viewDepth - n) / (f - n);
}

ShadowMapView::ShadowMapView()
    : displayProgram_(gl::buildProgram({{GL_VERTEX_SHADER, "shadow_map_view.vert.glsl"},
                                        {GL_FRAGMENT_SHADER, "shadow_map_view.frag.glsl"}},
                                       {})),
      emptyVertexArray_(gl::createVertexArray()),
      rawSampler_(gl::createSampler()) {
    glSamplerParameteri(rawSampler_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(rawSampler_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(rawSampler_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(rawSampler_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(rawSampler_.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
    const GLuint program = displayProgram_.id();
    uniforms_.uvMin = glGetUniformLocation(program, "uUvMin");
    uniforms_.uvMax = glGetUniformLocation(program, "uUvMax");
    uniforms_.viewSize = glGetUniformLocation(program, "uViewSize");
    uniforms_.range = glGetUniformLocation(program, "uRange");
    uniforms_.linearize = glGetUniformLocation(program, "uLinearize");
    uniforms_.nearFar = glGetUniformLocation(program, "uNearFar");
    uniforms_.gridTexelPixels = glGetUniformLocation(program, "uGridTexelPixels");
    uniforms_.reversedZ = glGetUniformLocation(program, "uReversedZ");
    uniforms_.channel = glGetUniformLocation(program, "uChannel");
}

void ShadowMapView::measureWrittenRange(const ShadowMap& map, bool reversedZ) {
    rangeReduction_.dispatch(map.texture(), map.resolution(), map.resolution(), reversedZ);
    if (const std::optional<WrittenDepths> written = rangeReduction_.read()) {
        writtenMin_ = written->min;
        writtenMax_ = written->max;
    } else {
        writtenMin_.reset();
        writtenMax_.reset();
    }
    measuredGeneration_ = map.generation();
    measuredReversedZ_ = reversedZ;
    measuredChannel_ = 0;
    rangeStale_ = false;
}

void ShadowMapView::measureChannelRange(int channel) {
    rangeReduction_.dispatch(momentsView_.id(), momentsViewOf_.resolution, momentsViewOf_.resolution, false,
                             channel - 1);
    if (const std::optional<WrittenDepths> range = rangeReduction_.read()) {
        writtenMin_ = range->min;
        writtenMax_ = range->max;
    } else {
        writtenMin_.reset();
        writtenMax_.reset();
    }
    measuredChannel_ = channel;
    measuredMoments_ = momentsViewOf_;
    rangeStale_ = false;
}

void ShadowMapView::viewMomentsLayer(const MomentsLayer& layer) {
    if (momentsView_ && sameLayer(momentsViewOf_, layer)) return;
    GLuint id = 0;
    glGenTextures(1, &id);  // a view needs a name that was never bound
    gl::Texture view(id);
    glTextureView(view.id(), GL_TEXTURE_2D, layer.texture, layer.format, 0, 1, GLuint(layer.layer), 1);
    momentsView_ = std::move(view);
    momentsViewOf_ = layer;
}

std::string ShadowMapView::render(const ShadowMap& map, const LightSpace& light, bool mapRedrawn,
                                  const ShadowMapViewOptions& options, int width, int height,
                                  const MomentsLayer* moments) {
    if (!map.valid()) return "no shadow map yet: render a frame first";
    const int channel = options.channel;
    if (channel > 0) {
        if (!moments || !moments->texture)
            return "moment " + std::to_string(channel) + ": the frame's filter stores no moments (filter.kind is a "
                   "depth technique)";
        if (channel > momentChannels(moments->format))
            return "moment " + std::to_string(channel) + ": this technique stores " +
                   std::to_string(momentChannels(moments->format)) + " moments";
        viewMomentsLayer(*moments);
    }
    if (options.contrast == DepthContrast::Manual && !(options.manualMin < options.manualMax))
        return "manual contrast: min (" + std::to_string(options.manualMin) + ") must be below max (" +
               std::to_string(options.manualMax) + ")";
    if (std::string error = target_.resize(width, height); !error.empty()) return "shadow map view: " + error;

    const MomentsLayer shownMoments = channel > 0 ? *moments : MomentsLayer{};
    const Inputs inputs{options,          width,           height,          map.texture(),
                        map.generation(), light.perspective, light.nearPlane, light.farPlane,
                        light.reversedZ,  shownMoments.texture, shownMoments.layer, shownMoments.generation};
    redrawn_ = mapRedrawn || !drawn_ || !(*drawn_ == inputs);
    if (!redrawn_) return {};

    if (mapRedrawn || measuredGeneration_ != map.generation() || measuredReversedZ_ != light.reversedZ ||
        measuredChannel_ != channel || (channel > 0 && !sameLayer(measuredMoments_, shownMoments)))
        rangeStale_ = true;
    const bool linearize = options.linearize && light.perspective && channel == 0;
    ShownDepthRange shown;
    switch (options.contrast) {
        case DepthContrast::Auto: {
            if (rangeStale_) {  // only when the map changed
                if (channel > 0)
                    measureChannelRange(channel);
                else
                    measureWrittenRange(map, light.reversedZ);
            }
            shown.anyCaster = writtenMin_.has_value();
            if (shown.anyCaster) {
                shown.min = float(linearize ? linearLightDepth(light, *writtenMin_) : *writtenMin_);
                shown.max = float(linearize ? linearLightDepth(light, *writtenMax_) : *writtenMax_);
            }
            // A flat map (one depth everywhere) still shows mid grey rather than dividing by zero.
            if (shown.max <= shown.min) shown.max = shown.min + 1e-6f;
            break;
        }
        case DepthContrast::Full: shown = {0.0f, 1.0f, false}; break;
        case DepthContrast::Manual: shown = {options.manualMin, options.manualMax, false}; break;
    }

    const double pixelsPerTexel = texelPixels(options.visible, width, map.resolution());
    gridShown_ = options.texelGrid && pixelsPerTexel >= kGridMinTexelPixels;

    const DisplayUniforms& u = uniforms_;
    glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer());
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glUseProgram(displayProgram_.id());
    glUniform2f(u.uvMin, float(options.visible.min.x), float(options.visible.min.y));
    glUniform2f(u.uvMax, float(options.visible.max.x), float(options.visible.max.y));
    glUniform2f(u.viewSize, float(width), float(height));
    glUniform2f(u.range, shown.min, shown.max);
    glUniform1i(u.linearize, linearize ? 1 : 0);
    glUniform2f(u.nearFar, float(light.nearPlane), float(light.farPlane));
    glUniform1i(u.reversedZ, light.reversedZ ? 1 : 0);
    glUniform1f(u.gridTexelPixels, gridShown_ ? float(pixelsPerTexel) : 0.0f);
    glUniform1i(u.channel, channel);
    glBindTextureUnit(kViewerDepthUnit, map.texture());
    glBindSampler(kViewerDepthUnit, rawSampler_.id());
    if (channel > 0) {
        glBindTextureUnit(kMomentsUnit, momentsView_.id());
        glBindSampler(kMomentsUnit, rawSampler_.id());
    }
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindSampler(kViewerDepthUnit, 0);
    glBindSampler(kMomentsUnit, 0);
    glBindTextureUnit(kMomentsUnit, 0);
    glUseProgram(0);
    glEnable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    shown_ = shown;
    drawn_ = inputs;
    return {};
}

std::optional<float> ShadowMapView::depthAt(const ShadowMap& map, int texelX, int texelY) const {
    if (!map.valid() || texelX < 0 || texelY < 0 || texelX >= map.resolution() || texelY >= map.resolution())
        return std::nullopt;
    return map.readDepthRect(texelX, texelY, 1, 1)[0];
}

}  // namespace shadowlab
