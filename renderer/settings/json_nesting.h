#pragma once
// How deep JSON text nests, found by a flat scan before any parser sees it: recursive walkers (tinygltf's, or a
// message that prints a value) overflow the stack on a few KiB of "[[[[...". One limit for presets, --set values
// and glTF files; no real file comes near it.
#include <cstddef>
#include <string>
#include <string_view>

namespace shadowlab {

inline constexpr std::size_t kMaxJsonNesting = 64;

// "" when `text` nests at most kMaxJsonNesting arrays/objects deep; else "line:column: JSON nests deeper than 64
// levels" at the first bracket past the limit. Brackets inside strings do not count; syntax is not checked.
std::string checkJsonNesting(std::string_view text);

}  // namespace shadowlab
