// A PNG that carries its preset: iTXt chunks inserted after IHDR with a correct CRC, the picture unchanged, the
// preset read back equal from the picture, and a clear message for a PNG without one.
#include "image/image_io.h"
#include "image/png_text.h"
#include "settings/preset_io.h"

#include <gtest/gtest.h>

#include <unistd.h>

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
