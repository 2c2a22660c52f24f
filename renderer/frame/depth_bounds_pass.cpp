#include "frame/depth_bounds_pass.h"

#include "views/depth_bounds.h"

#include <numeric>

namespace shadowlab {

DepthBoundsPass::DepthBoundsPass() = default;

void DepthBoundsPass::drawDepth(const GpuScene& scene, const glm::dmat4& viewProjection, RenderTarget& target) {
    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
    glViewport(0, 0, target.width(), target.height());
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    // Every draw, casting or not: what the camera sees is what receives.
    std::vector<std::uint32_t> all(scene.draws().size());
    std::iota(all.begin(), all.end(), 0u);
    casters_.draw(scene, all, glm::mat4(viewProjection), viewFaceCullState);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glUseProgram(0);
}

ViewDepths DepthBoundsPass::toViewDepths(const std::optional<WrittenDepths>& written,
                                         const glm::dmat4& projection) const {
    if (!written) return {1.0, 0.0};  // nothing drawn: farthest < nearest says "nothing seen"
    return {viewDepthOfWindowDepth(projection, written->min), viewDepthOfWindowDepth(projection, written->max)};
}

ViewDepths DepthBoundsPass::measureNow(const GpuScene& scene, const glm::dmat4& viewProjection,
                                       const glm::dmat4& projection, RenderTarget& target) {
    drawDepth(scene, viewProjection, target);
    reduction_.dispatch(target.depthTexture(), target.width(), target.height(), false);
    return toViewDepths(reduction_.read(), projection);
}

void DepthBoundsPass::reduceMainDepth(const glm::dmat4& projection, RenderTarget& target) {
    reduction_.dispatch(target.depthTexture(), target.width(), target.height(), false);
    pendingProjection_ = projection;
}

std::optional<ViewDepths> DepthBoundsPass::collect() {
    if (!reduction_.pending()) return std::nullopt;
    return toViewDepths(reduction_.read(), pendingProjection_);
}

}  // namespace shadowlab
