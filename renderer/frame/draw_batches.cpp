#include "frame/draw_batches.h"

#include <algorithm>

namespace shadowlab {

namespace {

// GL 4.5's DrawElementsIndirectCommand.
struct DrawElementsIndirectCommand {
    GLuint count;
    GLuint instanceCount;
    GLuint firstIndex;
    GLint baseVertex;
    GLuint baseInstance;
};

}  // namespace

DrawBatches::DrawBatches() : commands_(gl::createBuffer()) {}

const std::vector<DrawBatch>& DrawBatches::build(const GpuScene& scene, const std::vector<std::uint32_t>& draws,
                                                 const std::function<std::uint64_t(std::uint32_t)>& keyOf) {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
    keyed.reserve(draws.size());
    for (std::uint32_t d : draws) keyed.emplace_back(keyOf(d), d);
    std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<DrawElementsIndirectCommand> commands;
    commands.reserve(keyed.size());
    batches_.clear();
    for (const auto& [key, d] : keyed) {
        if (batches_.empty() || batches_.back().key != key)
            batches_.push_back({key, d, 0, commands.size() * sizeof(DrawElementsIndirectCommand)});
        ++batches_.back().commands;
        const GpuDraw& draw = scene.draws()[d];
        commands.push_back({GLuint(draw.indexCount), 1, GLuint(draw.firstIndexByte / sizeof(std::uint32_t)),
                            draw.baseVertex, d});
    }
    // A fresh store each build (the driver orphans the old one while earlier draws still read it).
    if (!commands.empty())
        glNamedBufferData(commands_.id(), GLsizeiptr(commands.size() * sizeof(DrawElementsIndirectCommand)),
                          commands.data(), GL_STREAM_DRAW);
    return batches_;
}

void DrawBatches::draw(const DrawBatch& batch) const {
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands_.id());
    glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, reinterpret_cast<const void*>(batch.offset),
                                batch.commands, 0);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
}

}  // namespace shadowlab
