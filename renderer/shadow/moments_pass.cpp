#include "shadow/moments_pass.h"

#include "gl/gl_errors.h"
#include "gl/program.h"
#include "shading/filters/filter_technique.h"
#include "shading/filters/moment_filter.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>

namespace shadowlab {

namespace {

std::uint64_t nextStorageGeneration() {
    static std::uint64_t generation = 0;
    return ++generation;
}

// The GL formats of the names momentImageFormat chooses (shading/filters/moment_filter.h).
struct NamedFormat {
    const char* name;
    GLenum format;
};
constexpr NamedFormat kMomentFormats[] = {
    {"rg16f", GL_RG16F}, {"rg32f", GL_RG32F}, {"rgba16f", GL_RGBA16F}, {"rgba16", GL_RGBA16}, {"rgba32f", GL_RGBA32F}};

const char* imageFormatName(GLenum format) {
    for (const NamedFormat& f : kMomentFormats)
        if (f.format == format) return f.name;
    return "rgba32f";
}

std::string joined(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
    return out;
}

}  // namespace

GLenum momentInternalFormat(const FilterTechnique& technique, int momentBits) {
    const std::string name = momentImageFormat(technique, momentBits);
    for (const NamedFormat& f : kMomentFormats)
        if (name == f.name) return f.format;
    return GL_RGBA32F;
}

struct MomentsPass::Storage {
    gl::Texture texture;    // GL_TEXTURE_2D_ARRAY or GL_TEXTURE_CUBE_MAP_ARRAY of moments
    gl::Texture depthView;  // the depth array seen as 2D layers (a cube-map array's faces too), for texelFetch
    GLuint depthTexture = 0;
    std::uint64_t depthGeneration = 0;
    GLenum format = 0;
    int resolution = 0, layers = 0, levels = 1;
    std::uint64_t generation = 0;
};

MomentsPass::MomentsPass() = default;
MomentsPass::~MomentsPass() = default;

void MomentsPass::release() {
    storage_.clear();
    current_.clear();
    temp_.reset();
    tempResolution_ = 0;
}

GLuint MomentsPass::texture(const MapGroup& group) const {
    const auto it = storage_.find(group);
    return it == storage_.end() ? 0 : it->second.texture.id();
}

MomentsLayer MomentsPass::layer(const MapGroup& group, int layer) const {
    const auto it = storage_.find(group);
    if (it == storage_.end() || !it->second.texture) return {};
    const Storage& s = it->second;
    return {s.texture.id(), s.format, layer, s.resolution, s.generation};
}

void MomentsPass::configureSampler(const FilterSettings& filter, const SamplerSettings& settings) {
    if (!sampler_) sampler_ = gl::createSampler();
    const GLuint s = sampler_.id();
    GLint wrap = GL_CLAMP_TO_BORDER;
    if (settings.addressMode == AddressMode::Wrap) wrap = GL_REPEAT;
    if (settings.addressMode == AddressMode::ClampToEdge) wrap = GL_CLAMP_TO_EDGE;
    glSamplerParameteri(s, GL_TEXTURE_WRAP_S, wrap);
    glSamplerParameteri(s, GL_TEXTURE_WRAP_T, wrap);
    // With mips the lookup picks the level itself (textureLod): trilinear between the two around it.
    glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, filter.momentMips ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    // Outside the map: the moments of the border depth (sampler.borderDepth, in the near-0 convention moments use).
    const MomentTechnique& m = *filterTechnique(filter.kind).moments;
    const glm::vec4 border = m.encode(settings.borderDepth, m.uniforms(filter));
    glSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, &border.x);
}

