#include "cli/bench_planner.h"
#include "cli/bench_input.h"

#include "cli/command_input.h"
#include "context/headless_context.h"
#include "frame/timed_frames.h"
#include "light/scene_lights.h"
#include "scene/scene_source.h"
#include "settings/settings_fields.h"
#include "sweep/bare_depth_draw.h"
#include "views/shadow_planner.h"

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>

#include <time.h>

namespace shadowlab::cli {

namespace {

constexpr double kPlannerTargetMs = 0.05;
constexpr double kCascadeTargetRatio = 1.1;

// The camera moved `step` steps along its right axis (the cascades follow it; the other views do not).
Camera movedCamera(const Camera& camera, int step, double stepLength) {
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    glm::dvec3 right = glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0));
    right = glm::length(right) > 1e-9 ? glm::normalize(right) : glm::dvec3(1.0, 0.0, 0.0);
    Camera moved = camera;
    moved.position += right * (stepLength * step);
    moved.target += right * (stepLength * step);
    return moved;
}

// This thread's CPU time: what the planner costs, without the time other processes take the core (a loaded
// machine would otherwise count them).
double threadCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

struct PlannerTiming {
    double meanMs = 0.0;
    int viewsRendered = 0;  // in the last timed frame
};

// The mean CPU time of planShadowViews over `frames` frames, each planned against the one before.
PlannerTiming timePlanner(const Scene& scene, const Settings& settings, const Camera& camera, double aspect,
                          const glm::dvec3& origin, const std::vector<CasterSphere>& casters, int maxTextureSize,
                          int frames, double stepLength) {
    const std::size_t fingerprint = sceneFingerprint(scene);
    std::optional<ShadowPlan> previous;
    PlannerTiming timing;
    double total = 0.0;
    for (int f = -1; f < frames; ++f) {  // frame -1: the first frame, not timed (it renders everything)
        const Camera at = movedCamera(camera, (f + 1) % 2, stepLength);  // back and forth: it stays in the scene
        const ViewCamera view = viewCameraOf(at, aspect, origin);
        const glm::dmat4 viewProjection = at.projection(aspect) * at.view(origin);
        const double start = threadCpuMs();
        ShadowPlan plan = planShadowViews({scene, settings, origin, &view, viewProjection, casters, fingerprint,
                                           maxTextureSize, previous ? &*previous : nullptr, ""});
        const double end = threadCpuMs();
        if (!plan.error.empty()) throw std::runtime_error("planner: " + plan.error);
        if (f >= 0) total += end - start;
        timing.viewsRendered = viewsToRender(plan);
        previous = std::move(plan);
    }
    timing.meanMs = total / frames;
    return timing;
}

std::string mixDescription(const std::vector<LightSettings>& lights) {
    int suns = 0, spots = 0, points = 0;
    for (const LightSettings& l : lights)
        (l.type == LightType::Directional ? suns : l.type == LightType::Spot ? spots : points)++;
    return std::to_string(suns) + " directional cascaded, " + std::to_string(spots) + " spot, " +
           std::to_string(points) + " point";
}

}  // namespace

std::vector<LightSettings> plannerBenchLights(const Bounds& bounds, const LightSettings& model) {
    const glm::dvec3 centre = bounds.centreOrOrigin();
    const double r = std::max(1.0, double(bounds.radius()));
    std::vector<LightSettings> lights;
    LightSettings base;
    base.shadow = model.shadow;
    for (const auto& [direction, cascades] :
         {std::pair{glm::vec3(-0.4f, -1.0f, -0.3f), 4}, std::pair{glm::vec3(0.5f, -1.0f, 0.2f), 3}}) {
        LightSettings sun = base;
        sun.type = LightType::Directional;
        sun.direction = direction;
        sun.projection.fit = ProjectionFit::Cascades;
        sun.projection.cascadeCount = cascades;
        lights.push_back(sun);
    }
    // Spots above a ring around the centre looking at its middle; point lights lower on the same ring.
    for (int k = 0; k < 6; ++k) {
        const double a = 2.0 * 3.14159265358979 * k / 6.0;
        const glm::dvec3 ring = centre + glm::dvec3(std::cos(a) * 0.4 * r, 0.0, std::sin(a) * 0.4 * r);
        LightSettings l = base;
        if (k % 2 == 0) {
            l.type = LightType::Spot;
            l.position = glm::vec3(ring + glm::dvec3(0.0, 0.3 * r, 0.0));
            l.direction = glm::vec3(centre - glm::dvec3(l.position));
        } else {
            l.type = LightType::Point;
            l.position = glm::vec3(ring + glm::dvec3(0.0, 0.1 * r, 0.0));
        }
        lights.push_back(l);
    }
    return lights;
}

