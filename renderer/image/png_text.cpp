#include "image/png_text.h"

#include <zlib.h>

#include <cstring>

namespace shadowlab {

namespace {

// PNG's CRC-32 (ISO 3309) over the chunk type and data: zlib's.
std::uint32_t chunkCrc(const std::uint8_t* data, std::size_t size) {
    return std::uint32_t(crc32_z(0, data, size));
}

std::uint32_t readBE32(const std::uint8_t* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | std::uint32_t(p[3]);
}

void appendBE32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(v >> shift));
}

std::vector<std::uint8_t> chunk(const char type[4], const std::vector<std::uint8_t>& data) {
    std::vector<std::uint8_t> out;
    appendBE32(out, std::uint32_t(data.size()));
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    appendBE32(out, chunkCrc(out.data() + 4, data.size() + 4));
    return out;
}

bool validKeyword(const std::string& k) {
    if (k.empty() || k.size() > 79 || k.front() == ' ' || k.back() == ' ') return false;
    for (unsigned char c : k)
        if (!((c >= 32 && c <= 126) || c >= 161)) return false;
    return true;
}

}  // namespace

bool isPng(const std::uint8_t* bytes, std::size_t size) {
    return size >= sizeof kPngSignature && std::memcmp(bytes, kPngSignature, sizeof kPngSignature) == 0;
}

std::string insertPngText(std::vector<std::uint8_t>& png, const PngText& entries) {
    // Signature, then IHDR: length 13, "IHDR", 13 bytes, CRC.
    constexpr std::size_t kAfterIhdr = 8 + 4 + 4 + 13 + 4;
    if (!isPng(png.data(), png.size()) || png.size() < kAfterIhdr || std::memcmp(png.data() + 12, "IHDR", 4) != 0)
        return "not a PNG with an IHDR chunk first";
    std::vector<std::uint8_t> chunks;
    for (const auto& [keyword, text] : entries) {
        if (!validKeyword(keyword)) return "'" + keyword + "' is not a PNG text keyword (1-79 printable bytes)";
        // iTXt: keyword NUL, compression flag 0, method 0, language tag "" NUL, translated keyword "" NUL, text.
        std::vector<std::uint8_t> data(keyword.begin(), keyword.end());
        data.insert(data.end(), {0, 0, 0, 0, 0});
        data.insert(data.end(), text.begin(), text.end());
        const std::vector<std::uint8_t> c = chunk("iTXt", data);
        chunks.insert(chunks.end(), c.begin(), c.end());
    }
    png.insert(png.begin() + static_cast<long>(kAfterIhdr), chunks.begin(), chunks.end());
    return {};
}

std::optional<std::string> findPngText(const PngByteReader& read, std::uint64_t size, const std::string& keyword,
                                       std::size_t maxText, std::string* why) {
    std::uint8_t head[8];
    if (size < sizeof head || !read(0, sizeof head, head) || !isPng(head, sizeof head)) return std::nullopt;
    std::uint64_t at = sizeof kPngSignature;
    std::vector<std::uint8_t> chunkBytes;  // type, data, CRC of a text chunk
    while (at + 12 <= size) {
        if (!read(at, 8, head)) return std::nullopt;
        const std::uint32_t length = readBE32(head);
        if (length > size - at - 12) return std::nullopt;  // truncated or corrupt: stop, never read past the end
        const bool tEXt = std::memcmp(head + 4, "tEXt", 4) == 0, iTXt = std::memcmp(head + 4, "iTXt", 4) == 0;
        if (std::memcmp(head + 4, "IEND", 4) == 0) break;
        if ((tEXt || iTXt) && length > keyword.size()) {
            const std::size_t keyLength = keyword.size() + 1;
            std::uint8_t key[80];
            if (keyLength > sizeof key || !read(at + 8, keyLength, key)) return std::nullopt;
            if (std::memcmp(key, keyword.data(), keyword.size()) == 0 && key[keyword.size()] == 0) {
                if (length > maxText) {
                    if (why) *why = "its '" + keyword + "' text chunk is " + std::to_string(length) +
                                    " bytes, more than the limit of " + std::to_string(maxText);
                    return std::nullopt;
                }
                chunkBytes.resize(std::size_t(length) + 8);
                if (!read(at + 4, chunkBytes.size(), chunkBytes.data())) return std::nullopt;
                const std::uint8_t* data = chunkBytes.data() + 4;
                if (chunkCrc(chunkBytes.data(), std::size_t(length) + 4) == readBE32(data + length)) {
                    std::size_t p = keyLength;
                    if (tEXt) return std::string(reinterpret_cast<const char*>(data + p), length - p);
                    // iTXt: compression flag, method (0 = zlib), language tag NUL, translated keyword NUL, the text.
                    if (p + 2 <= length && data[p] <= 1) {
                        const bool compressed = data[p] == 1;
                        const bool zlib = data[p + 1] == 0;
                        p += 2;
                        for (int field = 0; field < 2 && p < length; ++field) {
                            while (p < length && data[p] != 0) ++p;
                            ++p;
                        }
                        if (p <= length && !compressed)
                            return std::string(reinterpret_cast<const char*>(data + p), length - p);
                        if (p <= length && zlib) {
                            if (std::optional<std::vector<std::uint8_t>> text = inflateZlib(data + p, length - p, maxText))
                                return std::string(text->begin(), text->end());
                            if (why) *why = "its compressed '" + keyword + "' text chunk is corrupt or inflates to " +
                                            "more than the limit of " + std::to_string(maxText) + " bytes";
                            return std::nullopt;
                        }
                    }
                }
            }
        }
        at += std::uint64_t(length) + 12;
    }
    return std::nullopt;
}

std::optional<std::string> findPngText(const std::uint8_t* bytes, std::size_t size, const std::string& keyword) {
    const PngByteReader read = [&](std::uint64_t offset, std::size_t n, std::uint8_t* out) {
        if (offset > size || n > size - offset) return false;
        std::memcpy(out, bytes + offset, n);
        return true;
    };
    return findPngText(read, size, keyword, size);
}

}  // namespace shadowlab
