// A PNG that carries its preset: iTXt chunks inserted after IHDR with a correct CRC, the picture unchanged, the
// preset read back equal from the picture, and a clear message for a PNG without one.
#include "image/image_io.h"
#include "image/png_text.h"
#include "settings/preset_io.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace shadowlab;
namespace fs = std::filesystem;

namespace {

struct TempFolder {
    fs::path path;
    TempFolder() {
        path = fs::temp_directory_path() / ("shadowlab-pngpreset-" + std::to_string(::getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempFolder() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::string operator/(const std::string& name) const { return (path / name).string(); }
};

std::vector<std::uint8_t> readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::uint8_t> gradient(int w, int h) {
    std::vector<std::uint8_t> rgba(std::size_t(w) * h * 4);
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = std::uint8_t(i * 7 % 251);
    return rgba;
}

}  // namespace

TEST(PngPreset, TextChunkFollowsIhdrWithAValidCrcAndThePictureIsUnchanged) {
    TempFolder dir;
    const std::vector<std::uint8_t> rgba = gradient(13, 7);
    ASSERT_EQ(writePng(dir / "plain.png", 13, 7, 4, rgba.data(), false), "");
    ASSERT_EQ(writePng(dir / "text.png", 13, 7, 4, rgba.data(), false, {{"shadowlab.test", "héllo {\"a\": 1}"}}), "");
    const std::vector<std::uint8_t> bytes = readBytes(dir / "text.png");
    // Signature (8) + IHDR (25), then our chunk.
    ASSERT_GT(bytes.size(), 41u);
    EXPECT_EQ(std::string(bytes.begin() + 37, bytes.begin() + 41), "iTXt");
    EXPECT_EQ(findPngText(bytes.data(), bytes.size(), "shadowlab.test"), "héllo {\"a\": 1}");
    EXPECT_EQ(findPngText(bytes.data(), bytes.size(), "shadowlab.other"), std::nullopt);
    // The CRC is PNG's: a flipped text byte makes the chunk unreadable rather than wrong.
    std::vector<std::uint8_t> tampered = bytes;
    tampered[41 + 20] ^= 0x01;
    EXPECT_EQ(findPngText(tampered.data(), tampered.size(), "shadowlab.test"), std::nullopt);
    // The pixels decode the same as without the chunk.
    std::optional<PngImage> a = readPng(dir / "plain.png"), b = readPng(dir / "text.png");
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->pixels, b->pixels);
    EXPECT_EQ(a->pixels, rgba);
    // Bad keywords are refused with the keyword named, and nothing is written.
    const std::string error = writePng(dir / "bad.png", 13, 7, 4, rgba.data(), false, {{"", "x"}});
    EXPECT_NE(error.find("not a PNG text keyword"), std::string::npos) << error;
    EXPECT_FALSE(fs::exists(dir / "bad.png"));
}

TEST(PngPreset, APresetLoadsBackFromTheScreenshotThatCarriesIt) {
    TempFolder dir;
    Settings s;
    s.lights[0].shadow.depthBias = 3.25f;
    s.filter.kind = FilterKind::Poisson;
    s.camera.autoFrame = false;
    s.camera.position = {1.5, 2.0, -4.0};
    s.view = ViewMode::Shadow;
    const std::vector<std::uint8_t> rgba = gradient(8, 8);
    ASSERT_EQ(writePng(dir / "shot.png", 8, 8, 4, rgba.data(), true, presetPngText(s, "builtin:fence")), "");
    PresetLoadResult r = loadPresetFile(dir / "shot.png");
    ASSERT_TRUE(r.settings) << (r.errors.empty() ? "" : r.errors.front());
    EXPECT_EQ(*r.settings, s);
    EXPECT_EQ(r.scene, "builtin:fence");

    // A PNG without the chunk: a message naming the file and what is missing.
    ASSERT_EQ(writePng(dir / "plain.png", 8, 8, 4, rgba.data(), true), "");
    PresetLoadResult none = loadPresetFile(dir / "plain.png");
    EXPECT_FALSE(none.settings);
    ASSERT_EQ(none.errors.size(), 1u);
    EXPECT_NE(none.errors.front().find(dir / "plain.png"), std::string::npos) << none.errors.front();
    EXPECT_NE(none.errors.front().find("carries no ShadowLab preset"), std::string::npos) << none.errors.front();
}

namespace {

std::uint32_t pngCrc(const std::uint8_t* data, std::size_t size) {
    std::uint32_t crc = 0xffffffffu;
    for (std::size_t i = 0; i < size; ++i) {
        crc ^= data[i];
        for (int k = 0; k < 8; ++k) crc = (crc & 1u) ? 0xedb88320u ^ (crc >> 1) : crc >> 1;
    }
    return ~crc;
}

void appendBE32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(std::uint8_t(v >> shift));
}

// A whole chunk: length, type, data, CRC.
std::vector<std::uint8_t> pngChunk(const char* type, const std::vector<std::uint8_t>& data) {
    std::vector<std::uint8_t> out;
    out.reserve(data.size() + 12);
    appendBE32(out, std::uint32_t(data.size()));
    for (int i = 0; i < 4; ++i) out.push_back(std::uint8_t(type[i]));
    out.insert(out.end(), data.begin(), data.end());
    appendBE32(out, pngCrc(out.data() + 4, data.size() + 4));
    return out;
}

// `text` as a zlib stream of stored (uncompressed) deflate blocks: valid zlib that needs no compressor in the test.
std::vector<std::uint8_t> zlibStored(const std::string& text) {
    std::vector<std::uint8_t> out = {0x78, 0x01};
    std::size_t at = 0;
    do {
        const std::size_t n = std::min<std::size_t>(65535, text.size() - at);
        const bool last = at + n == text.size();
        out.push_back(last ? 1 : 0);  // BFINAL, BTYPE 00 (stored)
        out.insert(out.end(), {std::uint8_t(n), std::uint8_t(n >> 8), std::uint8_t(~n), std::uint8_t(~n >> 8)});
        out.insert(out.end(), text.begin() + std::ptrdiff_t(at), text.begin() + std::ptrdiff_t(at + n));
        at += n;
    } while (at < text.size());
    std::uint32_t a = 1, b = 0;  // Adler-32
    for (unsigned char c : text) {
        a = (a + c) % 65521;
        b = (b + a) % 65521;
    }
    appendBE32(out, b << 16 | a);
    return out;
}

Settings tunedSettings() {
    Settings s;
    s.lights[0].shadow.depthBias = 2.5f;
    s.lights[0].shadow.resolution = 1024;
    s.filter.kind = FilterKind::Poisson;
    return s;
}

}  // namespace

// A 16384x16383 screenshot is about 22 MB: more than the preset file limit, yet it carries its preset. Only IHDR and
// the text chunks are read, so the test writes a sparse 17 MiB IDAT (never read, never decoded).
TEST(PngPreset, AScreenshotLargerThanThePresetLimitLoadsItsPreset) {
    TempFolder dir;
    std::vector<std::uint8_t> png(std::begin(kPngSignature), std::end(kPngSignature));
    std::vector<std::uint8_t> ihdr;
    appendBE32(ihdr, 16384);
    appendBE32(ihdr, 16383);
    ihdr.insert(ihdr.end(), {8, 6, 0, 0, 0});  // 8-bit RGBA
    const std::vector<std::uint8_t> ihdrChunk = pngChunk("IHDR", ihdr);
    png.insert(png.end(), ihdrChunk.begin(), ihdrChunk.end());
    const Settings s = tunedSettings();
    ASSERT_EQ(insertPngText(png, presetPngText(s, "builtin:fence")), "");
    const std::uint32_t idatLength = std::uint32_t(kMaxPresetBytes) + (1u << 20);
    appendBE32(png, idatLength);
    png.insert(png.end(), {'I', 'D', 'A', 'T'});
    const std::string path = dir / "huge.png";
    {
        std::ofstream out(path, std::ios::binary);
        out.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
        out.seekp(std::streamoff(png.size()) + idatLength);  // a hole: the pixels are never read
        const std::vector<std::uint8_t> tail = [] {
            std::vector<std::uint8_t> t = {0, 0, 0, 0};  // IDAT's CRC (not checked: IDAT is skipped)
            const std::vector<std::uint8_t> iend = pngChunk("IEND", {});
            t.insert(t.end(), iend.begin(), iend.end());
            return t;
        }();
        out.write(reinterpret_cast<const char*>(tail.data()), std::streamsize(tail.size()));
    }
    ASSERT_GT(fs::file_size(path), kMaxPresetBytes);
    const PresetLoadResult r = loadPresetFile(path);
    ASSERT_TRUE(r.settings) << (r.errors.empty() ? "" : r.errors.front());
    EXPECT_EQ(*r.settings, s);
    EXPECT_EQ(r.scene, "builtin:fence");
}

// iTXt with compression flag 1 (zlib), as other tools write it, is inflated and read.
TEST(PngPreset, ACompressedITxtPresetIsRead) {
    TempFolder dir;
    const std::vector<std::uint8_t> rgba = gradient(8, 8);
    ASSERT_EQ(writePng(dir / "plain.png", 8, 8, 4, rgba.data(), false), "");
    std::vector<std::uint8_t> png = readBytes(dir / "plain.png");
    const Settings s = tunedSettings();
    const std::string preset = presetPngText(s, "builtin:fence").front().second;
    std::vector<std::uint8_t> data(kPresetPngKeyword, kPresetPngKeyword + std::strlen(kPresetPngKeyword));
    data.insert(data.end(), {0, 1, 0, 0, 0});  // NUL, compressed, zlib, no language, no translated keyword
    const std::vector<std::uint8_t> stream = zlibStored(preset);
    data.insert(data.end(), stream.begin(), stream.end());
    const std::vector<std::uint8_t> chunk = pngChunk("iTXt", data);
    png.insert(png.begin() + 33, chunk.begin(), chunk.end());  // after the signature and IHDR
    {
        std::ofstream out(dir / "compressed.png", std::ios::binary);
        out.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
    }
    const PresetLoadResult r = loadPresetFile(dir / "compressed.png");
    ASSERT_TRUE(r.settings) << (r.errors.empty() ? "" : r.errors.front());
    EXPECT_EQ(*r.settings, s);

    EXPECT_EQ(findPngText(png.data(), png.size(), kPresetPngKeyword), preset);
}

// Inflating is bounded by the limit, not by the chunk's size: 121 bytes of zlib (Python's zlib.compress of 100000
// 'a', level 9) that inflate past a 1000-byte limit are refused with the reason, never inflated whole.
TEST(PngPreset, ACompressedTextThatInflatesPastTheLimitIsRefused) {
    const std::uint8_t head[] = {0x78, 0xda, 0xed, 0xc1, 0x31, 0x01, 0x00, 0x00, 0x00, 0xc2,
                                 0xa0, 0xac, 0xeb, 0x5f, 0xc2, 0x1a, 0x1e, 0x40, 0x01};
    const std::uint8_t tail[] = {0xaf, 0x06, 0x79, 0x66, 0x0b, 0x4d};
    std::vector<std::uint8_t> data = {'t', 'e', 'x', 't', 0, 1, 0, 0, 0};
    data.reserve(data.size() + sizeof head + 96 + sizeof tail);
    for (std::uint8_t b : head) data.push_back(b);
    data.resize(data.size() + 96, 0x00);
    for (std::uint8_t b : tail) data.push_back(b);
    std::vector<std::uint8_t> png(std::begin(kPngSignature), std::end(kPngSignature));
    const std::vector<std::uint8_t> chunk = pngChunk("iTXt", data);
    png.insert(png.end(), chunk.begin(), chunk.end());
    const PngByteReader read = [&](std::uint64_t offset, std::size_t n, std::uint8_t* out) {
        if (offset > png.size() || n > png.size() - offset) return false;
        std::memcpy(out, png.data() + offset, n);
        return true;
    };
    std::string why;
    EXPECT_EQ(findPngText(read, png.size(), "text", 1000, &why), std::nullopt);
    EXPECT_NE(why.find("inflates to more than the limit of 1000 bytes"), std::string::npos) << why;
    EXPECT_EQ(findPngText(read, png.size(), "text", 100000, &why), std::string(100000, 'a'));
}