MomentsPassResult MomentsPass::run(const FilterSettings& filter, const std::map<MapGroup, ShadowMapArray>& arrays,
                                   const std::vector<MomentsView>& views, PassTimer& timer) {
    MomentsPassResult result;
    lastConverted_ = 0;
    const FilterTechnique& technique = filterTechnique(filter.kind);
    const MomentTechnique& m = *technique.moments;
    if (m.clamps) result.warnings = m.clamps(filter);
    const GLenum format = momentInternalFormat(technique, filter.momentBits);
    const glm::vec4 uniforms = m.uniforms(filter);

    // Storage: one moments array per depth array, the same size and layers; unused groups are freed.
    for (auto it = storage_.begin(); it != storage_.end();)
        it = arrays.count(it->first) ? std::next(it) : storage_.erase(it);
    for (const auto& [group, array] : arrays) {
        Storage& s = storage_[group];
        const int levels = momentLevels(array.resolution(), filter.momentMips);
        if (!s.texture || s.format != format || s.resolution != array.resolution() || s.layers != array.layers() ||
            s.levels != levels) {
            gl::Texture texture = gl::createTexture(group.cube ? GL_TEXTURE_CUBE_MAP_ARRAY : GL_TEXTURE_2D_ARRAY);
            glTextureStorage3D(texture.id(), levels, format, array.resolution(), array.resolution(), array.layers());
            s.levels = levels;
            s.texture = std::move(texture);
            s.format = format;
            s.resolution = array.resolution();
            s.layers = array.layers();
            s.generation = nextStorageGeneration();
        }
        if (!s.depthView || s.depthTexture != array.texture() || s.depthGeneration != array.generation()) {
            GLuint id = 0;
            glGenTextures(1, &id);  // a view needs a name that was never bound
            gl::Texture view(id);
            glTextureView(view.id(), GL_TEXTURE_2D_ARRAY, array.texture(), depthInternalFormat(array.format()), 0, 1, 0,
                          GLuint(array.layers()));
            s.depthView = std::move(view);
            s.depthTexture = array.texture();
            s.depthGeneration = array.generation();
        }
    }

    // Which views need new moments: drawn this frame, or computed from other settings or storage.
    std::vector<Work> work;
    std::vector<std::string> clampedBlur;
    for (const MomentsView& v : views) {
        const auto s = storage_.find(v.group);
        if (s == storage_.end()) continue;
        bool clamped = false;
        const double width = blurTexels(filter, v.texelWorldSize, &clamped);
        if (clamped) clampedBlur.push_back(v.name);
        const Inputs inputs{filter.kind,  filter.momentBits, width,       uniforms,   s->second.generation,
                            v.layer,      filter.momentMips, v.perspective, v.nearPlane, v.farPlane};
        const auto it = current_.find(v.id);
        const bool current = it != current_.end() && it->second == inputs;
        if (v.rendered || !current) work.push_back({&v, width, !current && !v.rendered});
        current_[v.id] = inputs;
    }
    if (!clampedBlur.empty())
        result.warnings.push_back("filter.blurWidth: wider than " + std::to_string(int(kMaxBlurTexels)) +
                                  " texels in " + joined(clampedBlur) + "; " + std::to_string(int(kMaxBlurTexels)) +
                                  " texels are used");
    if (work.empty()) {
        result.moments = {false, "no view was re-rendered and the moments settings are unchanged", std::nullopt};
        result.blur = result.mips = {false, result.moments.reason, std::nullopt};
        return result;
    }

    // Programs: the conversion per technique and storage, the blur per storage format.
    auto& convert = convertPrograms_[{filter.kind, int(format)}];
    if (!convert)
        convert = gl::buildProgram({{GL_COMPUTE_SHADER, "moments.comp.glsl", {}}},
                                   {"CONVERT", std::string("MOMENT_FORMAT ") + imageFormatName(format)},
                                   {{"alias:technique", m.glslFile}});

    std::vector<std::string> reasons;
    bool anyBlur = false;
    timer.begin(TimedPass::Moments);
    glUseProgram(convert.id());
    glUniform4fv(glGetUniformLocation(convert.id(), "uTechnique"), 1, &uniforms.x);
    glUniform1i(glGetUniformLocation(convert.id(), "uDepth"), 0);
    for (const Work& w : work) {
        const MomentsView& v = *w.view;
        const Storage& s = storage_.at(v.group);
        glBindTextureUnit(0, s.depthView.id());
        glBindSampler(0, 0);
        glUniform1i(glGetUniformLocation(convert.id(), "uLayer"), v.layer);
        glUniform1i(glGetUniformLocation(convert.id(), "uReversedZ"), v.group.reversedZ ? 1 : 0);
        glUniform1i(glGetUniformLocation(convert.id(), "uPerspective"), v.perspective ? 1 : 0);
        glUniform2f(glGetUniformLocation(convert.id(), "uNearFar"), v.nearPlane, v.farPlane);
        glUniform1i(glGetUniformLocation(convert.id(), "uSize"), s.resolution);
        glBindImageTexture(0, s.texture.id(), 0, GL_FALSE, v.layer, GL_WRITE_ONLY, format);
        glDispatchCompute(GLuint((s.resolution + 7) / 8), GLuint((s.resolution + 7) / 8), 1);
        reasons.push_back(v.name + (w.settingsChanged ? " (moments settings changed)" : " (map re-rendered)"));
        anyBlur = anyBlur || w.blurTexels > 1.0;
        ++lastConverted_;
    }
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    timer.end(TimedPass::Moments);
    result.moments = {true, joined(reasons), timer.latestMilliseconds(TimedPass::Moments)};

    if (!anyBlur) result.blur = {false, "filter.blurWidth is 1 texel: no blur", std::nullopt};
    else blurViews(work, format, filter, joined(reasons), timer, result);
    mipViews(work, format, filter, joined(reasons), timer, result);
    glUseProgram(0);
    return result;
}

