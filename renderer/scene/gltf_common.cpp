#include "scene/gltf_common.h"

namespace shadowlab::gltf {

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
    for (const std::string& l : splitLines(text)) out += (out.empty() ? "" : "; ") + l;
    return out;
}

}  // namespace shadowlab::gltf
