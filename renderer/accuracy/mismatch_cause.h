#pragma once
// Why a pixel's shadow is wrong (DESIGN.md, "cause"): one cause per mismatched pixel, decided from the exact
// reference's rays (what the shadow pass would hold in front of the receiver: nearest face toward the light under the
// shadow pass's culling and alpha rules), the receiver's and that caster's light-space depths, and the map's bounds.
// The table below is the one source of each cause's name, JSON key, colour in the overlay and remedy.
#include "light/light_space.h"
#include "views/shadow_view.h"
#include "reference/embree_scene.h"
#include "reference/visibility.h"
#include "settings/settings.h"

#include <array>
#include <cstdint>

namespace shadowlab {

enum class MismatchCause : std::uint8_t {
    None,           // not mismatched
    SelfShadowing,  // a truly lit receiver shadows itself: bias below its own depth slope (acne)
    BiasOverGap,    // the map holds the caster, but the bias pushed it behind the receiver (Peter Panning)
    CasterCulled,   // every occluder on the ray is a face the shadow pass culls (single-sided back face, cullMode)
    OutsideVolume,  // outside the light's volume (point light: beyond its range / far plane): the border policy decides S
    NearPlaneClip,  // the caster lies before the light's near plane and depth clamp is off
    AlphaTest,      // the map's alpha test and the exact one disagree (a MASK face on the ray)
    NearEdge,       // within k texels of a true shadow boundary: resolution / filter blur
};
inline constexpr std::size_t kCauseCount = 8;  // including None

struct CauseInfo {
    const char* key;     // JSON key, e.g. "casterCulled"
    const char* name;    // for people, e.g. "caster culled"
    const char* remedy;  // one line, naming the preset key that helps
    std::uint8_t red, green, blue;  // overlay colour
};

const CauseInfo& causeInfo(MismatchCause cause);
// Every real cause (None excluded), in the order reports list them.
const std::array<MismatchCause, kCauseCount - 1>& allCauses();

// What decideCause needs besides the pixel.
struct CauseContext {
    const EmbreeScene* bvh = nullptr;
    ReferenceLight light;        // render-origin-relative
    LightSpace lightSpace;       // the tool's light space (map bounds, near plane)
    std::vector<ShadowView> cascades;  // a cascaded light's cascades: the one holding the pixel is its light space
    CullMode cullMode = CullMode::None;
    bool depthClamp = true;
    double sceneRadius = 1.0;
};

// The cause of one mismatched pixel: point/normal of the receiver (render-origin-relative, normal toward the
// camera), its reference class, its distance to the true boundary and k (both in texels). Thread-safe.
MismatchCause decideCause(const CauseContext& context, const glm::dvec3& point, const glm::dvec3& normal,
                          PixelClass reference, double distanceTexels, double k);

}  // namespace shadowlab