void MomentsPass::blurViews(const std::vector<Work>& work, GLenum format, const FilterSettings& filter,
                            const std::string& reasons, PassTimer& timer, MomentsPassResult& result) {
    auto& blur = blurPrograms_[int(format)];
    if (!blur) blur = gl::buildProgram({{GL_COMPUTE_SHADER, "moments.comp.glsl", {}}},
                                       {std::string("MOMENT_FORMAT ") + imageFormatName(format)});
    timer.begin(TimedPass::Blur);
    glUseProgram(blur.id());
    for (const Work& w : work) {
        const std::vector<float> weights = blurWeights(w.blurTexels);
        const int r = int(weights.size() / 2);
        if (r == 0) continue;
        const MomentsView& v = *w.view;
        const Storage& s = storage_.at(v.group);
        if (!temp_ || tempResolution_ != s.resolution || tempFormat_ != format) {
            temp_ = gl::createTexture(GL_TEXTURE_2D);
            glTextureStorage2D(temp_.id(), 1, format, s.resolution, s.resolution);
            tempResolution_ = s.resolution;
            tempFormat_ = format;
        }
        glUniform1fv(glGetUniformLocation(blur.id(), "uWeights"), GLsizei(r + 1), weights.data() + r);
        glUniform1i(glGetUniformLocation(blur.id(), "uRadius"), r);
        glUniform1i(glGetUniformLocation(blur.id(), "uSize"), s.resolution);
        const GLuint groups = GLuint((s.resolution + 7) / 8);
        // Horizontal: the layer into the temporary; vertical: back into the layer.
        glBindImageTexture(1, s.texture.id(), 0, GL_FALSE, v.layer, GL_READ_ONLY, format);
        glBindImageTexture(0, temp_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
        glUniform2i(glGetUniformLocation(blur.id(), "uDirection"), 1, 0);
        glDispatchCompute(groups, groups, 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        glBindImageTexture(1, temp_.id(), 0, GL_FALSE, 0, GL_READ_ONLY, format);
        glBindImageTexture(0, s.texture.id(), 0, GL_FALSE, v.layer, GL_WRITE_ONLY, format);
        glUniform2i(glGetUniformLocation(blur.id(), "uDirection"), 0, 1);
        glDispatchCompute(groups, groups, 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    timer.end(TimedPass::Blur);
    char width[64];
    std::snprintf(width, sizeof width, "%g", double(filter.blurWidth));
    result.blur = {true,
                   std::string("filter.blurWidth ") + width +
                       (filter.blurUnit == BlurUnit::World ? " world units" : " texels") + ": " + reasons,
                   timer.latestMilliseconds(TimedPass::Blur)};
}

void MomentsPass::mipViews(const std::vector<Work>& work, GLenum format, const FilterSettings& filter,
                           const std::string& reasons, PassTimer& timer, MomentsPassResult& result) {
    if (!filter.momentMips) {
        result.mips = {false, "filter.momentMips is off", std::nullopt};
        return;
    }
    auto& mips = mipsPrograms_[int(format)];
    if (!mips) mips = gl::buildProgram({{GL_COMPUTE_SHADER, "moments.comp.glsl", {}}},
                                       {"MIPS", std::string("MOMENT_FORMAT ") + imageFormatName(format)});
    timer.begin(TimedPass::Mips);
    glUseProgram(mips.id());
    int levels = 1;
    for (const Work& w : work) {
        const Storage& s = storage_.at(w.view->group);
        levels = s.levels;
        // Each level from the blurred one below it, written after the level below is complete.
        for (int level = 1; level < s.levels; ++level) {
            const int size = std::max(s.resolution >> level, 1);
            glUniform1i(glGetUniformLocation(mips.id(), "uSize"), size);
            glBindImageTexture(1, s.texture.id(), level - 1, GL_FALSE, w.view->layer, GL_READ_ONLY, format);
            glBindImageTexture(0, s.texture.id(), level, GL_FALSE, w.view->layer, GL_WRITE_ONLY, format);
            glDispatchCompute(GLuint((size + 7) / 8), GLuint((size + 7) / 8), 1);
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        }
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    timer.end(TimedPass::Mips);
    result.mips = {true, std::to_string(levels - 1) + " levels below the map: " + reasons,
                   timer.latestMilliseconds(TimedPass::Mips)};
}

std::vector<glm::vec4> MomentsPass::read(const MapGroup& group, int layer, int x0, int y0, int w, int h,
                                         int level) const {
    std::vector<glm::vec4> texels(std::size_t(std::max(w, 0)) * std::size_t(std::max(h, 0)));
    const auto it = storage_.find(group);
    if (it == storage_.end() || texels.empty()) return texels;
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureSubImage(it->second.texture.id(), level, x0, y0, layer, w, h, 1, GL_RGBA, GL_FLOAT,
                         GLsizei(texels.size() * sizeof(glm::vec4)), texels.data());
    return texels;
}

}  // namespace shadowlab
