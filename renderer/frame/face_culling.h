#pragma once
// The one rule for which faces each pass draws (glTF 2.0, "doubleSided"):
//  - the view (main pass and G-buffer): back faces of single-sided materials are not drawn; double-sided ones are
//    drawn from both sides. A draw without a material uses glTF's default material, which is single-sided.
//  - the shadow pass: shadow.cullMode decides what the map holds; double-sided materials are never culled (they
//    cast from both faces).
// Mirrored instances (negative determinant) reverse the winding in world space, so their front face is clockwise.
// The reference (Embree) keeps every triangle as an occluder: that is the physical truth the passes are judged by.
#include "scene/scene.h"
#include "settings/settings.h"

namespace shadowlab {

// The shadow pass's rule without GL, so the reference's cause rays apply the same one: cullMode none and
// double-sided materials keep every face; otherwise back culling drops the faces whose front (counter-clockwise,
// clockwise for mirrored instances) looks away from the light, front culling those that look toward it.
inline bool shadowPassCullsAny(CullMode mode, bool doubleSided) { return mode != CullMode::None && !doubleSided; }
inline bool shadowPassCulls(CullMode mode, bool doubleSided, bool frontFacesLight) {
    return shadowPassCullsAny(mode, doubleSided) && (mode == CullMode::Back ? !frontFacesLight : frontFacesLight);
}

// The GL face-culling state a draw needs, as a value: draws with equal states can share one multi-draw call
// (frame/draw_batches.h).
struct FaceCullState {
    bool cull = false;
    bool cullFront = false;  // glCullFace(GL_FRONT), else GL_BACK
    bool clockwise = false;  // glFrontFace(GL_CW): a mirrored instance's front faces
    int key() const { return int(cull) | int(cullFront) << 1 | int(clockwise) << 2; }  // 0..7, distinct per state
};
FaceCullState viewFaceCullState(const Material* material, bool mirrored);
FaceCullState shadowFaceCullState(CullMode mode, const Material* material, bool mirrored);
void applyFaceCulling(const FaceCullState& state);

// Sets GL_CULL_FACE, glCullFace and glFrontFace for one draw of the main pass or the G-buffer.
void applyViewFaceCulling(const Material* material, bool mirrored);

// Sets GL_CULL_FACE, glCullFace and glFrontFace for one draw of the shadow pass.
void applyShadowFaceCulling(CullMode mode, const Material* material, bool mirrored);

// Restores the GL defaults the passes assume between draws: culling off, counter-clockwise front faces.
void resetFaceCulling();

}  // namespace shadowlab
