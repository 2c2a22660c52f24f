#include "frame/face_culling.h"

#include "gl/gl.h"

namespace shadowlab {

namespace {

void cull(bool enabled, GLenum face, bool mirrored) {
    if (enabled) {
        glEnable(GL_CULL_FACE);
        glCullFace(face);
    } else {
        glDisable(GL_CULL_FACE);
    }
    glFrontFace(mirrored ? GL_CW : GL_CCW);
}

bool doubleSided(const Material* material) { return material && material->doubleSided; }

}  // namespace

void applyViewFaceCulling(const Material* material, bool mirrored) {
    cull(!doubleSided(material), GL_BACK, mirrored);
}

void applyShadowFaceCulling(CullMode mode, const Material* material, bool mirrored) {
    cull(shadowPassCullsAny(mode, doubleSided(material)), mode == CullMode::Front ? GL_FRONT : GL_BACK, mirrored);
}

void resetFaceCulling() {
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
}

}  // namespace shadowlab
