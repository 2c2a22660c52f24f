#include "export/shadow_shader_code.h"

#include "gl/shader_sources.h"
#include "shading/filter_taps.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace shadowlab {

std::string shortestFloatText(float value) {
    char text[40];
    for (int digits = 1; digits <= 9; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, double(value));
        if (std::strtof(text, nullptr) == value) break;
    }
    std::string s = text;
    if (s.find_first_of(".eE") == std::string::npos) s += ".0";
    return s;
}

ShaderTarget shaderTargetFor(ExportFormat format, bool reversedZ) {
    ShaderTarget t;
    const bool d3d = format == ExportFormat::D3D12 || format == ExportFormat::D3D11;
    t.language = d3d ? ShaderLanguage::Hlsl : ShaderLanguage::Glsl;
    t.flipV = d3d;
    t.zeroToOneDepth = format != ExportFormat::GL || reversedZ;
    return t;
}

namespace {

// A float as a shader literal that reads back as the same float ("0.5", "1e-30").
std::string lit(double value) { return shortestFloatText(float(value)); }

// The words that differ between the two languages; every line below is written once with them.
struct Words {
    bool hlsl;
    std::string v2, v3, v4, m4, constant, rsqrt;
    explicit Words(ShaderLanguage language)
        : hlsl(language == ShaderLanguage::Hlsl),
          v2(hlsl ? "float2" : "vec2"),
          v3(hlsl ? "float3" : "vec3"),
          v4(hlsl ? "float4" : "vec4"),
          m4(hlsl ? "float4x4" : "mat4"),
          constant(hlsl ? "static const" : "const"),
          rsqrt(hlsl ? "rsqrt" : "inversesqrt") {}
    std::string mul(const std::string& m, const std::string& v) const {
        return hlsl ? "mul(" + m + ", " + v + ")" : m + " * " + v;
    }
    std::string toFloat(const std::string& x) const { return hlsl ? "(float)" + x : "float(" + x + ")"; }
    std::string allGreaterEqual(const std::string& a, const std::string& b) const {
        return hlsl ? "all(" + a + " >= " + b + ")" : "all(greaterThanEqual(" + a + ", " + b + "))";
    }
    std::string allLessEqual(const std::string& a, const std::string& b) const {
        return hlsl ? "all(" + a + " <= " + b + ")" : "all(lessThanEqual(" + a + ", " + b + "))";
    }
    std::string array(const std::string& type, const std::string& name, std::size_t n,
                      const std::vector<std::string>& values) const {
        std::string out = constant + " " + type + " " + name + "[" + std::to_string(n) + "] = " +
                          (hlsl ? "{" : type + "[](");
        for (std::size_t i = 0; i < values.size(); ++i) {
            out += (i ? ", " : "") + values[i];
            if (i % 4 == 3 && i + 1 < values.size()) out += "\n    ";
        }
        return out + (hlsl ? "};\n" : ");\n");
    }
    std::string vec(const std::string& type, const glm::dvec3& v) const {
        return type + "(" + lit(v.x) + ", " + lit(v.y) + ", " + lit(v.z) + ")";
    }
    // The shadow map and its comparison sampler as parameters.
    std::string mapParameters(bool cube) const {
        if (hlsl) return std::string(cube ? "TextureCube<float>" : "Texture2D<float>") + " map, SamplerComparisonState cmp";
        return cube ? "samplerCubeShadow map" : "sampler2DShadow map";
    }
    std::string compare2D(const std::string& uv, const std::string& ref) const {
        return hlsl ? "map.SampleCmpLevelZero(cmp, " + uv + ", " + ref + ")" : "texture(map, vec3(" + uv + ", " + ref + "))";
    }
    std::string compareCube(const std::string& dir, const std::string& ref) const {
        return hlsl ? "map.SampleCmpLevelZero(cmp, " + dir + ", " + ref + ")" : "texture(map, vec4(" + dir + ", " + ref + "))";
    }
};

std::string upperCase(std::string s) {
    for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

void tapTable(std::ostream& o, const Words& w, const std::string& P, const ShadowExport& e, bool mirrorY) {
    const std::vector<FilterTap> taps = filterTaps(e.filter);
    std::vector<std::string> values;
    for (const FilterTap& tap : taps)
        values.push_back(w.v2 + "(" + lit(tap.offsetTexels.x) + ", " + lit(mirrorY ? -tap.offsetTexels.y : tap.offsetTexels.y) + ")");
    o << w.constant << " int " << P << "TAPS = " << taps.size() << ";\n";
    o << "// The filter's taps in texels (ShadowLab's table, shading/filter_taps" << (mirrorY ? "; y mirrored: D3D's row 0 is clip y +1" : "")
      << "), each 1/" << taps.size() << " of S.\n";
    o << w.array(w.v2, P + "TAP_OFFSETS", taps.size(), values);
}

std::string clampToFar(const ShadowExport& e, const std::string& x) {
    return e.reversedZ ? "max(" + x + ", 0.0)" : "min(" + x + ", 1.0)";
}

// A cascaded light: which cascade holds a receiver and how the next one blends in, by ShadowLab's own selection
// (shaders/shadow/view_select.glsl, printed as it is; GLSL, so a comment for HLSL), with this light's split depths
// and the camera the cascades were fitted to.
std::string cascadeSelection(const ShadowExport& e, const Words& w, const std::string& p, const std::string& P) {
    std::ostringstream o;
    if (e.views.size() < e.cascadeCount) {
        o << "\n// One cascade of " << e.cascadeCount << " exported (--view): no selection; look it up with "
          << P << "CASCADE_TEXEL_WORLD[0].\n";
        return o.str();
    }
    std::vector<double> far(4, 0.0), blend(4, 0.0);
    for (const ExportView& v : e.views) {
        far[std::size_t(v.cascade)] = v.farDepth;
        blend[std::size_t(v.cascade)] = v.blendStart;
    }
    const auto v4 = [&](const std::vector<double>& x) {
        return w.v4 + "(" + lit(x[0]) + ", " + lit(x[1]) + ", " + lit(x[2]) + ", " + lit(x[3]) + ")";
    };
    std::ostringstream g;  // GLSL
    g << "\n// ---- The cascade selection: ShadowLab's shaders/shadow/view_select.glsl as it is ----\n"
      << "#ifndef SHADOWLAB_VIEW_SELECT\n#define SHADOWLAB_VIEW_SELECT\n"
      << embeddedShaderSources().at("shadow/view_select.glsl") << "#endif\n\n"
      << "const int " << P << "CASCADES = " << e.cascadeCount << ";\n"
      << "// Where each cascade ends, and where it starts fading into the next: depths in front of the camera.\n"
      << "const vec4 " << P << "CASCADE_FAR = " << v4(far) << ";\n"
      << "const vec4 " << P << "CASCADE_BLEND_START = " << v4(blend) << ";\n"
      << "// The camera the cascades (and their matrices above) were fitted to, minus the render origin: a moving camera\n"
      << "// needs the cascades refitted (ShadowLab does it every frame the camera moves).\n"
      << "const vec3 " << P << "CAMERA_EYE = " << w.vec("vec3", e.camera.eye) << ";\n"
      << "const vec3 " << P << "CAMERA_FORWARD = " << w.vec("vec3", e.camera.forward) << ";\n"
      << "// Which cascade holds worldPos (view -1: beyond the shadow distance, lit) and, in its blend band, the next one's\n"
      << "// share. S = choice.view < 0 ? 1.0 : mix(S(view), S(next), choice.weight) with\n"
      << "// S(c) = " << p << "Shadow(map of cascade c, its matrix, " << P << "CASCADE_TEXEL_WORLD[c], worldPos, n"
      << (e.receiverPlane ? ", positionDx, positionDy" : "") << ").\n"
      << "CascadeChoice " << p << "Cascade(vec3 worldPos) {\n"
      << "    return selectCascade(dot(worldPos - " << P << "CAMERA_EYE, " << P << "CAMERA_FORWARD), " << P
      << "CASCADE_FAR, " << P << "CASCADE_BLEND_START, " << P << "CASCADES);\n}\n";
    if (!w.hlsl) return g.str();
    // HLSL: the same GLSL, commented, to translate (vecN -> floatN, the struct's constructor).
    o << "\n// The cascade selection in GLSL (ShadowLab's shaders/shadow/view_select.glsl; translate vecN to floatN):\n";
    std::istringstream lines(g.str());
    for (std::string line; std::getline(lines, line);) o << "// " << line << "\n";
    return o.str();
}

// Directional and spot lights: shadow2D of shaders/shadow/lookup_2d.glsl, receiverPlaneSlope of compare_2d.glsl.
std::string code2D(const ShadowExport& e, const ShaderTarget& t) {
    const Words w(t.language);
    const std::string p = "light" + std::to_string(e.lightIndex);
    const std::string P = upperCase(p) + "_";
    const bool spot = e.lightType == LightType::Spot;
    const bool plane = e.receiverPlane;
    const bool nearest = !filterIsBilinear(e.filter.kind);
    std::ostringstream o;
    o << "// S of " << e.label << " (1 = lit), " << (w.hlsl ? "HLSL" : "GLSL") << ", generated by ShadowLab from its filter table.\n"
      << "// worldPos: the receiver's world position minus the render origin; n: its unit normal, facing the viewer's side;\n"
      << "// viewProjection: " << e.label << "'s matrix above"
      << (w.hlsl ? " (column_major float4x4, as uploaded column by column)" : "") << ".\n";
    if (plane)
        o << "// Receiver-plane depth bias: positionDx, positionDy are " << (w.hlsl ? "ddx(worldPos), ddy(worldPos)" : "dFdx(worldPos), dFdy(worldPos)")
          << ", taken where control\n// flow is uniform (before any light's branch).\n";
    o << w.constant << " float " << P << "TEXEL = " << lit(1.0 / double(e.shadow.resolution)) << ";  // 1 / resolution\n"
      << w.constant << " float " << P << "NORMAL_OFFSET = " << lit(e.shadow.normalOffset) << ";  // texels\n"
      ;
    if (e.cascaded) {  // each cascade's own texel: the caller passes texelWorld of the cascade it looks up in
        std::vector<std::string> sizes;
        for (const ExportView& v : e.views) sizes.push_back(lit(v.texelWorldSize));
        o << "// Each exported cascade's texel, world units (the normal offset and receiver plane scale with it).\n"
          << w.array("float", P + "CASCADE_TEXEL_WORLD", sizes.size(), sizes);
    } else {
        o << w.constant << " float " << P << "TEXEL_WORLD = " << lit(spot ? e.texelWorldPerDepth : e.texelWorldSize)
          << (spot ? ";  // a texel's world size per unit of distance along the spot's axis\n" : ";  // a texel's world size\n");
    }
    if (spot)
        o << w.constant << " " << w.v3 << " " << P << "POSITION = " << w.vec(w.v3, e.lightPosition) << ";  // minus the render origin\n"
          << w.constant << " " << w.v3 << " " << P << "AXIS = " << w.vec(w.v3, e.lightDirection) << ";\n";
    else
        o << w.constant << " " << w.v3 << " " << P << "DIRECTION = " << w.vec(w.v3, e.lightDirection)
          << ";  // the direction light travels\n";
    tapTable(o, w, P, e, t.flipV);
    o << "\n" << w.v3 << " " << p << "ToTexture(" << w.m4 << " viewProjection, " << w.v3 << " position) {\n"
      << "    " << w.v4 << " clip = " << w.mul("viewProjection", w.v4 + "(position, 1.0)") << ";\n"
      << "    " << w.v3 << " ndc = clip.xyz / clip.w;\n"
      << "    return " << w.v3 << "(ndc.x * 0.5 + 0.5, " << (t.flipV ? "0.5 - ndc.y * 0.5" : "ndc.y * 0.5 + 0.5") << ", "
      << (t.zeroToOneDepth ? "ndc.z" : "ndc.z * 0.5 + 0.5") << ");  // texture u, v and window depth\n}\n";
    if (plane) {
        o << "\n// The receiver's depth change per texel along u and v (Isidoro, GDC 2006): the pixel's steps taken into the map\n"
          << "// give d(u,v)/d(x,y) and d(depth)/d(x,y); its inverse gives d(depth)/d(u,v). 0 for an edge-on receiver; a\n"
          << "// plane steeper than " << lit(kExportReceiverPlaneMaxSlope) << " texel-world-sizes of depth per texel is clamped.\n"
          << w.v2 << " " << p << "ReceiverPlaneSlope(" << w.m4 << " viewProjection, " << w.v3 << " lookup, " << w.v3 << " lightTex, "
          << w.v3 << " ray, float texelWorld,\n        " << w.v3 << " positionDx, " << w.v3 << " positionDy) {\n"
          << "    float texels = 1.0 / " << P << "TEXEL;\n"
          << "    " << w.v3 << " dx = " << p << "ToTexture(viewProjection, lookup + positionDx) - lightTex;\n"
          << "    " << w.v3 << " dy = " << p << "ToTexture(viewProjection, lookup + positionDy) - lightTex;\n"
          << "    dx.xy *= texels;\n    dy.xy *= texels;\n"
          << "    float det = dx.x * dy.y - dx.y * dy.x;\n"
          << "    if (!(abs(det) > " << lit(kExportReceiverPlaneSingular) << " * length(dx.xy) * length(dy.xy))) return "
          << w.v2 << "(0.0, 0.0);\n"
          << "    " << w.v2 << " slope = " << w.v2 << "(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det;\n"
          << "    float limit = " << lit(kExportReceiverPlaneMaxSlope) << " * abs(" << p
          << "ToTexture(viewProjection, lookup + ray * texelWorld).z - lightTex.z);\n"
          << "    float length2 = dot(slope, slope);\n"
          << "    return length2 > limit * limit ? slope * (limit * " << w.rsqrt << "(length2)) : slope;\n}\n";
    }
    o << "\nfloat " << p << "Shadow(" << w.mapParameters(false) << ", " << w.m4 << " viewProjection, "
      << (e.cascaded ? "float texelWorld, " : "") << w.v3 << " worldPos, "
      << w.v3 << " n" << (plane ? ",\n        " + w.v3 + " positionDx, " + w.v3 + " positionDy" : "") << ") {\n";
    if (spot)
        o << "    " << w.v3 << " fromLight = worldPos - " << P << "POSITION;\n"
          << "    float texelWorld = " << P << "TEXEL_WORLD * dot(fromLight, " << P << "AXIS);\n";
    else if (!e.cascaded)
        o << "    float texelWorld = " << P << "TEXEL_WORLD;\n";
    o << "    " << w.v3 << " lookup = worldPos + n * (" << P << "NORMAL_OFFSET * texelWorld);  // normal offset\n"
      << "    " << w.v3 << " lightTex = " << p << "ToTexture(viewProjection, lookup);\n";
    if (plane)
        o << "    " << w.v3 << " ray = " << (spot ? "fromLight / max(length(fromLight), 1e-20)" : P + "DIRECTION")
          << ";  // the direction light travels here\n"
          << "    " << w.v2 << " plane = " << p << "ReceiverPlaneSlope(viewProjection, lookup, lightTex, ray, texelWorld, positionDx, positionDy);\n";
    else
        o << "    float ref = " << clampToFar(e, "lightTex.z") << ";  // beyond the far plane: compared as on it\n";
    o << "    // A lookup inside the map keeps its taps inside it (half a texel from the edge), so a kernel near the edge reads\n"
      << "    // the map's own border texels, not the address mode's outside.\n"
      << "    bool inside = " << w.allGreaterEqual("lightTex.xy", w.v2 + "(0.0, 0.0)") << " && "
      << w.allLessEqual("lightTex.xy", w.v2 + "(1.0, 1.0)") << ";\n"
      << "    " << w.v2 << " lo = inside ? " << w.v2 << "(0.5 * " << P << "TEXEL, 0.5 * " << P << "TEXEL) : " << w.v2 << "(-1e30, -1e30);\n"
      << "    " << w.v2 << " hi = inside ? " << w.v2 << "(1.0 - 0.5 * " << P << "TEXEL, 1.0 - 0.5 * " << P << "TEXEL) : "
      << w.v2 << "(1e30, 1e30);\n"
      << "    float sum = 0.0;\n"
      << "    for (int i = 0; i < " << P << "TAPS; ++i) {\n"
      << "        " << w.v2 << " tapTex = clamp(lightTex.xy + " << P << "TAP_OFFSETS[i] * " << P << "TEXEL, lo, hi);\n";
    if (plane) {
        o << "        " << w.v2 << " offset = (tapTex - lightTex.xy) / " << P << "TEXEL;  // texels, to the tap actually read\n";
        if (nearest)
            o << "        // A nearest tap reads one texel, whose stored depth is its caster's at the texel's centre: the plane there.\n"
              << "        " << w.v2 << " lookupTexels = lightTex.xy / " << P << "TEXEL;\n"
              << "        " << w.v2 << " toCentre = floor(lookupTexels + offset) + 0.5 - lookupTexels;\n"
              << "        float tapRef = " << clampToFar(e, "lightTex.z + dot(plane, toCentre)") << ";\n";
        else
            o << "        float tapRef = " << clampToFar(e, "lightTex.z + dot(plane, offset)") << ";  // the receiver's plane at the tap\n";
    } else {
        o << "        float tapRef = ref;\n";
    }
    o << "        sum += " << w.compare2D("tapTex", "tapRef") << ";\n"
      << "    }\n"
      << "    return sum / " << w.toFloat(P + "TAPS") << ";\n}\n";
    if (e.cascaded) o << cascadeSelection(e, w, p, P);
    return o.str();
}

// Point lights: shadowCube of shaders/shadow/lookup_cube.glsl and faceDepth of cube_face_depth.glsl.
std::string codeCube(const ShadowExport& e, const ShaderTarget& t) {
    const Words w(t.language);
    const std::string p = "light" + std::to_string(e.lightIndex);
    const std::string P = upperCase(p) + "_";
    std::ostringstream o;
    o << "// S of " << e.label << " (1 = lit), " << (w.hlsl ? "HLSL" : "GLSL") << ", generated by ShadowLab from its filter table.\n"
      << "// worldPos: the receiver's world position minus the render origin; n: its unit normal, facing the viewer's side.\n"
      << "// The cube map is sampled by direction; each face stores its own perspective depth, so the reference is the\n"
      << "// receiver's depth in the face the tap's direction selects. (Receiver-plane bias does not apply to cube faces.)\n";
    o << w.constant << " float " << P << "TEXEL = " << lit(1.0 / double(e.shadow.resolution)) << ";  // 1 / resolution\n"
      << w.constant << " float " << P << "NORMAL_OFFSET = " << lit(e.shadow.normalOffset) << ";  // texels\n"
      << w.constant << " float " << P << "TEXEL_WORLD = " << lit(e.texelWorldPerDepth)
      << ";  // a texel's world size per unit of distance along the face's axis\n"
      << w.constant << " " << w.v3 << " " << P << "POSITION = " << w.vec(w.v3, e.lightPosition) << ";  // minus the render origin\n"
      << w.constant << " float " << P << "NEAR = " << lit(e.nearPlane) << ";\n"
      << w.constant << " float " << P << "FAR = " << lit(e.farPlane) << ";\n";
    tapTable(o, w, P, e, false);
    o << "\nfloat " << p << "FaceDepth(" << w.v3 << " fromLight, " << w.v3 << " tapDirection) {\n"
      << "    " << w.v3 << " a = abs(tapDirection);\n"
      << "    " << w.v3 << " axis = a.x >= a.y && a.x >= a.z ? " << w.v3 << "(sign(tapDirection.x), 0.0, 0.0)\n"
      << "              : a.y >= a.z                ? " << w.v3 << "(0.0, sign(tapDirection.y), 0.0)\n"
      << "                                          : " << w.v3 << "(0.0, 0.0, sign(tapDirection.z));\n"
      << "    float z = max(dot(fromLight, axis), " << P << "NEAR);\n";
    if (e.reversedZ)
        o << "    return " << P << "NEAR * (" << P << "FAR - z) / (z * (" << P << "FAR - " << P << "NEAR));  // zero-to-one, near 1, far 0\n";
    else
        o << "    return ((" << P << "FAR + " << P << "NEAR) / (" << P << "FAR - " << P << "NEAR) - 2.0 * " << P << "FAR * " << P
          << "NEAR / ((" << P << "FAR - " << P << "NEAR) * z)) * 0.5 + 0.5;\n";
    o << "}\n\nfloat " << p << "Shadow(" << w.mapParameters(true) << ", " << w.v3 << " worldPos, " << w.v3 << " n) {\n"
      << "    " << w.v3 << " a0 = abs(worldPos - " << P << "POSITION);\n"
      << "    " << w.v3 << " lookup = worldPos + n * (" << P << "NORMAL_OFFSET * (" << P
      << "TEXEL_WORLD * max(a0.x, max(a0.y, a0.z))));  // normal offset\n"
      << "    " << w.v3 << " v = lookup - " << P << "POSITION;\n"
      << "    " << w.v3 << " a = abs(v);\n"
      << "    float major = max(a.x, max(a.y, a.z));\n"
      << "    // The face's two tangent axes: taps move across the face by texels (2 / resolution at unit distance).\n"
      << "    " << w.v3 << " s = a.x >= a.y && a.x >= a.z ? " << w.v3 << "(0.0, 0.0, 1.0) : " << w.v3 << "(1.0, 0.0, 0.0);\n"
      << "    " << w.v3 << " t = a.y >= a.x && a.y >= a.z ? " << w.v3 << "(0.0, 0.0, 1.0) : " << w.v3 << "(0.0, 1.0, 0.0);\n"
      << "    float texelAtMajor = 2.0 * " << P << "TEXEL * major;\n"
      << "    float sum = 0.0;\n"
      << "    for (int i = 0; i < " << P << "TAPS; ++i) {\n"
      << "        " << w.v2 << " o = " << P << "TAP_OFFSETS[i] * texelAtMajor;\n"
      << "        " << w.v3 << " d = v + o.x * s + o.y * t;\n"
      << "        float ref = " << clampToFar(e, p + "FaceDepth(v, d)") << ";\n"
      << "        sum += " << w.compareCube("d", "ref") << ";\n"
      << "    }\n"
      << "    return sum / " << w.toFloat(P + "TAPS") << ";\n}\n";
    return o.str();
}

}  // namespace

std::string shadowShaderCode(const ShadowExport& light, const ShaderTarget& target) {
    return light.lightType == LightType::Point ? codeCube(light, target) : code2D(light, target);
}

}  // namespace shadowlab
