#include "settings/json_nesting.h"

namespace shadowlab {

std::string checkJsonNesting(std::string_view text) {
    std::size_t depth = 0, line = 1, lineStart = 0;
    bool inString = false, escaped = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
            continue;
        }
        if (c == '"') inString = true;
        else if (c == '\n') {
            ++line;
            lineStart = i + 1;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonNesting)
                return std::to_string(line) + ":" + std::to_string(i - lineStart + 1) + ": JSON nests deeper than " +
                       std::to_string(kMaxJsonNesting) + " levels (the limit)";
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return {};
}

}  // namespace shadowlab
