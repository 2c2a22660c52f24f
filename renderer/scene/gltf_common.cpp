#include "scene/gltf_common.h"

#include <cstdio>

namespace shadowlab::gltf {

std::string str(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        if (!line.empty()) out.push_back(std::move(line));
        start = end + 1;
    }
    return out;
}

std::string joinLines(const std::string& text) {
    std::string out;
    constexpr std::size_t maxLine = 200;
    for (std::string l : splitLines(text)) {
        if (l.size() > maxLine) l = l.substr(0, maxLine) + "... (" + str(l.size()) + " bytes)";
        out += (out.empty() ? "" : "; ") + l;
    }
    return out;
}

}  // namespace shadowlab::gltf
