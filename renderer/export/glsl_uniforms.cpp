#include "export/glsl_uniforms.h"

#include <algorithm>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace shadowlab {

namespace {

// A declaration line: indentation, an optional layout(...), qualifiers, type, name, an optional [N], the rest.
const std::regex& declaration() {
    static const std::regex r(
        R"(^(\s*)(?:layout\s*\(([^)]*)\)\s*)?uniform\s+((?:(?:readonly|writeonly|coherent|restrict|highp|mediump|lowp)\s+)*)(\w+)\s+(\w+)(\[\w+\])?\s*;(.*)$)");
    return r;
}

bool opaque(const std::string& type) {
    return type.rfind("sampler", 0) == 0 || type.rfind("image", 0) == 0 || type.rfind("texture", 0) == 0;
}

template <typename Each>
std::string eachLine(const std::string& text, Each each) {
    std::istringstream in(text);
    std::string out;
    for (std::string line; std::getline(in, line);) out += each(line) + "\n";
    return out;
}

}  // namespace

std::string bakeUniforms(const std::string& glsl, const std::map<std::string, std::string>& values) {
    std::set<std::string> baked;
    const std::string out = eachLine(glsl, [&](const std::string& line) {
        std::smatch m;
        if (!std::regex_match(line, m, declaration()) || m[2].matched) return line;
        const auto value = values.find(m[5]);
        if (value == values.end()) return line;
        baked.insert(value->first);
        return m[1].str() + "const " + m[4].str() + " " + m[5].str() + m[6].str() + " = " + value->second + ";" +
               m[7].str();
    });
    for (const auto& [name, value] : values)
        if (!baked.count(name))
            throw std::runtime_error("the exported shader declares no loose uniform " + name + " to set to " + value);
    return out;
}

std::string vulkanUniforms(const std::string& glsl, int firstBinding, std::vector<VulkanBinding>& bindings) {
    // Bindings the text already names (an image's layout(..., binding = 0)).
    static const std::regex bindingOf(R"(binding\s*=\s*(\d+))");
    int next = firstBinding;
    {
        std::istringstream in(glsl);
        for (std::string line; std::getline(in, line);) {
            std::smatch m, b;
            const std::string layout = std::regex_match(line, m, declaration()) && m[2].matched ? m[2].str() : "";
            if (std::regex_search(layout, b, bindingOf)) next = std::max(next, std::stoi(b[1]) + 1);
        }
    }
    return eachLine(glsl, [&](const std::string& line) {
        std::smatch m;
        if (!std::regex_match(line, m, declaration())) return line;
        const std::string qualifiers = m[3], type = m[4], name = m[5], array = m[6], rest = m[7];
        VulkanBinding b;
        b.name = name;
        if (m[2].matched) {  // an image with its format and binding: kept as written
            std::smatch n;
            const std::string layout = m[2];
            if (!std::regex_search(layout, n, bindingOf))
                throw std::runtime_error("the exported shader's " + name + " has a layout without a binding");
            b.binding = std::stoi(n[1]);
            b.declaration = qualifiers + type + " " + name + array;
            bindings.push_back(b);
            return line;
        }
        b.binding = next++;
        if (opaque(type)) {
            b.declaration = type + " " + name + array;
            bindings.push_back(b);
            return m[1].str() + "layout(set = 0, binding = " + std::to_string(b.binding) + ") uniform " + qualifiers +
                   type + " " + name + array + ";" + rest;
        }
        b.block = true;
        b.declaration = "std140 block ShadowLab_" + name + " { " + type + " " + name + array + "; }";
        bindings.push_back(b);
        return m[1].str() + "layout(std140, set = 0, binding = " + std::to_string(b.binding) + ") uniform ShadowLab_" +
               name + " { " + type + " " + name + array + "; };" + rest;
    });
}

}  // namespace shadowlab
