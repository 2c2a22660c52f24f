#include "frame/depth_casters.h"

#include "gl/program.h"

#include <glm/gtc/type_ptr.hpp>

#include <set>

namespace shadowlab {

DepthCasters::Program::Program(gl::Program built) : program(std::move(built)) {
    const GLuint p = program.id();
    viewProjection = glGetUniformLocation(p, "uLightViewProjection");
    uvTransform = glGetUniformLocation(p, "uUvTransform");
    alphaFactor = glGetUniformLocation(p, "uAlphaFactor");
    alphaCutoff = glGetUniformLocation(p, "uAlphaCutoff");
    baseColor = glGetUniformLocation(p, "uBaseColorTexture");
    bindDrawTransformsBlock(p);
}

DepthCasters::DepthCasters() : opaque_(gl::buildProgram({{GL_VERTEX_SHADER, "shadow_depth.vert.glsl"}}, {})) {}

const DepthCasters::Program& DepthCasters::alphaProgram(bool textured) {
    std::optional<Program>& p = textured ? alphaTextured_ : alphaFactor_;
    if (!p) {
        std::vector<std::string> defines{"ALPHA_MASK"};
        if (textured) defines.push_back("BASE_COLOR_TEXTURE");
        p.emplace(gl::buildProgram(
            {{GL_VERTEX_SHADER, "shadow_depth.vert.glsl"}, {GL_FRAGMENT_SHADER, "shadow_alpha.frag.glsl"}}, defines));
    }
    return *p;
}

DepthCastersDrawn DepthCasters::draw(const GpuScene& scene, const std::vector<std::uint32_t>& draws,
                                     const glm::mat4& viewProjection,
                                     const std::function<FaceCullState(const Material*, bool mirrored)>& cullOf) {
    const Scene& model = scene.scene();
    const std::vector<GpuDraw>& all = scene.draws();
    auto materialOf = [&](const GpuDraw& draw) {
        return draw.material >= 0 ? &model.materials[std::size_t(draw.material)] : nullptr;
    };
    auto masked = [](const Material* material) { return material && material->alphaMode == AlphaMode::Mask; };
    DepthCastersDrawn drawn;
    for (std::uint32_t d : draws) {
        drawn.triangles += std::size_t(all[d].indexCount / 3);
        drawn.alphaTested += masked(materialOf(all[d]));
    }
    // A group's key: its cull state (0..7), and for alpha-tested draws their material (uniforms and texture).
    const std::vector<DrawBatch>& batches = batches_.build(scene, draws, [&](std::uint32_t d) {
        const Material* material = materialOf(all[d]);
        const std::uint64_t cull = std::uint64_t(cullOf(material, all[d].mirrored).key());
        return masked(material) ? (std::uint64_t(all[d].material) + 1) << 3 | cull : cull;
    });
    std::set<GLuint> prepared;  // programs whose per-pass uniforms are set
    scene.bind();
    for (const DrawBatch& batch : batches) {
        const GpuDraw& first = all[batch.firstDraw];
        const Material* material = materialOf(first);
        const bool alpha = masked(material);
        const GLuint texture = alpha ? scene.materialTexture(first.material) : 0;
        const Program& p = alpha ? alphaProgram(texture != 0) : opaque_;
        glUseProgram(p.program.id());
        if (prepared.insert(p.program.id()).second) {
            glUniformMatrix4fv(p.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProjection));
            glUniform1i(p.baseColor, 1);
        }
        if (alpha) {
            glUniformMatrix3fv(p.uvTransform, 1, GL_FALSE, glm::value_ptr(material->uvTransform));
            glUniform1f(p.alphaFactor, material->baseColorFactor.a);
            glUniform1f(p.alphaCutoff, material->alphaCutoff);
            if (texture) glBindTextureUnit(1, texture);
        }
        applyFaceCulling(cullOf(material, first.mirrored));
        batches_.draw(batch);
        ++drawn.drawCalls;
    }
    resetFaceCulling();
    return drawn;
}

}  // namespace shadowlab
