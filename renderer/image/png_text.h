#pragma once
// Text carried inside a PNG: iTXt chunks (UTF-8, uncompressed), the place a screenshot keeps the preset it was
// rendered with. stb_image_write cannot add chunks, so they are inserted into the encoded bytes, after IHDR.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace shadowlab {

inline constexpr std::uint8_t kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

// (keyword, text) pairs to carry in a PNG.
using PngText = std::vector<std::pair<std::string, std::string>>;

bool isPng(const std::uint8_t* bytes, std::size_t size);

// Inserts one iTXt chunk per (keyword, text) right after IHDR. Keywords: 1..79 Latin-1 printable bytes (PNG's
// rule). Returns "" or why not (not a PNG, a bad keyword); `png` is untouched on error.
std::string insertPngText(std::vector<std::uint8_t>& png, const PngText& entries);

// The text of the first tEXt or uncompressed iTXt chunk named `keyword`; nullopt when there is none (or the
// bytes are not a PNG). Chunks with a wrong CRC are skipped.
std::optional<std::string> findPngText(const std::uint8_t* bytes, std::size_t size, const std::string& keyword);

}  // namespace shadowlab
