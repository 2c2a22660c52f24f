// Screenshots: a timestamped PNG of the view that decodes to what was rendered, never overwriting an earlier one,
// optionally the shadow map as float EXR + PNG beside it, and failures that say why.
#include "gl_fixture.h"

#include "../support/as_unprivileged_user.h"
#include "frame/screenshot.h"

#include <sys/mount.h>
#include <unistd.h>

#include <ctime>
#include <fstream>
#include <set>

namespace shadowlab::test {
namespace {

namespace fs = std::filesystem;

class Screenshot : public GlTest {
protected:
    void SetUp() override {
        GlTest::SetUp();
        dir_ = fs::path(SHADOWLAB_TEST_OUTPUT) / "gl" / "screenshots" /
               ::testing::UnitTest::GetInstance()->current_test_info()->name();
        ::umount((dir_ / "full-disk").c_str());  // left mounted only if an earlier run crashed mid-test
        fs::remove_all(dir_);
        scene_ = loadBuiltin("textbook");
        ASSERT_EQ(target_.resize(320, 200), "");
        const Settings settings = loadShippedPreset("default");
        renderer_ = std::make_unique<Renderer>();
        stats_ = renderer_->render(scene_, settings, cameraFor(settings.camera, scene_, double(target_.width()) / target_.height()), target_);
        ASSERT_TRUE(stats_.ok) << stats_.error;
    }
    static std::chrono::system_clock::time_point at(int year, int month, int day, int h, int m, int s) {
        std::tm t{};
        t.tm_year = year - 1900;
        t.tm_mon = month - 1;
        t.tm_mday = day;
        t.tm_hour = h;
        t.tm_min = m;
        t.tm_sec = s;
        t.tm_isdst = -1;
        return std::chrono::system_clock::from_time_t(std::mktime(&t));
    }
    fs::path dir_;
    Scene scene_;
    std::unique_ptr<Renderer> renderer_;  // made in SetUp, once the context is current
    RenderTarget target_;
    FrameStats stats_;
};

TEST_F(Screenshot, WritesATimestampedPngOfTheViewIntoANewFolder) {
    const fs::path folder = dir_ / "new" / "screenshots";
    const ScreenshotResult shot = writeScreenshot(target_, folder.string(), nullptr, at(2026, 11, 23, 21, 5, 9));
    ASSERT_TRUE(shot.ok()) << shot.error;
    EXPECT_EQ(shot.viewPng, (folder / "shadowlab-20261123-210509.png").string());
    EXPECT_TRUE(shot.shadowMapExr.empty());
    std::string error;
    std::optional<PngImage> png = readPng(shot.viewPng, &error);
    ASSERT_TRUE(png.has_value()) << error;
    EXPECT_EQ(png->width, 320);
    EXPECT_EQ(png->height, 200);
    // Same pixels as the view, top row first in the file.
    const std::vector<std::uint8_t> view = target_.readColor();
    ASSERT_EQ(png->channels, 4);
    ASSERT_EQ(png->pixels.size(), view.size());
    const std::size_t row = 320 * 4;
    for (int y = 0; y < 200; y += 37)
        EXPECT_TRUE(std::equal(png->pixels.begin() + y * row, png->pixels.begin() + (y + 1) * row,
                               view.begin() + (199 - y) * row));
    // Not blank: the scene has many distinct colours.
    std::set<std::uint32_t> colours;
    for (std::size_t i = 0; i + 3 < png->pixels.size(); i += 4)
        colours.insert(png->pixels[i] | png->pixels[i + 1] << 8 | png->pixels[i + 2] << 16);
    EXPECT_GT(colours.size(), 50u);
}

TEST_F(Screenshot, SameSecondGetsANumberedNameAndNeverOverwrites) {
    const auto when = at(2026, 1, 2, 3, 4, 5);
    const ScreenshotResult first = writeScreenshot(target_, dir_.string(), nullptr, when);
    ASSERT_TRUE(first.ok()) << first.error;
    const auto firstSize = fs::file_size(first.viewPng);
    const ScreenshotResult second = writeScreenshot(target_, dir_.string(), nullptr, when);
    const ScreenshotResult third = writeScreenshot(target_, dir_.string(), nullptr, when);
    ASSERT_TRUE(second.ok() && third.ok()) << second.error << third.error;
    EXPECT_EQ(fs::path(first.viewPng).filename(), "shadowlab-20260102-030405.png");
    EXPECT_EQ(fs::path(second.viewPng).filename(), "shadowlab-20260102-030405-2.png");
    EXPECT_EQ(fs::path(third.viewPng).filename(), "shadowlab-20260102-030405-3.png");
    EXPECT_EQ(fs::file_size(first.viewPng), firstSize);

    // A file someone else put there under the next name is left alone.
    std::ofstream(dir_ / "shadowlab-20260102-030406.png") << "not mine";
    const ScreenshotResult fourth = writeScreenshot(target_, dir_.string(), nullptr, at(2026, 1, 2, 3, 4, 6));
    ASSERT_TRUE(fourth.ok()) << fourth.error;
    EXPECT_EQ(fs::path(fourth.viewPng).filename(), "shadowlab-20260102-030406-2.png");
    EXPECT_EQ(fs::file_size(dir_ / "shadowlab-20260102-030406.png"), 8u);
}

TEST_F(Screenshot, WithTheShadowMapAlsoWritesItsFloatExrAndPng) {
    const ScreenshotResult shot =
        writeScreenshot(target_, dir_.string(), &renderer_->shadowMap(), at(2026, 5, 6, 7, 8, 9));
    ASSERT_TRUE(shot.ok()) << shot.error;
    EXPECT_EQ(fs::path(shot.shadowMapExr).filename(), "shadowlab-20260506-070809-shadowmap.exr");
    EXPECT_EQ(fs::path(shot.shadowMapPng).filename(), "shadowlab-20260506-070809-shadowmap.png");
    const int size = renderer_->shadowMap().resolution();
    std::optional<DepthImage> exr = readExrDepth(shot.shadowMapExr);
    ASSERT_TRUE(exr.has_value());
    EXPECT_EQ(exr->width, size);
    // Bit-exact depths, top row of the file = top row of the map.
    const std::vector<float> depth = renderer_->shadowMap().readDepth();
    for (int y = 0; y < size; y += size / 8)
        for (int x = 0; x < size; x += size / 8)
            EXPECT_EQ(exr->depth[std::size_t(y) * size + x], depth[std::size_t(size - 1 - y) * size + x]);
    std::optional<PngImage> png = readPng(shot.shadowMapPng);
    ASSERT_TRUE(png.has_value());
    EXPECT_EQ(png->channels, 1);
    EXPECT_EQ(png->width, size);
}

TEST_F(Screenshot, AFolderThatCannotBeCreatedSaysWhyAndWritesNothing) {
    fs::create_directories(dir_);
    std::ofstream(dir_ / "regular-file") << "x";
    const fs::path impossible = dir_ / "regular-file" / "screenshots";
    const ScreenshotResult shot = writeScreenshot(target_, impossible.string(), &renderer_->shadowMap());
    EXPECT_FALSE(shot.ok());
    EXPECT_NE(shot.error.find("screenshot not saved"), std::string::npos) << shot.error;
    EXPECT_NE(shot.error.find(impossible.string()), std::string::npos) << shot.error;
    EXPECT_NE(shot.error.find("Not a directory"), std::string::npos) << shot.error;
    EXPECT_TRUE(shot.viewPng.empty());

    // The folder is a file itself.
    const ScreenshotResult onFile = writeScreenshot(target_, (dir_ / "regular-file").string());
    EXPECT_NE(onFile.error.find("not a folder"), std::string::npos) << onFile.error;
}

TEST_F(Screenshot, AReadOnlyFolderSaysWhy) {
    fs::create_directories(dir_ / "locked");
    // Readable and searchable by everyone, writable by no one.
    fs::permissions(dir_ / "locked", fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                         fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
    ScreenshotResult shot;
    {
        const test::AsUnprivilegedUser user;  // root (CI) would write into the folder regardless
        EXPECT_EQ(user.error(), "");
        shot = writeScreenshot(target_, (dir_ / "locked").string());
    }
    fs::permissions(dir_ / "locked", fs::perms::owner_all);
    EXPECT_FALSE(shot.ok());
    EXPECT_NE(shot.error.find("Permission denied"), std::string::npos) << shot.error;
    EXPECT_TRUE(fs::is_empty(dir_ / "locked"));
}

TEST_F(Screenshot, AFullDiskSaysSoAndLeavesNoEmptyFile) {
    // A tiny tmpfs filled to the brim stands in for a full disk (needs root and permission to mount).
    const fs::path disk = dir_ / "full-disk";
    fs::create_directories(disk);
    if (::mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=64k") != 0) GTEST_SKIP() << "cannot mount a tmpfs here";
    {
        std::ofstream filler(disk / "filler", std::ios::binary);
        const std::string block(4096, 'x');
        for (int i = 0; i < 64 && filler; ++i) filler.write(block.data(), std::streamsize(block.size()));
    }
    const ScreenshotResult shot = writeScreenshot(target_, disk.string(), nullptr, at(2026, 3, 4, 5, 6, 7));
    std::vector<std::string> left;
    for (const auto& entry : fs::directory_iterator(disk)) left.push_back(entry.path().filename().string());
    ::umount(disk.c_str());
    EXPECT_FALSE(shot.ok());
    EXPECT_NE(shot.error.find("No space left on device"), std::string::npos) << shot.error;
    EXPECT_NE(shot.error.find("shadowlab-20260304-050607.png"), std::string::npos) << shot.error;
    EXPECT_TRUE(shot.viewPng.empty());
    EXPECT_EQ(left, std::vector<std::string>{"filler"});  // the reserved name was given back
}

}  // namespace
}  // namespace shadowlab::test
