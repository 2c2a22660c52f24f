#include "frame/face_culling.h"

#include "gl/gl.h"

namespace shadowlab {

namespace {

FaceCullState cullState(bool enabled, bool front, bool clockwise) { return {enabled, enabled && front, clockwise}; }

bool doubleSided(const Material* material) { return material && material->doubleSided; }

}  // namespace

FaceCullState viewFaceCullState(const Material* material, bool mirrored) {
    // The winding stays part of the state with culling off: main.frag.glsl reads gl_FrontFacing.
    return cullState(!doubleSided(material), false, mirrored);
}

FaceCullState shadowFaceCullState(CullMode mode, const Material* material, bool mirrored) {
    // No shadow-pass shader reads gl_FrontFacing: with culling off the winding changes nothing, so mirrored and
    // plain draws share the state (and a multi-draw call).
    const bool culls = shadowPassCullsAny(mode, doubleSided(material));
    return cullState(culls, mode == CullMode::Front, culls && mirrored);
}

void applyFaceCulling(const FaceCullState& state) {
    if (state.cull) {
        glEnable(GL_CULL_FACE);
        glCullFace(state.cullFront ? GL_FRONT : GL_BACK);
    } else {
        glDisable(GL_CULL_FACE);
    }
    glFrontFace(state.clockwise ? GL_CW : GL_CCW);
}

void applyViewFaceCulling(const Material* material, bool mirrored) {
    applyFaceCulling(viewFaceCullState(material, mirrored));
}

void applyShadowFaceCulling(CullMode mode, const Material* material, bool mirrored) {
    applyFaceCulling(shadowFaceCullState(mode, material, mirrored));
}

void resetFaceCulling() {
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
}

}  // namespace shadowlab
