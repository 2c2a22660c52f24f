#include "cli/bench_reference_update.h"
#include "cli/bench_input.h"

#include "cli/command_input.h"
#include "cli/json_output.h"
#include "reference/embree_scene.h"
#include "reference/parallel_rows.h"
#include "scene/scene_animation.h"
#include "scene/scene_casters.h"
#include "scene/scene_source.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>

namespace shadowlab::cli {

namespace {

constexpr double kStepSeconds = 1.0 / 30.0;
constexpr double kTargetShare = 0.10;  // issue 22: an update after a move <= 10 % of a rebuild

// The median and the fastest of some timings (on a shared machine the fastest shows the cost without waits).
struct Timing {
    double median = 0.0, fastest = 0.0;
};

Timing timingOf(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? Timing{} : Timing{v[v.size() / 2], v.front()};
}

std::string describe(const Timing& t, const Timing& rebuild) {
    char text[160];
    std::snprintf(text, sizeof text, "%.3f ms (%.1f %% of a rebuild; fastest %.3f ms, %.1f %%)", t.median,
                  100.0 * t.median / rebuild.median, t.fastest, 100.0 * t.fastest / rebuild.fastest);
    return text;
}

// The median milliseconds of `repeats` updates of `bvh`, alternating `scene`'s instances between the poses `a` and
// `b` (only the instances in `moved`).
Timing timeUpdates(EmbreeScene& bvh, Scene& scene, const Scene& a, const Scene& b, const std::vector<std::size_t>& moved,
                   const glm::dvec3& origin, int repeats, std::size_t& movedCount) {
    std::vector<double> ms;
    for (int r = 0; r < repeats; ++r) {
        const Scene& pose = r % 2 == 0 ? b : a;
        for (std::size_t i : moved) scene.instances[i].transform = pose.instances[i].transform;
        movedCount = bvh.updateTransforms(scene, origin);
        ms.push_back(bvh.updateMilliseconds());
    }
    return timingOf(ms);
}

}  // namespace

std::string cpuName() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0) {
            const std::size_t colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(line.find_first_not_of(' ', colon + 1));
        }
    return "unknown CPU";
}

int runBenchReferenceUpdate(const BenchOptions& options) {
    BenchInput input = readBenchInput(options, /*checkView=*/false);  // no view: it times the BVH alone
    if (input.refused) return input.refused;
    std::optional<Settings>& settings = input.settings;
    SceneLoadResult& loaded = input.loaded;
    std::string error;
    const std::optional<std::vector<int>> chosen = chosenAnimations(*loaded.scene, settings->animation.play, error);
    if (!chosen) return fail(error);
    if (chosen->empty())
        return fail("bench --reference-update: the scene " + loaded.scene->name +
                    " has no animation to play (animation.play " + settings->animation.play +
                    "); builtin:city-traffic has one");
    // Two poses a frame apart; `scene` is the one the BVH follows (posed in place, as the flicker measure does).
    Scene& scene = *loaded.scene;
    const double t = double(settings->animation.time);
    Scene before = scene, after = scene;
    poseScene(before, *chosen, t);
    poseScene(after, *chosen, t + kStepSeconds);
    std::vector<std::size_t> moving;
    for (std::size_t i = 0; i < scene.instances.size(); ++i)
        if (before.instances[i].transform != after.instances[i].transform) moving.push_back(i);
    if (moving.empty())
        return fail("bench --reference-update: nothing in " + scene.name + " moves between t = " + std::to_string(t) +
                    " and " + std::to_string(t + kStepSeconds) + " s (animation.time past the animation's end?)");
    for (std::size_t i = 0; i < scene.instances.size(); ++i) scene.instances[i].transform = before.instances[i].transform;
    const glm::dvec3 origin = scene.bounds.centreOrOrigin();
    const std::vector<char> casting = castingInstances(scene, settings->casters);
    const int updates = std::max(options.frames, 2);
    const int builds = std::clamp(options.frames / 6, 2, 5);
    try {
        EmbreeScene bvh(scene, origin, casting);
        const std::size_t meshBuilds = bvh.meshBuilds();
        std::size_t oneMoved = 0, stepMoved = 0;
        const Timing one = timeUpdates(bvh, scene, before, after, {moving.front()}, origin, updates, oneMoved);
        const Timing step = timeUpdates(bvh, scene, before, after, moving, origin, updates, stepMoved);
        if (bvh.meshBuilds() != meshBuilds) return fail("bench --reference-update: an update rebuilt a mesh BVH");
        std::vector<double> rebuildMs;
        for (int r = 0; r < builds; ++r) rebuildMs.push_back(EmbreeScene(scene, origin, casting).buildMilliseconds());
        const Timing rebuild = timingOf(rebuildMs);
        const std::string cpu = cpuName();
        std::cout << "bench --reference-update: " << scene.name << " (" << bvh.triangles() << " triangles in "
                  << bvh.meshBvhs() << " mesh BVHs, " << scene.instances.size() << " instances), the reference's "
                  << "Embree scene on the CPU: " << cpu << ", " << workerCount() << " threads\n"
                  << "an animation step of " << std::setprecision(4) << kStepSeconds << " s at t = " << t
                  << " s moves " << moving.size() << " instances; medians of " << updates << " updates and "
                  << builds << " builds (target: update <= " << int(kTargetShare * 100) << " % of a rebuild)\n"
                  << "  update, one instance moved:  " << describe(one, rebuild) << "\n"
                  << "  update, the whole step (" << stepMoved << "): " << describe(step, rebuild) << "\n"
                  << std::fixed << std::setprecision(3) << "  full rebuild:                " << rebuild.median
                  << " ms (fastest " << rebuild.fastest << " ms; every mesh BVH and the top level)\n";
        if (oneMoved != 1) return fail("bench --reference-update: moving one instance moved " + std::to_string(oneMoved));
        if (!options.json.empty()) {
            const nlohmann::json doc = {
                {"scene", scene.name},          {"cpu", cpu},
                {"threads", workerCount()},     {"triangles", bvh.triangles()},
                {"meshBvhs", bvh.meshBvhs()},   {"instances", scene.instances.size()},
                {"time", t},                    {"stepSeconds", kStepSeconds},
                {"instancesMovedByStep", moving.size()},
                {"updateOneMs", one.median},    {"updateOneFastestMs", one.fastest},
                {"updateStepMs", step.median},  {"updateStepFastestMs", step.fastest},
                {"rebuildMs", rebuild.median},  {"rebuildFastestMs", rebuild.fastest},
                {"updateOneShare", one.median / rebuild.median},
                {"updateStepShare", step.median / rebuild.median}, {"targetShare", kTargetShare},
                {"updates", updates},           {"builds", builds}};
            if (std::string e = writeJsonOutput(options.json, doc); !e.empty()) return fail(e);
        }
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}

}  // namespace shadowlab::cli
