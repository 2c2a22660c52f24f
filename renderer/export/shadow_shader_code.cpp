#include "export/shadow_shader_code.h"

#include "gl/shader_sources.h"
#include "gl/shader_text.h"
#include "shading/filter_taps.h"
#include "shading/filters/filter_technique.h"
#include "shading/filters/moments_mirror.h"
#include "shading/variant_key.h"

#include <cstdio>
#include <cstdlib>
#include <cctype>
#include <map>
#include <regex>
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
    t.vulkan = format == ExportFormat::Vulkan;
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

// The renderer's GLSL file `file` (shaders/...) as a snippet prints it: the files it includes first, each once, every
// file inside a guard named after it (SHADOWLAB_SHADOW_VIEW_SELECT_GLSL), so two lights' code that print the same
// file compile it once.
void printRendererFile(std::ostream& o, const std::string& file) {
    static const std::regex include(R"re(^\s*#include\s+"([^"]+)"\s*$)re");
    std::string guard = "SHADOWLAB_" + upperCase(file);
    for (char& c : guard)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    std::istringstream lines(embeddedShaderSources().at(file));
    std::string body;
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        if (std::regex_match(line, m, include)) printRendererFile(o, m[1]);
        else body += line + "\n";
    }
    o << "#ifndef " << guard << "\n#define " << guard << "\n" << body << "#endif\n";
}

// A cascaded light: which cascade holds a receiver and how the next one blends in, by ShadowLab's own selection
// (shaders/shadow/view_select.glsl, printed as it is; GLSL, so a comment for HLSL), with this light's split depths
// and the camera the cascades were fitted to.
std::string cascadeSelection(const ShadowExport& e, const Words& w, const std::string& p, const std::string& P,
                             bool viewSelectIncluded = false) {
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
    if (viewSelectIncluded) {  // the technique's lookup above holds it already
        g << "\n// ---- The cascade selection (selectCascade: shaders/shadow/view_select.glsl, above) ----\n";
    } else {
        g << "\n// ---- The cascade selection: ShadowLab's shaders/shadow/view_select.glsl as it is ----\n";
        printRendererFile(g, "shadow/view_select.glsl");
        g << "\n";
    }
    g << "const int " << P << "CASCADES = " << e.cascadeCount << ";\n"
      << "// Where each cascade ends, and where it starts fading into the next: depths in front of the camera.\n"
      << "const vec4 " << P << "CASCADE_FAR = " << v4(far) << ";\n"
      << "const vec4 " << P << "CASCADE_BLEND_START = " << v4(blend) << ";\n"
      << "// The camera the cascades (and their matrices above) were fitted to, minus the render origin: a moving camera\n"
      << "// needs the cascades refitted (ShadowLab does it every frame the camera moves).\n"
      << "const vec3 " << P << "CAMERA_EYE = " << w.vec("vec3", e.camera.eye) << ";\n"
      << "const vec3 " << P << "CAMERA_FORWARD = " << w.vec("vec3", e.camera.forward) << ";\n"
      << "// Which cascade holds worldPos (view -1: beyond the shadow distance, lit) and, in its blend band, the next one's\n"
      << "// share. S = choice.view < 0 ? 1.0 : mix(S(view), S(next), choice.weight) with\n"
      << "// S(c) = " << (viewSelectIncluded ? p + "Shadow(c, worldPos, n" : p + "Shadow(map of cascade c, its matrix, " + P + "CASCADE_TEXEL_WORLD[c], worldPos, n")
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

// Point lights: shadowCube of shaders/shadow/lookup_cube.glsl, with the renderer's cube face frame, taps and face
// depth (shaders/shadow/cube_face_depth.glsl, printed as it is: one source of truth for the taps' directions) and a
// LightData filled from the exported numbers. HLSL: those GLSL files as comments, to translate.
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
    std::ostringstream g;  // the renderer's GLSL: HLSL takes it as comments
    g << "\n// ---- ShadowLab's cube face frame, taps and face depth: shaders/shadow/cube_face_depth.glsl and what it includes, as they are ----\n";
    printRendererFile(g, "shadow/cube_face_depth.glsl");
    if (w.hlsl) {
        o << "\n// The renderer's GLSL this lookup calls (translate vecN -> floatN, the structs' constructors):\n";
        std::istringstream lines(g.str());
        for (std::string line; std::getline(lines, line);) o << "// " << line << "\n";
    } else {
        o << g.str();
    }
    const int flags = e.reversedZ ? 1 : 0;
    o << "\n// " << e.label << "'s numbers as the LightData the files above read (depth.w: 1 = reversed-Z).\n"
      << "LightData " << p << "Data() {\n"
      << "    LightData L;\n"
      << "    L.viewProjection = " << (w.hlsl ? "(float4x4)0" : "mat4(1.0)") << ";\n"
      << "    L.position = " << w.v4 << "(" << P << "POSITION, 0.0);\n"
      << "    L.direction = " << w.v4 << "(0.0, 0.0, 0.0, 0.0);\n"
      << "    L.radiance = " << w.v4 << "(1.0, 1.0, 1.0, 1.0);\n"
      << "    L.shadow = " << w.v4 << "(0.0, 0.0, " << P << "TEXEL, " << P << "NORMAL_OFFSET);\n"
      << "    L.depth = " << w.v4 << "(" << P << "NEAR, " << P << "FAR, " << P << "TEXEL_WORLD, " << flags << ".0);\n"
      << "    L.views = " << w.v4 << "(0.0, 0.0, 0.0, 0.0);\n"
      << "    return L;\n}\n";
    o << "\nfloat " << p << "Shadow(" << w.mapParameters(true) << ", " << w.v3 << " worldPos, " << w.v3 << " n) {\n"
      << "    LightData L = " << p << "Data();\n"
      << "    " << w.v3 << " a0 = abs(worldPos - " << P << "POSITION);\n"
      << "    " << w.v3 << " lookup = worldPos + n * (" << P << "NORMAL_OFFSET * (" << P
      << "TEXEL_WORLD * max(a0.x, max(a0.y, a0.z))));  // normal offset\n"
      << "    " << w.v3 << " v = lookup - " << P << "POSITION;\n"
      << "    CubeFaceFrame frame = cubeFaceFrame(v, L);  // taps move across the lookup's face, texel by texel\n"
      << "    float sum = 0.0;\n"
      << "    for (int i = 0; i < " << P << "TAPS; ++i) {\n"
      << "        " << w.v3 << " d = cubeFaceTap(frame, " << P << "TAP_OFFSETS[i]);\n"
      << "        float ref = clampToFar(L, faceDepth(v, d, L));\n"
      << "        sum += " << w.compareCube("d", "ref") << ";\n"
      << "    }\n"
      << "    return sum / " << w.toFloat(P + "TAPS") << ";\n}\n";
    return o.str();
}

std::string vec4Text(const glm::vec4& v) {
    return "vec4(" + lit(v.x) + ", " + lit(v.y) + ", " + lit(v.z) + ", " + lit(v.w) + ")";
}

std::string mat4Text(const glm::dmat4& m) {
    std::string out = "mat4(";
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) out += (c || r ? ", " : "") + lit(m[c][r]);
    return out + ")";
}

