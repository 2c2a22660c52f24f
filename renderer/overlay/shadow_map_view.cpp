#include "overlay/shadow_map_view.h"

#include "gl/program.h"

#include <algorithm>

namespace shadowlab {

namespace {

constexpr GLuint kDepthUnit = 0;

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
    rangeStale_ = false;
}

std::string ShadowMapView::render(const ShadowMap& map, const LightSpace& light, bool mapRedrawn,
                                  const ShadowMapViewOptions& options, int width, int height) {
    if (!map.valid()) return "no shadow map yet: render a frame first";
    if (options.contrast == DepthContrast::Manual && !(options.manualMin < options.manualMax))
        return "manual contrast: min (" + std::to_string(options.manualMin) + ") must be below max (" +
               std::to_string(options.manualMax) + ")";
    if (std::string error = target_.resize(width, height); !error.empty()) return "shadow map view: " + error;

    const Inputs inputs{options, width, height, map.texture(), map.generation(), light.perspective,
                        light.nearPlane, light.farPlane, light.reversedZ};
    redrawn_ = mapRedrawn || !drawn_ || !(*drawn_ == inputs);
    if (!redrawn_) return {};

    if (mapRedrawn || measuredGeneration_ != map.generation() || measuredReversedZ_ != light.reversedZ)
        rangeStale_ = true;
    const bool linearize = options.linearize && light.perspective;
    ShownDepthRange shown;
    switch (options.contrast) {
        case DepthContrast::Auto: {
            if (rangeStale_) measureWrittenRange(map, light.reversedZ);  // only when the map changed
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
    glBindTextureUnit(kDepthUnit, map.texture());
    glBindSampler(kDepthUnit, rawSampler_.id());
    glBindVertexArray(emptyVertexArray_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glBindSampler(kDepthUnit, 0);
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
