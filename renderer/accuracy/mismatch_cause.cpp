#include "accuracy/mismatch_cause.h"

#include "views/view_select.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace shadowlab {

namespace {

constexpr CauseInfo kCauses[kCauseCount] = {
    {"none", "none", "", 0, 0, 0},
    {"selfShadowing", "self-shadowing", "raise shadow.slopeScaledDepthBias or shadow.normalOffset", 235, 40, 40},
    {"biasOverGap", "bias larger than the caster-receiver gap",
     "lower the bias, or cap it with shadow.depthBiasClamp", 50, 110, 255},
    {"casterCulled", "caster culled in the shadow pass",
     "set shadow.cullMode=none (or make the material doubleSided)", 230, 60, 230},
    {"outsideVolume", "outside the light's volume",
     "set projection.autoFit=true (or sampler.addressMode=border); point light: beyond its range or far plane",
     40, 200, 200},
    {"nearPlaneClip", "caster clipped by the near plane", "set projection.depthClamp=true or lower projection.near",
     250, 150, 30},
    {"alphaTest", "alpha test", "check the material's alphaCutoff and texture coordinates", 120, 220, 60},
    {"nearEdge", "within k of a true edge", "raise shadow.resolution or use a smaller filter.kernel", 120, 100, 70},
};

// The depth at which a point light's cube face holding p (views/view_select.h) sees it: along that face's axis.
double cubeFaceDepth(const ReferenceLight& light, const glm::dvec3& p) {
    const glm::dvec3 d = p - light.position;
    return glm::dot(d, cubeFaces()[std::size_t(cubeFaceOf(d))].look);
}

// The receiver's place in the map: outside [-1, 1] laterally, behind the light, or beyond the far plane. A point
// light's cube covers every direction: only beyond its range or the faces' far plane is outside.
bool outsideVolume(const ReferenceLight& reference, const LightSpace& light, const glm::dvec3& p) {
    if (reference.type == LightType::Point)
        return beyondRange(reference, p) || cubeFaceDepth(reference, p) > light.farPlane;
    const glm::dvec4 clip = light.viewProjection() * glm::dvec4(p, 1.0);
    if (!(clip.w > 0.0)) return true;
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    // Beyond the far plane in either depth convention (reversed-Z: far is depth 0).
    return std::abs(ndc.x) > 1.0 || std::abs(ndc.y) > 1.0 || light.normalDepth(light.windowDepth(clip)) > 1.0;
}

}  // namespace

const CauseInfo& causeInfo(MismatchCause cause) { return kCauses[std::size_t(cause)]; }

const std::array<MismatchCause, kCauseCount - 1>& allCauses() {
    static const std::array<MismatchCause, kCauseCount - 1> causes = {
        MismatchCause::CasterCulled, MismatchCause::SelfShadowing, MismatchCause::BiasOverGap,
        MismatchCause::OutsideVolume, MismatchCause::NearPlaneClip, MismatchCause::AlphaTest, MismatchCause::NearEdge};
    return causes;
}

MismatchCause decideCause(const CauseContext& c, const glm::dvec3& p, const glm::dvec3& n, PixelClass reference,
                          double distance, double k) {
    // A cascaded light: the cascade that holds p; beyond the shadow distance none does (the tool says lit there).
    const ShadowView* cascade = c.cascades.empty() ? nullptr : viewHolding(c.cascades, p);
    if (!c.cascades.empty() && !cascade) return MismatchCause::OutsideVolume;
    const LightSpace& space = cascade ? cascade->space : c.lightSpace;
    if (reference == PixelClass::OutsideCone || outsideVolume(c.light, space, p)) return MismatchCause::OutsideVolume;
    const glm::dvec3 l = towardLight(c.light, p);
    // The ray the map sees: from the light side down to just above the receiver.
    const double offset = 1e-5 * (glm::length(p) + c.sceneRadius);
    const glm::dvec3 receiver = p + n * offset;
    const double length = c.light.positional() ? glm::length(c.light.position - receiver) : 4.0 * c.sceneRadius + 1.0;
    const glm::dvec3 start = c.light.positional() ? c.light.position : receiver + l * length;
    HitRules rules;
    rules.positional = c.light.positional();
    rules.lightDirection = glm::vec3(c.light.direction);
    rules.lightPosition = glm::vec3(c.light.position);
    rules.cullMode = c.cullMode;

    if (!isLit(reference)) {  // too light: why does the map not hold the occluder?
        rules.shadowPassCulling = true;
        const RayHit kept = c.bvh->firstHit(glm::vec3(start), glm::vec3(-l), float(length), rules);
        if (!kept.hit) return MismatchCause::CasterCulled;
        // The caster's distance along the light from the light's eye (near plane's frame).
        const glm::dvec3 caster = start - l * double(kept.t);
        const double casterDepth = c.light.type == LightType::Point ? cubeFaceDepth(c.light, caster)
                                                                     : -(space.view * glm::dvec4(caster, 1.0)).z;
        if (!c.depthClamp && casterDepth < space.nearPlane) return MismatchCause::NearPlaneClip;
        if (distance <= k) return MismatchCause::NearEdge;
        return MismatchCause::BiasOverGap;
    }
    // Too dark on a truly lit receiver.
    if (distance <= k) return MismatchCause::NearEdge;
    if (c.bvh->hasAlphaMask()) {
        rules.ignoreAlpha = true;  // a MASK face the exact test lets light through, but the map may hold
        const RayHit any = c.bvh->firstHit(glm::vec3(start), glm::vec3(-l), float(length), rules);
        if (any.hit && any.alphaMask) return MismatchCause::AlphaTest;
    }
    return MismatchCause::SelfShadowing;
}

}  // namespace shadowlab