// The defines the main pass compiles shaders/shadow/lookup.glsl with for this technique and one map array of this
// light's kind (shading/variant_key.h's, those the lookup files read), and the file its alias names.
std::vector<std::string> lookupDefines(const ShadowExport& e, gl::IncludeAliases& aliases) {
    const FilterTechnique& technique = filterTechnique(e.filter.kind);
    MainVariantKey key;
    key.filter = e.filter.kind;
    key.kernel = e.filter.kernel;
    const bool cube = e.lightType == LightType::Point;
    key.lights.mapArrays2D = cube ? 0 : 1;
    key.lights.mapArraysCube = cube ? 1 : 0;
    key.receiverPlane = e.receiverPlane;
    key.momentMips = e.filter.momentMips;
    std::vector<std::string> defines;
    for (const std::string& d : key.defines())
        for (const char* read : {"MOMENT_TECHNIQUE", "MOMENT_MIPS", "OWN_LOOKUP", "FILTER_", "MAP_ARRAYS_", "RECEIVER_PLANE"})
            if (d.rfind(read, 0) == 0) defines.push_back(d);
    if (technique.moments) aliases["alias:technique"] = technique.moments->glslFile;
    if (technique.ownLookup) aliases["alias:lookup"] = technique.ownLookup->glslFile;
    return defines;
}

}  // namespace

