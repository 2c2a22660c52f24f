#pragma once
// JSON text to a value, for every file a user writes by hand (presets, check case lists): the nesting limit first
// (json_nesting.h), then nlohmann's parser with the syntax error's line and column.
#include <nlohmann/json.hpp>

#include <string>

namespace shadowlab {

// "" with `out` set, or "line:column: JSON nests deeper than 64 levels" / "line:column: invalid JSON: what".
std::string parseJsonText(const std::string& text, nlohmann::json& out);

}  // namespace shadowlab
