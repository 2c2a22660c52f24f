#include "probe/probe_description.h"

#include "light/light_space.h"
#include "shading/filters/filter_technique.h"

#include "settings/settings_fields.h"
#include "shadow/shadow_map.h"

#include <cmath>
#include <cstdio>

namespace shadowlab {

namespace {

std::string format(const char* pattern, auto... values) {
    char buf[512];
    std::snprintf(buf, sizeof buf, pattern, values...);
    return buf;
}

std::string vec(const glm::dvec3& v) { return format("(%.9g, %.9g, %.9g)", v.x, v.y, v.z); }

std::string units(const BiasTerm& t) {
    return format("%.3g depth = %.3g world units = %.3g texels", t.depth, t.world, t.texels);
}

const char* filterName(const FilterSettings& f) {
    switch (f.kind) {
        case FilterKind::Point: return "point";
        case FilterKind::Hardware2x2: return "hardware 2x2";
        case FilterKind::Pcf: return "PCF";
        case FilterKind::Poisson: return "Poisson";
        default: return filterTechnique(f.kind).name;  // the moments techniques: their filter.kind name
    }
}

const char* className(PixelClass c) {
    switch (c) {
        case PixelClass::Background: return "background";
        case PixelClass::NonFinite: return "non-finite";
        case PixelClass::FacingAway: return "facing away from the light (unlit, not scored)";
        case PixelClass::OutOfRange: return "beyond the light's range (not reached, not scored)";
        case PixelClass::OutsideCone: return "outside the spot cone (V = 0)";
        case PixelClass::Lit: return "lit (V = 1)";
        case PixelClass::Shadowed: return "shadowed (V = 0)";
    }
    return "?";
}

int litTaps(const PixelProbeReport& r) {
    int n = 0;
    for (const ProbeTap& t : r.taps) n += t.value >= 0.5 ? 1 : 0;
    return n;
}

nlohmann::json toJson(const glm::dvec3& v) { return {v.x, v.y, v.z}; }
nlohmann::json toJson(const BiasTerm& t) { return {{"depth", t.depth}, {"world", t.world}, {"texels", t.texels}}; }

// The lookup of one view: where it reads the map, the receiver's depth, the bias in this view's texels, its taps.
void lookupLines(const PixelProbeReport& r, std::vector<std::string>& lines, const std::string& indent) {
    lines.push_back(indent + "lookup (normal offset applied): world " + vec(r.lookupWorld));
    lines.push_back(indent + "  light view " + vec(r.lightView) +
                    format(", map coord (%.6f, %.6f) = texel coord (%.3f, %.3f) in texel [%d,%d] of %d²%s%s",
                           r.lightTexture.x, r.lightTexture.y, r.texelCoord.x, r.texelCoord.y, r.texel.x, r.texel.y,
                           r.resolution, r.insideMap ? "" : " (outside the map: the address mode decides)",
                           r.inCone ? "" : " (outside the spot cone: S = 0)"));
    lines.push_back(indent + format("receiver depth %.9g (window depth %.9g, %s; float rounding +-%.2g)", r.receiverDepth,
                           r.lightTexture.z, depthFormatName(r.format), r.depthUncertainty));
    lines.push_back(indent + format("bias at this surface (depth slope m = %.3g per texel, r = %.3g)%s:",
                                    r.bias.depthSlope, r.bias.step,
                                    r.cascade.empty() ? "" : (" in " + r.cascade + "'s texels").c_str()));
    lines.push_back(indent + "  constant DepthBias x r: " + units(r.bias.constant));
    lines.push_back(indent + "  slope-scaled SlopeScaledDepthBias x m: " + units(r.bias.slope));
    lines.push_back(indent + (r.bias.clamp.depth > 0.0 ? "  clamp DepthBiasClamp: " + units(r.bias.clamp)
                                                       : std::string("  clamp: none")));
    lines.push_back(indent + "  total (as a caster, in the map): " + units(r.bias.total));
    lines.push_back(indent + format("  normal offset %.3g texels = %.3g world units along the shading normal",
                           r.bias.normalOffsetTexels, r.bias.normalOffsetWorld));
    if (r.momentLookup) {
        // A moments technique: one bilinear read of the blurred moments, then the technique's bound.
        lines.push_back(indent + format("filter %s: one bilinear read of %d-bit moments (blur %g %s) at texel coord "
                                        "(%.3f, %.3f): moments (%.6g, %.6g, %.6g, %.6g), receiver %.6g (near 0)",
                                        filterName(r.filter), r.filter.momentBits, double(r.filter.blurWidth),
                                        r.filter.blurUnit == BlurUnit::World ? "world units" : "texels",
                                        r.taps.empty() ? 0.0 : r.taps[0].texelCoord.x,
                                        r.taps.empty() ? 0.0 : r.taps[0].texelCoord.y, r.moments.x, r.moments.y,
                                        r.moments.z, r.moments.w, r.momentDepth));
        if (r.momentLevel >= 0.0)
            lines.push_back(indent + format("  mip level %.3f (the pixel's footprint in the map's texels: trilinear "
                                            "between levels %d and %d)",
                                            r.momentLevel, int(r.momentLevel), int(std::ceil(r.momentLevel))));
        lines.push_back(indent + "  " + r.momentText);
        return;
    }
    if (r.ownLookup && !r.search.text.empty()) lines.push_back(indent + r.search.text);
    lines.push_back(indent + format("filter %s%s: %zu taps (stored depth, lit if receiver <= stored; ? = within float "
                           "rounding; (+x) = stored - receiver)",
                           filterName(r.filter),
                           r.filter.kind == FilterKind::Pcf ? format(" %dx%d", r.filter.kernel, r.filter.kernel).c_str()
                           : r.filter.kind == FilterKind::Poisson ? format(" radius %g", double(r.filter.poissonRadius)).c_str()
                                                                  : "",
                           r.taps.size()));
    for (const ProbeTap& t : r.taps) lines.push_back(indent + "  " + describeTap(r, t));
}

}  // namespace

std::string probeSummary(const PixelProbeReport& r) {
    if (!r.ok) return r.error;
    return format("S = %.4f (GPU %.4f, %s): %d of %zu taps lit%s", r.shadowCpu, r.shadowGpu,
                  !r.compared ? "not compared" : r.agrees ? "agree" : "DISAGREE", litTaps(r), r.taps.size(),
                  r.uncertainComparisons ? format(", %d comparison(s) within float rounding",
                                                  r.uncertainComparisons).c_str()
                                         : "");
}

std::string describeTap(const PixelProbeReport& r, const ProbeTap& t) {
    std::string line = format("tap (%+.2f, %+.2f) at texel coord (%.3f, %.3f): ", t.offsetTexels.x, t.offsetTexels.y,
                              t.texelCoord.x, t.texelCoord.y);
    for (std::size_t k = 0; k < t.texels.size(); ++k) {
        const ProbeTexel& x = t.texels[k];
        const bool otherFace = x.face >= 0 && x.face != r.face;
        line += format("%s%s%s%s[%d,%d] %.9g %s%s", k ? "; " : "", x.border ? "border" : "",
                       otherFace ? cubeFaces()[std::size_t(x.face)].name : "", otherFace ? " " : "", x.texel.x, x.texel.y,
                       x.stored, x.lit ? "lit" : "shadow", x.uncertain ? "?" : "");
        if (t.bilinear) line += format(" w%.3f", x.weight);
        line += format(" (%+.3g)", x.stored - r.receiverDepth);
    }
    return line + format(" -> %.3f", t.value);
}

std::vector<std::string> describeProbe(const PixelProbeReport& r) {
    std::vector<std::string> lines;
    if (!r.ok) {
        lines.push_back("no probe: " + r.error);
        return lines;
    }
    lines.push_back(format("pixel %d,%d of %dx%d: ", r.x, r.y, r.width, r.height) + probeSummary(r));
    lines.push_back("light " + std::to_string(r.light) + " (" + lightTypeName(r.lightType) + ")" +
                    (r.face >= 0 ? std::string(", cube face ") + cubeFaces()[std::size_t(r.face)].name : std::string()) +
                    (r.cascade.empty() ? std::string() : ", " + r.cascade) +
                    (r.viewCount < 2 ? std::string()
                     : r.viewChosen ? format(" (of %d views: the one asked for)", r.viewCount)
                                    : format(" (of %d views: the one holding this point; --view chooses another)",
                                             r.viewCount)) +
                    ", alone: S is this light's shadow factor");
    if (!r.blendNote.empty()) lines.push_back("  " + r.blendNote);
    lines.push_back("surface: world " + vec(r.world) + format(" on '%s' (instance %d, triangle %d), %s face",
                                                              r.meshName.c_str(), r.instance, r.triangle,
                                                              r.frontFacing ? "front" : "back"));
    lines.push_back("  geometric normal " + vec(r.geometricNormal) + ", shading normal " + vec(r.shadingNormal));
    lookupLines(r, lines, "");
    for (const PixelProbeReport& next : r.blend) {
        lines.push_back(format("blend partner %s (weight %.4f), the same surface in its own map:", next.cascade.c_str(),
                               r.blendWeight));
        lookupLines(next, lines, "  ");
        lines.push_back(format("  %s's S: CPU %.6f (possible %.6f..%.6f); %s's alone %.6f; mixed: %.6f",
                               next.cascade.c_str(), next.shadowCpu, next.shadowLow, next.shadowHigh,
                               r.cascade.c_str(), r.shadowView, r.shadowCpu));
    }
    lines.push_back(format("shadow factor: CPU %.6f (possible %.6f..%.6f), GPU %.6f, tolerance %.2g: %s", r.shadowCpu,
                           r.shadowLow, r.shadowHigh, r.shadowGpu, r.tolerance,
                           !r.compared ? "not compared (see above)" : r.agrees ? "agree" : "DISAGREE"));
    if (r.measured) {
        lines.push_back(std::string("exact visibility: ") + className(r.exact) +
                        format("; measured S %.4f", double(r.measuredShadow)) +
                        (r.cause != MismatchCause::None
                             ? std::string("; wrong because: ") + causeInfo(r.cause).name + " (" +
                                   causeInfo(r.cause).remedy + ")"
                             : std::string("; not mismatched")));
    }
    return lines;
}

nlohmann::json probeToJson(const PixelProbeReport& r) {
    nlohmann::json j;
    j["ok"] = r.ok;
    j["pixel"] = {r.x, r.y};
    j["view"] = {r.width, r.height};
    if (!r.ok) {
        j["error"] = r.error;
        return j;
    }
    j["light"] = r.light;
    j["lightType"] = lightTypeName(r.lightType);
    if (r.face >= 0) j["cubeFace"] = cubeFaces()[std::size_t(r.face)].name;
    if (!r.cascade.empty()) j["cascade"] = r.cascade;
    j["viewCount"] = r.viewCount;
    j["viewChosen"] = r.viewChosen;
    if (!r.blendNote.empty()) j["note"] = r.blendNote;
    if (!r.blend.empty())  // the blend band: the next cascade's own lookup, and the weight the GPU mixes it at
        j["blend"] = {{"weight", r.blendWeight}, {"shadowView", r.shadowView}, {"next", probeToJson(r.blend.front())}};
    j["surface"] = {{"world", toJson(r.world)},
                    {"geometricNormal", toJson(r.geometricNormal)},
                    {"shadingNormal", toJson(r.shadingNormal)},
                    {"frontFacing", r.frontFacing},
                    {"mesh", r.meshName},
                    {"instance", r.instance},
                    {"triangle", r.triangle}};
    j["lookupWorld"] = toJson(r.lookupWorld);
    j["lightView"] = toJson(r.lightView);
    j["lightTexture"] = toJson(r.lightTexture);
    j["texelCoord"] = {r.texelCoord.x, r.texelCoord.y};
    j["texel"] = {r.texel.x, r.texel.y};
    j["insideMap"] = r.insideMap;
    j["inCone"] = r.inCone;
    j["resolution"] = r.resolution;
    j["depthFormat"] = depthFormatName(r.format);
    j["receiverDepth"] = r.receiverDepth;
    j["depthUncertainty"] = r.depthUncertainty;
    j["bias"] = {{"depthSlope", r.bias.depthSlope},          {"step", r.bias.step},
                 {"constant", toJson(r.bias.constant)},       {"slopeScaled", toJson(r.bias.slope)},
                 {"clamp", toJson(r.bias.clamp)},             {"total", toJson(r.bias.total)},
                 {"normalOffsetWorld", r.bias.normalOffsetWorld}, {"normalOffsetTexels", r.bias.normalOffsetTexels}};
    nlohmann::json taps = nlohmann::json::array();
    for (const ProbeTap& t : r.taps) {
        nlohmann::json texels = nlohmann::json::array();
        for (const ProbeTexel& x : t.texels) {
            texels.push_back({{"texel", {x.texel.x, x.texel.y}}, {"border", x.border}, {"stored", x.stored},
                              {"weight", x.weight}, {"lit", x.lit}, {"uncertain", x.uncertain}});
            if (x.face >= 0) texels.back()["cubeFace"] = cubeFaces()[std::size_t(x.face)].name;
        }
        taps.push_back({{"offsetTexels", {t.offsetTexels.x, t.offsetTexels.y}},
                        {"texelCoord", {t.texelCoord.x, t.texelCoord.y}},
                        {"bilinear", t.bilinear},
                        {"texels", texels},
                        {"value", t.value}});
    }
    j["filter"] = {{"kind", filterName(r.filter)}, {"kernel", r.filter.kernel},
                   {"poissonRadius", r.filter.poissonRadius}, {"taps", taps}};
    j["shadow"] = {{"cpu", r.shadowCpu}, {"low", r.shadowLow},  {"high", r.shadowHigh},
                   {"gpu", r.shadowGpu}, {"tolerance", r.tolerance}, {"agree", r.agrees}, {"compared", r.compared},
                   {"uncertainComparisons", r.uncertainComparisons}};
    if (r.measured)
        j["accuracy"] = {{"exact", className(r.exact)}, {"measuredShadow", r.measuredShadow},
                         {"cause", causeInfo(r.cause).key}};
    return j;
}

}  // namespace shadowlab