std::string techniqueLookupCode(const ShadowExport& e, bool vulkan, std::vector<VulkanBinding>* bindings) {
    const FilterTechnique& technique = filterTechnique(e.filter.kind);
    const Words w(ShaderLanguage::Glsl);
    const std::string p = "light" + std::to_string(e.lightIndex);
    const std::string P = upperCase(p) + "_";
    const bool cube = e.lightType == LightType::Point;
    const bool spot = e.lightType == LightType::Spot;
    const bool mips = e.momentTechnique && e.filter.momentMips;
    gl::IncludeAliases aliases;
    const std::vector<std::string> defines = lookupDefines(e, aliases);
    // uFilterScale: the depth lookups' (filter_taps.glsl); the text holds every branch lookup.glsl includes.
    const std::map<std::string, std::string> baked = {{"uTechnique", vec4Text(e.techniqueUniforms)},
                                                      {"uFilterScale", lit(technique.scale(e.filter))}};
    std::string lookup = bakeUniforms(gl::preprocessedSource("shadow/lookup.glsl", {}, {}, aliases), baked);
    std::vector<VulkanBinding> own;
    if (vulkan) lookup = vulkanUniforms(lookup, 0, bindings ? *bindings : own);
    const std::string guard = std::string("SHADOWLAB_LOOKUP_") + (cube ? "CUBE" : "2D");

    std::ostringstream o;
    o << "// S of " << e.label << " (1 = lit), GLSL: ShadowLab's own lookup for filter.kind " << technique.name
      << ", shaders/shadow/lookup.glsl with\n// " << (technique.moments ? std::string("shaders/") + technique.moments->glslFile
                                                  : std::string("shaders/") + technique.ownLookup->glslFile)
      << " as the main pass compiles it (#includes expanded, uTechnique = " << vec4Text(e.techniqueUniforms) << ").\n";
    if (technique.moments && mips)
        o << "// It reads the view's blurred moments trilinearly at the level of the pixel's footprint (the moments pass and\n"
          << "// its mips below): bind the moments image as "
          << (cube ? "uMapsCube[0], a cube-map array" : "uMaps2D[0], a 2D array (one layer per view)")
          << " with every level,\n// min filter linear-mipmap-linear, mag linear, clamp to border with the border depth's moments.\n";
    else if (technique.moments)
        o << "// It reads one bilinear sample of the view's blurred moments (the moments pass below): bind the moments image\n"
          << "// as " << (cube ? "uMapsCube[0], a cube-map array" : "uMaps2D[0], a 2D array (one layer per view)")
          << ", linear filtering, clamp to border with the border depth's moments.\n";
    else
        o << "// It reads the depth map twice: bind it as " << (cube ? "uMapsCube[0] (a cube-map array) with a comparison sampler (linear, "
                                                               : "uMaps2D[0] (a 2D array, one layer per view) with a comparison sampler (linear, ")
          << (e.reversedZ ? "GEQUAL" : "LEQUAL") << ")\n// and as " << (cube ? "uDepthCube[0]" : "uDepth2D[0]")
          << " with a plain nearest sampler (the blocker search). The rotation hashes gl_FragCoord: fragment shaders only.\n";
    if (vulkan) {
        // The text keeps the branches the defines leave out (the depth lookups' samplers among them): name the
        // descriptors this technique's lookup reads.
        const std::string arrays = cube ? "[MAP_ARRAYS_CUBE]" : "[MAP_ARRAYS_2D]";
        std::vector<std::pair<std::string, std::string>> reads;
        if (technique.moments)
            reads = {{std::string(cube ? "samplerCubeArray uMapsCube" : "sampler2DArray uMaps2D") + arrays, "the moments"}};
        else
            reads = {{std::string(cube ? "samplerCubeArrayShadow uMapsCube" : "sampler2DArrayShadow uMaps2D") + arrays,
                      "the depth map, comparison sampler"},
                     {std::string(cube ? "samplerCubeArray uDepthCube" : "sampler2DArray uDepth2D") + arrays,
                      "the same depth map, plain nearest sampler"}};
        o << "// Vulkan descriptors (set 0) it reads:";
        for (const auto& [declaration, what] : reads)
            for (const VulkanBinding& b : bindings ? *bindings : own)
                if (b.declaration == declaration) o << " binding " << b.binding << " = " << declaration << " (" << what << ");";
        o << "\n";
    }
    for (const std::string& d : defines) {
        const std::string name = d.substr(0, d.find(' '));
        o << "#undef " << name << "\n#define " << d << "\n";
    }
    o << "#ifndef " << guard << "\n#define " << guard << "\n" << lookup << "#endif\n";

    // The light's numbers as the LightData block the main pass fills (renderer/shading/main_pass.cpp).
    const std::size_t n = e.views.size();
    std::vector<std::string> matrices, texels, nears, fars;
    for (const ExportView& v : e.views) {
        matrices.push_back(mat4Text(v.viewProjection));
        texels.push_back(lit(e.perspective ? e.texelWorldPerDepth : v.texelWorldSize));
        nears.push_back(lit(v.nearPlane));
        fars.push_back(lit(v.farPlane));
    }
    const int flags = (e.reversedZ ? 1 : 0) + (e.shadow.receiverPlaneBias ? 2 : 0);
    o << "\n// " << e.label << "'s numbers as the LightData the lookup reads. Matrices: ShadowLab's own (render-origin-relative\n"
      << "// world -> its light clip space; the lookup's toLightTexture maps its depth convention), whatever the API.\n";
    if (!cube) {
        o << w.array("mat4", P + "VIEW_PROJECTION", n, matrices)
          << "// " << (e.perspective ? "A texel's world size per unit of distance along the view's axis."
                                     : "Each view's texel, world units (the normal offset" + std::string(e.receiverPlane ? " and receiver plane" : "") + " scale with it).") << "\n"
          << w.array("float", P + "TEXEL_WORLD", n, texels) << w.array("float", P + "NEAR", n, nears)
          << w.array("float", P + "FAR", n, fars);
    }
    o << "// The layer of this light's " << (cube ? "cube in uMapsCube[0]" : "view 0 in uMaps2D[0] (its views follow)")
      << ": 0 when it is the only " << (cube ? "point" : "directional or spot") << " light exported; with several,\n"
      << "// give each its own and set it here.\n"
      << "const float " << P << "FIRST_LAYER = 0.0;\n";
    o << "LightData " << p << "Data(int view) {\n"
      << "    LightData L;\n"
      << "    L.viewProjection = " << (cube ? "mat4(1.0)" : P + "VIEW_PROJECTION[view]") << ";\n"
      << "    L.position = vec4(" << w.vec("vec3", e.lightPosition) << ", 0.0);  // minus the render origin\n"
      << "    L.direction = vec4(" << w.vec("vec3", e.lightDirection) << ", 0.0);\n"
      << "    L.radiance = vec4(1.0);\n"
      << "    L.shadow = vec4(0.0, " << P << "FIRST_LAYER" << (cube ? "" : " + float(view)") << ", " << lit(1.0 / double(e.shadow.resolution))
      << ", " << lit(e.shadow.normalOffset) << ");  // map, layer, 1 / resolution, normal offset (texels)\n"
      << "    L.depth = vec4(" << (cube ? lit(e.nearPlane) + ", " + lit(e.farPlane) + ", " + lit(e.texelWorldPerDepth)
                                     : P + "NEAR[view], " + P + "FAR[view], " + P + "TEXEL_WORLD[view]")
      << ", " << flags << ".0);  // flags: 1 = reversed-Z, 2 = receiver-plane bias\n"
      << "    L.views = vec4(0.0, 0.0, " << lit(e.lightSpread) << ", 0.0);  // z: the light's size as the lookup spreads it\n"
      << "    return L;\n}\n";
    o << "\n// worldPos: the receiver's world position minus the render origin; n: its unit normal, facing the viewer's side"
      << (cube ? "" : "; view: which of the views above (0 for a single view)") << ".\n";
    // The pixel's screen derivatives: the receiver plane's, or the moments mips' level (the pixel's footprint).
    const bool derivatives = e.receiverPlane || mips;
    if (e.receiverPlane)
        o << "// positionDx, positionDy: dFdx(worldPos), dFdy(worldPos), taken where control flow is uniform.\n";
    else if (mips)
        o << "// positionDx, positionDy: dFdxFine(worldPos), dFdyFine(worldPos), taken where control flow is uniform: the\n"
          << "// mip level read is the pixel's footprint in the map (filter.momentMips).\n";
    o << "float " << p << "Shadow(" << (cube ? "" : "int view, ") << "vec3 worldPos, vec3 n"
      << (derivatives ? ", vec3 positionDx, vec3 positionDy" : "") << ") {\n"
      << "    LightData L = " << p << "Data(" << (cube ? "0" : "view") << ");\n";
    if (derivatives) o << "    gPositionDx = positionDx;\n    gPositionDy = positionDy;\n";
    if (cube)
        o << "    vec3 a = abs(worldPos - L.position.xyz);\n"
          << "    return shadowCube(L, worldPos + n * (L.shadow.w * (L.depth.z * max(a.x, max(a.y, a.z)))));\n";
    else if (spot)
        o << "    vec3 toLight = L.position.xyz - worldPos;\n"
          << "    vec3 l = toLight / max(length(toLight), 1e-20);\n"
          << "    float texelWorld = L.depth.z * dot(worldPos - L.position.xyz, L.direction.xyz);\n"
          << "    return shadow2D(L, worldPos + n * (L.shadow.w * texelWorld), -l, texelWorld);\n";
    else
        o << "    return shadow2D(L, worldPos + n * (L.shadow.w * L.depth.z), L.direction.xyz, L.depth.z);\n";
    o << "}\n";
    if (e.cascaded) o << cascadeSelection(e, w, p, P, /*viewSelectIncluded=*/true);
    return o.str();
}

