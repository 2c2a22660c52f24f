#pragma once
// Text carried inside a PNG: iTXt chunks (UTF-8, written uncompressed; zlib-compressed ones are read too), the place a
// screenshot keeps the preset it was rendered with. stb_image_write cannot add chunks, so they are inserted into the
// encoded bytes, after IHDR.
#include <cstdint>
#include <functional>
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

// Reads `size` bytes at `offset` of a PNG into `out`; false when it cannot (past the end, a read error).
using PngByteReader = std::function<bool(std::uint64_t offset, std::size_t size, std::uint8_t* out)>;

// The text of the first tEXt or iTXt chunk named `keyword` (an iTXt's zlib-compressed text is inflated), found by
// walking the chunk headers: only text chunks are read, the pixels (IDAT) are skipped, so the PNG's size is no limit.
// nullopt when there is none (or the bytes are not a PNG); chunks with a wrong CRC are skipped. A text chunk of the
// keyword that is longer than `maxText` bytes, or cannot be inflated, is nullopt with *why (when given) saying so.
std::optional<std::string> findPngText(const PngByteReader& read, std::uint64_t size, const std::string& keyword,
                                       std::size_t maxText, std::string* why = nullptr);
// The same over bytes in memory.
std::optional<std::string> findPngText(const std::uint8_t* bytes, std::size_t size, const std::string& keyword);

// A zlib stream (RFC 1950, as an iTXt chunk's compressed text) inflated; nullopt when it is corrupt or inflates to
// more than maxBytes. Implemented with image_io's stb copy, the one holding the zlib decoder.
std::optional<std::vector<std::uint8_t>> inflateZlib(const std::uint8_t* data, std::size_t size, std::size_t maxBytes);

}  // namespace shadowlab
