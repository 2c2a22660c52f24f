#pragma once
// What every CLI command does before its work: report a failure, check the view size and output folders, load the
// scene.
#include "image/picture_size.h"
#include "scene/scene_source.h"

#include "settings/settings.h"

#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab::cli {

// Prints "error: message" to stderr and returns 1, the exit code of a command that failed.
int fail(const std::string& message);

// "" when --width/--height can be rendered, else why not.
std::string checkViewSize(int width, int height);
// "" when pixel (x, y) lies in a width x height view, else why, naming the option and its text as given.
std::string checkPixelInView(const std::string& option, const std::string& text, int x, int y, int width, int height);

// The lights a per-light command describes: `requested` (--light N, checked: it exists and casts), or, when it is
// -1, every shadow-casting light. nullopt with `error` when there is none ("...: nothing to `what`").
std::optional<std::vector<std::size_t>> chooseLights(const Settings& settings, const Scene& scene, int requested,
                                                     const std::string& what, std::string& error);

// The one light a one-light tool describes: `requested` (--light N, checked: it exists and casts) or, when it is -1,
// the only shadow-casting light; several casting lights without --light are refused (never light 0 silently).
// nullopt with `error` naming `option`.
std::optional<std::size_t> chooseOneLight(const Settings& settings, const Scene& scene, int requested,
                                          const std::string& option, std::string& error);

// Loads SCENE (a path or builtin:NAME) and prints the loader's warnings to stderr; on failure .error says why.
// Each of `settings` (null entries skipped) is checked against the scene: a camera.sceneCamera the scene lacks is
// the error, a casters.excluded path it lacks a warning.
SceneLoadResult loadSceneForCommand(const std::string& spec, std::initializer_list<const Settings*> settings);

// "" when a file can be written at path (its folder exists; it is a regular file or new; not a dangling symlink),
// else why not — checked before the work starts, with the rules of writeFileAtomically.
std::string checkOutputFolder(const std::string& path, const char* option);

// An option and the path it names ("--json", "o.json").
struct NamedPath {
    std::string path;
    const char* option;
};

// Every output of a command, checked before its work: each with checkOutputFolder's rules, none read-only, none
// the same file as another output (`sweep --json o --csv o`) or as an input (`render --scene mine.glb --out
// mine.glb`, `measure --preset p.json --overlay p.json`). Empty paths are skipped. "" or the first problem.
std::string checkOutputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs = {});

// "" or why the picture `output` names cannot be written at `size` (image/picture_size.h: its bytes, the PNG
// writer's limit), naming the option and the path; checked before the work that makes the picture. "" for no path.
std::string checkPictureOutput(const NamedPath& output, const PictureSize& size);

// What a measurement holds per view pixel, summed over its buffers (G-buffer readback with double positions and
// normals, the tool's frame and shadow factor, reference classes and Lambert, boundary search, overlay: ~180
// bytes) with a margin: the figure behind checkMeasureMemory.
inline constexpr int kMeasureBytesPerPixel = 200;

// "" when a measurement of width x height fits in 80 % of the memory available now, else the figure and why.
std::string checkMeasureMemory(int width, int height);

}  // namespace shadowlab::cli