MomentsPassShaders momentsPassShaders(const ShadowExport& e, bool vulkan) {
    const FilterTechnique& technique = filterTechnique(e.filter.kind);
    MomentsPassShaders out;
    if (!technique.moments) return out;
    const std::string format = "MOMENT_FORMAT " + e.momentFormat;
    // A perspective view's moments hold linear depth (shadow/linear_depth.glsl's momentDepth): its near and far
    // planes are the light's (a spot's one view, a point light's six faces); an orthographic view ignores them.
    out.convert = bakeUniforms(gl::preprocessedSource("moments.comp.glsl", {"CONVERT", format}, {},
                                                      {{"alias:technique", technique.moments->glslFile}}),
                               {{"uTechnique", vec4Text(e.techniqueUniforms)},
                                {"uSize", std::to_string(e.shadow.resolution)},
                                {"uReversedZ", e.reversedZ ? "true" : "false"},
                                {"uPerspective", e.perspective ? "true" : "false"},
                                {"uNearFar", "vec2(" + lit(e.nearPlane) + ", " + lit(e.farPlane) + ")"}});
    out.blur = bakeUniforms(gl::preprocessedSource("moments.comp.glsl", {format}),
                            {{"uSize", std::to_string(e.shadow.resolution)}});
    // uSize per level; uEmpty: "no caster" as the storage holds it (a level skips those texels).
    if (e.filter.momentMips)
        out.mips = bakeUniforms(gl::preprocessedSource("moments.comp.glsl", {"MIPS", format}),
                                {{"uEmpty", vec4Text(emptyMoments(e.filter))}});
    if (vulkan) {
        out.convert = vulkanUniforms(out.convert, 0, out.convertBindings);
        out.blur = vulkanUniforms(out.blur, 0, out.blurBindings);
        if (!out.mips.empty()) out.mips = vulkanUniforms(out.mips, 0, out.mipsBindings);
    }
    return out;
}

std::string shadowShaderCode(const ShadowExport& light, const ShaderTarget& target) {
    if (light.momentTechnique || light.ownLookup) {
        std::vector<VulkanBinding> bindings;
        const std::string glsl = techniqueLookupCode(light, target.vulkan, &bindings);
        if (target.language == ShaderLanguage::Glsl) return glsl;
        // HLSL: the renderer's lookup is GLSL; its text to translate (vecN -> floatN, texture() -> Sample...).
        std::string out = "// filter.kind " + std::string(filterTechnique(light.filter.kind).name) +
                          ": ShadowLab's lookup is GLSL; translate it (vecN -> floatN, mix -> lerp, texture() -> Sample /"
                          " SampleCmpLevelZero):\n";
        std::istringstream lines(glsl);
        for (std::string line; std::getline(lines, line);) out += "// " + line + "\n";
        return out;
    }
    return light.lightType == LightType::Point ? codeCube(light, target) : code2D(light, target);
}

}  // namespace shadowlab
