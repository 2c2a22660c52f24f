#include "shadow/moments_pass.h"

#include "gl/gl_errors.h"
#include "gl/program.h"
#include "shading/filters/cube_face_frame.h"
#include "shading/filters/filter_technique.h"
#include "shading/filters/moment_filter.h"
#include "shading/filters/moments_mirror.h"

#include <glm/geometric.hpp>

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
        if (v.rendered || !current) work.push_back({&v, width, v.rendered ? "map re-rendered" : "moments settings changed"});
        current_[v.id] = inputs;
    }
    // A cube's faces are blurred across their edges: a face whose neighbour changed is made again, from its depth.
    for (const MomentsView& v : views) {
        if (!v.group.cube || !storage_.count(v.group)) continue;
        const auto sameCube = [&](const Work& w) { return w.view->group == v.group && w.view->layer / 6 == v.layer / 6; };
        if (std::any_of(work.begin(), work.end(), [&](const Work& w) { return w.view == &v; }) ||
            std::none_of(work.begin(), work.end(), sameCube))
            continue;
        work.push_back({&v, blurTexels(filter, v.texelWorldSize), "a neighbouring face changed"});
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
        reasons.push_back(v.name + " (" + w.why + ")");
        anyBlur = anyBlur || w.blurTexels > 1.0;
        ++lastConverted_;
    }
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    timer.end(TimedPass::Moments);
    result.moments = {true, joined(reasons), timer.latestMilliseconds(TimedPass::Moments)};

    // The mips before the blur: level 1 from the unblurred moments, so that no level mixes the blur's fringe of
    // "no caster" (the far plane) around the casters' outline into a caster's texels (mipViews).
    mipViews(work, format, filter, joined(reasons), timer, result);
    if (!anyBlur) result.blur = {false, "filter.blurWidth is 1 texel: no blur", std::nullopt};
    else blurViews(work, format, filter, joined(reasons), timer, result);
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
        if (r == 0 || w.view->group.cube) continue;
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
    blurCubes(work, format);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    timer.end(TimedPass::Blur);
    char width[64];
    std::snprintf(width, sizeof width, "%g", double(filter.blurWidth));
    result.blur = {true,
                   std::string("filter.blurWidth ") + width +
                       (filter.blurUnit == BlurUnit::World ? " world units" : " texels") + ": " + reasons,
                   timer.latestMilliseconds(TimedPass::Blur)};
}

void MomentsPass::blurCubes(const std::vector<Work>& work, GLenum format) {
    // Each cube once, all its faces converted (run() adds a changed face's neighbours).
    std::vector<std::pair<MapGroup, int>> cubes;
    for (const Work& w : work) {
        const std::pair<MapGroup, int> cube{w.view->group, w.view->layer / 6};
        if (w.view->group.cube && blurWeights(w.blurTexels).size() > 1 &&
            std::find(cubes.begin(), cubes.end(), cube) == cubes.end())
            cubes.push_back(cube);
    }
    if (cubes.empty()) return;
    const std::string imageFormat = std::string("MOMENT_FORMAT ") + imageFormatName(format);
    auto& first = cubeBlurPrograms_[{int(format), 1}];
    auto& second = cubeBlurPrograms_[{int(format), 2}];
    if (!first) first = gl::buildProgram({{GL_COMPUTE_SHADER, "moments_cube_blur.comp.glsl", {}}}, {"FIRST", imageFormat});
    if (!second) second = gl::buildProgram({{GL_COMPUTE_SHADER, "moments_cube_blur.comp.glsl", {}}}, {imageFormat});
    if (!nearest_) {
        nearest_ = gl::createSampler();
        glSamplerParameteri(nearest_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glSamplerParameteri(nearest_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    for (const auto& [group, cube] : cubes) {
        const Storage& s = storage_.at(group);
        if (!tempCube_ || tempCubeResolution_ != s.resolution || tempCubeFormat_ != format) {
            // Two cubes: every face's blur along its frame's s, and along its t (near the edges).
            tempCube_ = gl::createTexture(GL_TEXTURE_CUBE_MAP_ARRAY);
            glTextureStorage3D(tempCube_.id(), 1, format, s.resolution, s.resolution, 12);
            tempCubeResolution_ = s.resolution;
            tempCubeFormat_ = format;
        }
        std::vector<const Work*> faces;
        for (const Work& w : work)
            if (w.view->group == group && w.view->layer / 6 == cube) faces.push_back(&w);
        const GLuint groups = GLuint((s.resolution + 7) / 8);
        const auto setFace = [&](GLuint program, const Work& w) {
            const std::vector<float> weights = blurWeights(w.blurTexels);
            const int r = int(weights.size() / 2);
            const glm::mat3 basis = cubeFaceBasis(w.view->layer % 6);
            glUniformMatrix3fv(glGetUniformLocation(program, "uFace"), 1, GL_FALSE, &basis[0][0]);
            glUniform1fv(glGetUniformLocation(program, "uWeights"), GLsizei(r + 1), weights.data() + r);
            glUniform1i(glGetUniformLocation(program, "uRadius"), r);
            glUniform1i(glGetUniformLocation(program, "uSize"), s.resolution);
            glUniform1i(glGetUniformLocation(program, "uIn"), 0);
        };
        // First pass: the moments (nearest, level 0) -> the temporary cubes. A face's blur along its t is made only
        // where the second pass reads it: a face whose t is the s of a face crossing into it along that face's t.
        const auto frameOf = [](int face) { return cubeFaceFrame(cubeFaceBasis(face)[2], 1.0f); };
        const auto readAlongT = [&](int face) {
            for (int other = 0; other < 6; ++other)
                if (other / 2 != face / 2 && std::abs(glm::dot(frameOf(other).t, cubeFaceBasis(face)[2])) > 0.5f &&
                    std::abs(glm::dot(frameOf(other).s, frameOf(face).t)) > 0.5f)
                    return true;
            return false;
        };
        glUseProgram(first.id());
        glBindTextureUnit(0, s.texture.id());
        glBindSampler(0, nearest_.id());
        glUniform1i(glGetUniformLocation(first.id(), "uCube"), cube);
        for (const Work* w : faces) {
            setFace(first.id(), *w);
            for (int axis = 0; axis < (readAlongT(w->view->layer % 6) ? 2 : 1); ++axis) {
                glUniform1i(glGetUniformLocation(first.id(), "uAxis"), axis);
                glBindImageTexture(0, tempCube_.id(), 0, GL_FALSE, 6 * axis + w->view->layer % 6, GL_WRITE_ONLY, format);
                glDispatchCompute(groups, groups, 1);
            }
        }
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        // Second pass: the temporary cubes -> the moments.
        glUseProgram(second.id());
        glBindTextureUnit(0, tempCube_.id());
        for (const Work* w : faces) {
            setFace(second.id(), *w);
            glBindImageTexture(0, s.texture.id(), 0, GL_FALSE, w->view->layer, GL_WRITE_ONLY, format);
            glDispatchCompute(groups, groups, 1);
        }
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        glBindSampler(0, 0);
        glBindTextureUnit(0, 0);
    }
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
    const glm::vec4 empty = emptyMoments(filter);
    glUniform4fv(glGetUniformLocation(mips.id(), "uEmpty"), 1, &empty.x);
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
