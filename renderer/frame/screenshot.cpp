#include "frame/screenshot.h"

#include "image/image_io.h"
#include "image/picture_size.h"
#include "settings/user_config.h"
#include "shadow/shadow_map_files.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

std::string timestamp(std::chrono::system_clock::time_point when) {
    const std::time_t seconds = std::chrono::system_clock::to_time_t(when);
    std::tm local{};
    localtime_r(&seconds, &local);
    char text[32];
    std::strftime(text, sizeof text, "%Y%m%d-%H%M%S", &local);
    return text;
}

struct ReservedNames {
    fs::path view, mapExr, mapPng;
    std::string error;
};

// Claims the first free name: the view's PNG is created empty with O_EXCL (so two screenshots in the same second,
// even from two processes, never share a name), and the shadow-map names beside it must not exist either.
ReservedNames reserveNames(const fs::path& folder, const std::string& base, bool withMap) {
    ReservedNames names;
    for (int n = 1; n < 10000; ++n) {
        const std::string stem = n == 1 ? base : base + "-" + std::to_string(n);
        names.view = folder / (stem + ".png");
        names.mapExr = folder / (stem + "-shadowmap.exr");
        names.mapPng = folder / (stem + "-shadowmap.png");
        std::error_code ec;
        if (withMap && (fs::exists(names.mapExr, ec) || fs::exists(names.mapPng, ec))) continue;
        const int fd = ::open(names.view.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            return names;
        }
        if (errno != EEXIST) {
            names.error = "cannot create '" + names.view.string() + "': " + std::strerror(errno);
            return names;
        }
    }
    names.error = "no free file name for " + base + " in '" + folder.string() + "'";
    return names;
}

// The picture's rows: GL's (bottom first) when `glRows`, else top first.
ScreenshotResult writePicture(const std::vector<std::uint8_t>& pixels, int width, int height, bool glRows,
                              const std::string& folder, const ShadowMap* shadowMap,
                              std::chrono::system_clock::time_point when, const PngText& text) {
    ScreenshotResult result;
    const std::string failed = "screenshot not saved: ";
    if (width < 1 || height < 1 || pixels.size() < std::size_t(width) * std::size_t(height) * 4) {
        result.error = failed + "the view has not been rendered yet";
        return result;
    }
    // Sizes first, before any file is reserved: the view and, when asked, the map as float depth.
    std::string tooLarge = pictureSizeError({width, height, 4, 4, true, "the view"});
    if (tooLarge.empty() && shadowMap && shadowMap->valid())
        tooLarge = pictureSizeError({shadowMap->resolution(), shadowMap->resolution(), 1, 4, true, "the shadow map"});
    if (!tooLarge.empty()) {
        result.error = failed + tooLarge;
        return result;
    }
    const fs::path dir = folder.empty() ? fs::path(".") : fs::path(folder);
    if (std::string error = ensureFolder(dir); !error.empty()) {
        result.error = failed + error;
        return result;
    }
    const bool withMap = shadowMap && shadowMap->valid();
    ReservedNames names = reserveNames(dir, "shadowlab-" + timestamp(when), withMap);
    if (!names.error.empty()) {
        result.error = failed + names.error;
        return result;
    }

    if (std::string error = writePng(names.view.string(), width, height, 4, pixels.data(), glRows, text);
        !error.empty()) {
        std::error_code ec;
        fs::remove(names.view, ec);  // the reserved (empty or partial) file is not a screenshot
        result.error = failed + error;
        return result;
    }
    result.viewPng = names.view.string();

    if (shadowMap) {
        if (!withMap) {
            result.error = "shadow map not saved: there is no shadow map yet";
            return result;
        }
        const ShadowMapFilesResult files = writeShadowMapFiles(*shadowMap, names.mapExr.string(), names.mapPng.string());
        if (!files.ok()) {
            result.error = "shadow map not saved: " + files.error;
            std::error_code ec;
            fs::remove(names.mapExr, ec);  // a failed pair is removed whole: a lone half would mislead
            fs::remove(names.mapPng, ec);
            return result;
        }
        result.shadowMapExr = names.mapExr.string();
        result.shadowMapPng = names.mapPng.string();
    }
    return result;
}

}  // namespace

ScreenshotResult writeScreenshot(const RenderTarget& target, const std::string& folder, const ShadowMap* shadowMap,
                                 std::chrono::system_clock::time_point when, const PngText& text) {
    const std::vector<std::uint8_t> pixels =
        target.width() > 0 && target.height() > 0 ? target.readColor() : std::vector<std::uint8_t>{};
    return writePicture(pixels, target.width(), target.height(), true, folder, shadowMap, when, text);
}

ScreenshotResult writeScreenshot(const std::vector<std::uint8_t>& rgbaTopFirst, int width, int height,
                                 const std::string& folder, const ShadowMap* shadowMap,
                                 std::chrono::system_clock::time_point when, const PngText& text) {
    return writePicture(rgbaTopFirst, width, height, false, folder, shadowMap, when, text);
}

}  // namespace shadowlab
