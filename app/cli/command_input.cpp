#include "cli/command_input.h"

#include "accuracy/light_isolation.h"
#include "frame/camera.h"
#include "scene/scene_animation.h"
#include "scene/scene_casters.h"
#include "settings/atomic_file.h"
#include "settings/regular_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>

namespace shadowlab::cli {

int fail(const std::string& message) {
    std::cerr << "error: " << message << "\n";
    return 1;
}

std::string checkPixelInView(const std::string& option, const std::string& text, int x, int y, int width, int height) {
    if (x >= 0 && y >= 0 && x < width && y < height) return "";
    return option + " " + text + " is outside the " + std::to_string(width) + "x" + std::to_string(height) +
           " view (x in [0, " + std::to_string(width - 1) + "], y in [0, " + std::to_string(height - 1) + "])";
}

std::string checkViewSize(int width, int height) {
    if (width >= 1 && height >= 1 && width <= 16384 && height <= 16384) return "";
    return "--width/--height must be in [1, 16384], got " + std::to_string(width) + "x" + std::to_string(height);
}

SceneLoadResult loadSceneForCommand(const std::string& spec, std::initializer_list<const Settings*> settings) {
    SceneLoadResult loaded = loadScene(spec);
    if (!loaded.scene) return loaded;
    for (const std::string& w : loaded.scene->warnings)
        std::cerr << "warning: " << loaded.scene->name << ": " << w << "\n";
    // The scene at the first settings' animation time (render --compare poses a copy for B at its own).
    for (const Settings* s : settings) {
        if (!s) continue;
        if (std::string error = poseScene(*loaded.scene, s->animation); !error.empty()) {
            loaded.scene.reset();
            loaded.error = std::move(error);
            return loaded;
        }
        if (!loaded.scene->animations.empty()) std::cerr << "note: " << animationNote(*loaded.scene, s->animation) << "\n";
        break;
    }
    for (const Settings* s : settings) {
        if (!s) continue;
        if (std::string error = sceneCameraError(s->camera, *loaded.scene); !error.empty()) {
            loaded.scene.reset();
            loaded.error = std::move(error);
            return loaded;
        }
        for (const std::string& w : unknownCasterPathWarnings(*loaded.scene, s->casters))
            std::cerr << "warning: " << w << "\n";
    }
    return loaded;
}

std::string checkOutputFolder(const std::string& path, const char* option) {
    namespace fs = std::filesystem;
    if (path.empty()) return {};
    const std::string where = std::string(option) + " " + path + ": ";
    std::error_code ec;
    // What the atomic writer will refuse at the end is refused before the work: only regular files are written.
    if (fs::is_symlink(fs::symlink_status(path, ec)) && !fs::exists(path, ec))
        return where + "a symbolic link to '" + fs::read_symlink(path, ec).string() +
               "', which does not exist (ShadowLab does not create files through dangling links)";
    if (const std::string kind = nonRegularFileKind(path); !kind.empty())
        return where + "it is " + kind + ", not a regular file; ShadowLab writes only regular files";
    if (const std::string readOnly = readOnlyFileReason(path); !readOnly.empty()) return where + readOnly;
    const fs::path folder = fs::path(path).parent_path();
    if (!folder.empty() && !fs::is_directory(folder, ec)) return where + "folder '" + folder.string() + "' does not exist";
    // Found now, not after the work: a folder the writer cannot create its temporary file in.
    if (::access(folder.empty() ? "." : folder.c_str(), W_OK | X_OK) != 0)
        return where + "folder '" + (folder.empty() ? std::string(".") : folder.string()) + "' is not writable (" +
               std::strerror(errno) + ")";
    return {};
}

namespace {

// Two names of one file: the same canonical path, or (both existing) the same inode.
bool sameFile(const std::string& a, const std::string& b) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
    const fs::path ca = fs::weakly_canonical(a, ec);
    if (ec) return false;
    const fs::path cb = fs::weakly_canonical(b, ec);
    return !ec && ca == cb;
}

}  // namespace

std::string checkOutputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const NamedPath& out = outputs[i];
        if (out.path.empty()) continue;
        if (std::string error = checkOutputFolder(out.path, out.option); !error.empty()) return error;
        for (std::size_t j = 0; j < i; ++j)
            if (!outputs[j].path.empty() && sameFile(outputs[j].path, out.path))
                return std::string(outputs[j].option) + " and " + out.option + " both name " + out.path +
                       ": each output needs its own file (one would overwrite the other)";
        for (const NamedPath& in : inputs)
            if (!in.path.empty() && sameFile(in.path, out.path))
                return std::string(out.option) + " " + out.path + " is the input " + in.option +
                       ": refusing to overwrite what the command reads";
    }
    return {};
}

std::string checkPictureOutput(const NamedPath& output, const PictureSize& size) {
    if (output.path.empty()) return {};
    if (std::string error = pictureSizeError(size); !error.empty())
        return std::string(output.option) + " " + output.path + ": " + error;
    return {};
}

std::string checkMeasureMemory(int width, int height) {
    const double bytes = double(width) * double(height) * kMeasureBytesPerPixel;
    const long pages = ::sysconf(_SC_AVPHYS_PAGES), pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages <= 0 || pageSize <= 0) return {};
    const double available = double(pages) * double(pageSize);
    if (bytes <= 0.8 * available) return {};
    auto gib = [](double b) {
        char text[32];
        std::snprintf(text, sizeof text, "%.1f GiB", b / double(1u << 30));
        return std::string(text);
    };
    return "--width/--height " + std::to_string(width) + "x" + std::to_string(height) + ": a measurement needs about " +
           gib(bytes) + " of memory (" + std::to_string(kMeasureBytesPerPixel) + " bytes a pixel), more than the " +
           gib(available) + " available; use a smaller view";
}

std::optional<std::vector<std::size_t>> chooseLights(const Settings& settings, const Scene& scene, int requested,
                                                     const std::string& what, std::string& error) {
    if (requested >= 0) {
        if (error = unmeasurableReason(settings, scene, std::size_t(requested)); !error.empty()) {
            error = "--light " + std::to_string(requested) + ": " + error;
            return std::nullopt;
        }
        return std::vector<std::size_t>{std::size_t(requested)};
    }
    std::vector<std::size_t> casting = castingLights(settings, scene);
    if (casting.empty()) {
        error = "no light casts a shadow (every light is off or has castsShadows=false): nothing to " + what;
        return std::nullopt;
    }
    return casting;
}

std::optional<std::size_t> chooseOneLight(const Settings& settings, const Scene& scene, int requested,
                                          const std::string& option, std::string& error) {
    if (requested >= 0) {
        const std::optional<std::vector<std::size_t>> one = chooseLights(settings, scene, requested, option, error);
        if (!one) return std::nullopt;
        return one->front();
    }
    const std::vector<std::size_t> casting = castingLights(settings, scene);
    if (casting.size() == 1) return casting.front();
    error = option + ": " +
            (casting.empty() ? std::string("no light casts a shadow (the settings have ") +
                                   std::to_string(settings.lights.size()) + " light" +
                                   (settings.lights.size() == 1 ? "" : "s") + ")"
                             : std::to_string(casting.size()) + " lights cast shadows: say which with --light N");
    return std::nullopt;
}

}  // namespace shadowlab::cli