int runBenchPlanner(const BenchOptions& options) {
    const BenchInput input = readBenchInput(options);
    if (input.refused) return input.refused;
    const Scene& scene = *input.loaded.scene;
    const Settings effective = withEffectiveLights(*input.settings, scene);
    const LightSettings model = effective.lights.empty() ? LightSettings{} : effective.lights.front();
    Settings mix = effective;
    mix.lights = plannerBenchLights(scene.bounds, model);
    try {
        HeadlessContext context;
        Renderer renderer;
        RenderTarget target;
        if (std::string e = target.resize(options.width, options.height); !e.empty()) return fail(e);
        const double aspect = double(options.width) / options.height;
        const Camera camera = cameraFor(input.settings->camera, scene, aspect);
        const GlInfo& info = renderer.glInfo();
        // One frame uploads the scene: the casters' bounding spheres are the renderer's own.
        FrameStats first = renderer.render(scene, mix, camera, target);
        if (!first.ok) return fail(first.error);
        const std::vector<CasterSphere> casters = casterSpheres(*renderer.gpuScene());
        std::cout << "bench --planner: " << scene.name << " (" << scene.triangleCount() << " triangles, "
                  << casters.size() << " casters), view " << options.width << "x" << options.height
                  << "\ngl: " << info.renderer << "\n";
        nlohmann::json doc = {{"scene", scene.name}, {"width", options.width}, {"height", options.height},
                              {"glRenderer", info.renderer}, {"casters", casters.size()}};

        // 1. The planner alone, on the CPU.
        const int plannerFrames = std::max(options.frames * 50, 500);
        // A brisk walk: a step per frame longer than the farthest cascade's texel, so every cascade re-plans.
        const double step = 0.02 * std::max(1.0, double(scene.bounds.radius()));
        const PlannerTiming moving = timePlanner(scene, mix, camera, aspect, first.renderOrigin, casters,
                                                 info.maxTextureSize, plannerFrames, step);
        const PlannerTiming still = timePlanner(scene, mix, camera, aspect, first.renderOrigin, casters,
                                                info.maxTextureSize, plannerFrames, 0.0);
        std::size_t views = 0, cascadeViews = 0;
        for (const ShadowViewStats& v : first.views) {
            views += v.hasView;
            cascadeViews += v.hasView && v.kind == ShadowViewKind::Cascade;
        }
        std::cout << std::fixed << std::setprecision(2) << "\nplanner CPU time per frame, scene " << scene.name << ", "
                  << mix.lights.size() << " lights (" << mixDescription(mix.lights) << "; " << views
                  << " views), this thread's CPU time, mean of " << plannerFrames << " frames (target < " << kPlannerTargetMs << " ms):\n"
                  << std::setprecision(4) << "  camera moving: " << moving.meanMs << " ms (" << moving.viewsRendered
                  << " of " << cascadeViews << " cascades re-rendered per frame)\n"
                  << "  camera still:  " << still.meanMs << " ms (" << still.viewsRendered << " views re-rendered)\n";
        doc["planner"] = {{"lights", mix.lights.size()}, {"mix", mixDescription(mix.lights)}, {"views", views},
                          {"frames", plannerFrames}, {"movingMeanMs", moving.meanMs},
                          {"movingViewsRendered", moving.viewsRendered}, {"stillMeanMs", still.meanMs},
                          {"stillViewsRendered", still.viewsRendered}, {"targetMs", kPlannerTargetMs}};

        // 2. Each cascade's shadow pass against a bare depth draw of the casters it holds.
        Settings cascaded = effective;
        std::erase_if(cascaded.lights, [](const LightSettings& l) {
            return !(l.enabled && l.castsShadows && l.type == LightType::Directional &&
                     l.projection.fit == ProjectionFit::Cascades);
        });
        const bool own = !cascaded.lights.empty();
        if (!own) cascaded.lights = {mix.lights.front()};
        PerViewTimes times = timeEveryView(renderer, scene, cascaded, camera, target, options.frames);
        if (!times.error.empty()) return fail(times.error);
        std::map<std::string, std::vector<double>>& perView = times.viewMs;
        const FrameStats& last = times.last;
        std::cout << "\ncascade shadow pass vs a bare depth draw of the casters it holds, scene " << scene.name
                  << ", " << (own ? "the settings' cascaded lights" : "no cascaded light in the settings: the mix's "
                                                                      "first sun alone")
                  << ", view " << options.width << "x" << options.height << ", median of " << options.frames
                  << " frames, timing " << last.timingSource << " (target ratio <= " << std::setprecision(2)
                  << kCascadeTargetRatio << "):\n";
        const TimingSource source = info.softwareRasterizer ? TimingSource::CpuAroundFinish : TimingSource::GpuQueries;
        nlohmann::json cascades = nlohmann::json::array();
        for (const ShadowViewStats& v : last.views) {
            if (!v.hasView || v.kind != ShadowViewKind::Cascade) continue;
            // The instances the pass draws into this cascade: the pass's own selection (castersInVolume).
            std::vector<char> held(scene.instances.size(), 0);
            int heldCount = 0;
            for (std::uint32_t d : castersInVolume(*renderer.gpuScene(), v.space).draws) {
                const std::size_t instance = renderer.gpuScene()->draws()[d].instance;
                heldCount += !held[instance];
                held[instance] = 1;
            }
            const LightSettings& light = cascaded.lights[v.light];
            std::cout << "  " << std::left << std::setw(18) << v.name << std::right << std::setw(5) << v.resolution
                      << "² " << depthFormatName(v.format) << "  ";
            if (!v.ran) {  // cleared, not drawn: nothing to compare
                std::cout << v.reason << "\n";
                cascades.push_back({{"view", v.name}, {"light", v.light}, {"cascade", v.index}, {"ran", false},
                                    {"reason", v.reason}});
                continue;
            }
            BareDepthDraw bare(scene, last.renderOrigin, source, &held);
            const BareDrawTiming timing =
                bare.time(v.space.viewProjection(), v.resolution, v.format, info.maxTextureSize, options.frames);
            if (!timing.ok) return fail("bare draw for " + v.name + ": " + timing.error);
            const double shadowMs = medianOf(perView[v.name]);
            const double ratio = timing.ms > 0.0 ? shadowMs / timing.ms : 0.0;
            std::cout << std::setw(6) << v.castersDrawn << " casters in " << v.drawCalls << " draw calls "
                      << std::setw(9) << v.triangles << " triangles  shadow " << std::setprecision(3) << std::setw(8)
                      << shadowMs << " ms  bare " << std::setw(8) << timing.ms << " ms  ratio " << std::setprecision(2)
                      << ratio << (ratio <= kCascadeTargetRatio ? "" : "  (over the target)") << "\n";
            cascades.push_back({{"view", v.name}, {"light", v.light}, {"cascade", v.index}, {"ran", true},
                                {"direction", {light.direction.x, light.direction.y, light.direction.z}},
                                {"resolution", v.resolution}, {"format", depthFormatName(v.format)},
                                {"casters", v.castersDrawn}, {"drawCalls", v.drawCalls},
                                {"heldInstances", heldCount},
                                {"triangles", v.triangles}, {"bareTriangles", bare.triangles()},
                                {"shadowMs", shadowMs}, {"bareMs", timing.ms}, {"ratio", ratio}});
        }
        doc["cascades"] = cascades;
        doc["cascadeTimingSource"] = last.timingSource;
        doc["cascadeTargetRatio"] = kCascadeTargetRatio;
        if (int failed = writeBenchJson(options.json, doc)) return failed;
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}

}  // namespace shadowlab::cli
