#include "settings/json_text.h"

#include "settings/json_nesting.h"

#include <algorithm>

namespace shadowlab {

using nlohmann::json;

namespace {

// nlohmann's DOM parser, but keeping the byte position of a syntax error (an out_of_range 406 "number overflow"
// carries none in its message).
class PositionedDomParser : public nlohmann::detail::json_sax_dom_parser<json> {
public:
    explicit PositionedDomParser(json& result) : json_sax_dom_parser(result, false) {}
    template <class Exception>
    bool parse_error(std::size_t position, const std::string& /*lastToken*/, const Exception& ex) {
        failed = true;
        errorPosition = position;
        errorMessage = ex.what();
        return false;
    }
    bool failed = false;
    std::size_t errorPosition = 0;
    std::string errorMessage;
};

// "" or "line:column: invalid JSON: what".
std::string parseSyntax(const std::string& text, json& out) {
    PositionedDomParser handler(out);
    bool ok = json::sax_parse(text, &handler);
    if (ok && !handler.failed) return {};

    // position = characters read, so the offending character is at position - 1.
    std::size_t at = std::min(handler.errorPosition > 0 ? handler.errorPosition - 1 : 0, text.size());
    std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
    std::size_t lineStart = at == 0 ? std::string::npos : text.rfind('\n', at - 1);
    std::size_t column = lineStart == std::string::npos ? at + 1 : at - lineStart;

    // "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ..." -> "syntax error ...".
    std::string what = handler.errorMessage;
    if (auto c = what.find("column "); c != std::string::npos) {
        if (auto colon = what.find(": ", c); colon != std::string::npos) what = what.substr(colon + 2);
    } else if (auto bracket = what.find("] "); bracket != std::string::npos) {
        what = what.substr(bracket + 2);
    }
    return std::to_string(line) + ":" + std::to_string(column) + ": invalid JSON: " + what;
}

}  // namespace

std::string parseJsonText(const std::string& text, json& out) {
    // Before parsing: what follows walks the value recursively in places (messages that print it).
    if (std::string error = checkJsonNesting(text); !error.empty()) return error;
    return parseSyntax(text, out);
}

}  // namespace shadowlab
