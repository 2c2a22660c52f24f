// Image files: PNG and EXR depth round trips (with the GL bottom-up flip), exact float depth, clear errors.
#include "image/image_io.h"
#include "image/picture_size.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

using namespace shadowlab;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct TempFolder {
    fs::path path;
    TempFolder() {
        path = fs::temp_directory_path() / ("shadowlab-images-" + std::to_string(::getpid()) + "-" +
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

// Row r of an image stored bottom-up (as glReadPixels gives it) is row height-1-r of the file.
template <class T>
std::vector<T> flipRows(const std::vector<T>& pixels, int width, int height, int channels) {
    std::vector<T> out(pixels.size());
    const std::size_t row = static_cast<std::size_t>(width) * channels;
    for (int y = 0; y < height; ++y)
        std::copy_n(pixels.begin() + static_cast<std::ptrdiff_t>(y * row), row,
                    out.begin() + static_cast<std::ptrdiff_t>((height - 1 - y) * row));
    return out;
}

}  // namespace

TEST(ImageIo, PngRoundTripsEveryChannelCountWithAndWithoutFlip) {
    TempFolder dir;
    const int w = 7, h = 5;
    for (int channels = 1; channels <= 4; ++channels) {
        std::vector<std::uint8_t> pixels(static_cast<std::size_t>(w) * h * channels);
        for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<std::uint8_t>(i * 37 + 11);
        for (bool flip : {false, true}) {
            SCOPED_TRACE("channels " + std::to_string(channels) + (flip ? " flipped" : ""));
            const std::string path = dir / ("img" + std::to_string(channels) + (flip ? "f" : "") + ".png");
            ASSERT_EQ(writePng(path, w, h, channels, pixels.data(), flip), "");
            std::string error;
            auto image = readPng(path, &error);
            ASSERT_TRUE(image) << error;
            EXPECT_EQ(image->width, w);
            EXPECT_EQ(image->height, h);
            EXPECT_EQ(image->channels, channels);
            EXPECT_EQ(image->pixels, flip ? flipRows(pixels, w, h, channels) : pixels);
        }
    }
}

TEST(ImageIo, PngErrorsAreClear) {
    TempFolder dir;
    std::vector<std::uint8_t> pixels(16 * 3, 0);
    std::string e = writePng(dir / "missing/x.png", 4, 4, 3, pixels.data(), false);
    EXPECT_TRUE(contains(e, "cannot write PNG '" + dir / "missing/x.png" + "'")) << e;
    EXPECT_TRUE(contains(e, "does not exist")) << e;
    EXPECT_FALSE(fs::exists(dir.path / "missing"));  // folders are never created
    EXPECT_FALSE(writePng(dir / "x.png", 0, 4, 3, pixels.data(), false).empty());
    EXPECT_FALSE(writePng(dir / "x.png", 4, 4, 5, pixels.data(), false).empty());
    EXPECT_FALSE(writePng(dir / "x.png", 4, 4, 3, nullptr, false).empty());
    EXPECT_FALSE(writePng(dir.path.string(), 4, 4, 3, pixels.data(), false).empty());  // a folder
    EXPECT_FALSE(fs::exists(dir.path / "x.png"));

    std::string error;
    EXPECT_FALSE(readPng(dir / "nothing.png", &error));
    EXPECT_TRUE(contains(error, "nothing.png")) << error;
}

TEST(ImageIo, ExrDepthRoundTripsBitExact) {
    TempFolder dir;
    // Taller than the writer's 64-row band, odd sizes, values that any lossy path would change.
    const int w = 13, h = 150;
    std::vector<float> depth(static_cast<std::size_t>(w) * h);
    for (std::size_t i = 0; i < depth.size(); ++i) depth[i] = static_cast<float>(i) / static_cast<float>(depth.size());
    depth[0] = 0.1f;
    depth[1] = 1e-7f;
    depth[2] = std::numeric_limits<float>::denorm_min();
    depth[3] = 1.0f;
    depth[4] = std::nextafter(1.0f, 0.0f);
    depth[5] = 0.0f;
    for (bool flip : {false, true}) {
        SCOPED_TRACE(flip ? "flipped" : "not flipped");
        const std::string path = dir / (flip ? "depth-flipped.exr" : "depth.exr");
        ASSERT_EQ(writeExrDepth(path, w, h, depth.data(), flip), "");
        std::string error;
        auto image = readExrDepth(path, &error);
        ASSERT_TRUE(image) << error;
        EXPECT_EQ(image->width, w);
        EXPECT_EQ(image->height, h);
        const std::vector<float> expected = flip ? flipRows(depth, w, h, 1) : depth;
        ASSERT_EQ(image->depth.size(), expected.size());
        EXPECT_EQ(std::memcmp(image->depth.data(), expected.data(), expected.size() * sizeof(float)), 0);
    }
}

TEST(ImageIo, ExrErrorsAreClear) {
    TempFolder dir;
    std::vector<float> depth(16, 0.5f);
    std::string e = writeExrDepth(dir / "missing/d.exr", 4, 4, depth.data(), false);
    EXPECT_TRUE(contains(e, "cannot write EXR '" + dir / "missing/d.exr" + "'")) << e;
    EXPECT_TRUE(contains(e, "does not exist")) << e;
    EXPECT_FALSE(writeExrDepth(dir / "d.exr", 4, 0, depth.data(), false).empty());
    EXPECT_FALSE(writeExrDepth(dir / "d.exr", 4, 4, nullptr, false).empty());
    EXPECT_FALSE(writeExrDepth(dir.path.string(), 4, 4, depth.data(), false).empty());  // a folder

    std::string error;
    EXPECT_FALSE(readExrDepth(dir / "nothing.exr", &error));
    EXPECT_TRUE(contains(error, "nothing.exr")) << error;
    std::ofstream(dir / "garbage.exr") << "not an exr";
    EXPECT_FALSE(readExrDepth(dir / "garbage.exr", &error));
    EXPECT_TRUE(contains(error, "garbage.exr")) << error;
}

// The picture limits, as figures: stb_image_write's PNG encoder holds (width x channels + 1) x height bytes in an int
// that must stay under INT_MAX / 2 (16384x16383 RGBA fits, 16384x16384 is 16 KiB over), and a picture's pixels take
// at most 1 GiB (a point light's 8192² faces as one 32768x24576 float cross take 3 GiB).
TEST(PictureSize, ThePngWriterLimitAndThePictureLimitAreSaidWithTheirFigures) {
    EXPECT_EQ(pictureSizeError({16384, 16383, 4, 4, true, {}}), "");
    EXPECT_EQ(pictureSizeError({16384, 16384, 4, 4, true, {}}),
              "a 16384x16384 PNG of 4 channels needs 1073758208 bytes of encoder rows ((width x channels + 1) x "
              "height), more than the PNG writer's limit of 1073741823 (it counts in int); at this width at most "
              "16383 rows fit");
    EXPECT_EQ(pictureSizeError({16384, 16384, 4, 4, false, {}}), "");  // an EXR has no PNG encoder
    EXPECT_EQ(pictureSizeError({32768, 24576, 1, 4, true, "a cross"}),
              "a 32768x24576 picture (a cross) needs 3221225472 bytes (4 a pixel), more than the limit of 1073741824 "
              "bytes for a picture (16384x16384 RGBA)");
    EXPECT_EQ(pictureSizeError({16384, 12288, 1, 4, true, {}}), "");  // 4096² faces: a 16384x12288 cross
    // writePng says the same before it reads a pixel.
    const std::uint8_t pixel[4] = {};
    EXPECT_NE(writePng("/nonexistent/never.png", 16384, 16384, 4, pixel, false).find("1073758208 bytes of encoder rows"),
              std::string::npos);
}
