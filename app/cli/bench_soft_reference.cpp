#include "cli/bench_soft_reference.h"
#include "cli/bench_input.h"

#include "accuracy/gbuffer_pass.h"
#include "accuracy/light_isolation.h"
#include "cli/bench_reference_update.h"
#include "cli/command_input.h"
#include "cli/json_output.h"
#include "context/headless_context.h"
#include "frame/camera.h"
#include "frame/gpu_scene.h"
#include "reference/embree_scene.h"
#include "reference/parallel_rows.h"
#include "reference/soft_visibility.h"
#include "reference/visibility.h"
#include "scene/scene_casters.h"
#include "scene/scene_source.h"
#include "settings/settings_fields.h"
#include "views/shadow_view.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace shadowlab::cli {

namespace {

std::string describe(const char* what, const SoftVisibilityResult& r) {
    char text[200];
    std::snprintf(text, sizeof text, "  %-34s %9.1f ms, %llu rays = %.1f Mrays/s", what, r.milliseconds,
                  static_cast<unsigned long long>(r.rays),
                  r.milliseconds > 0.0 ? double(r.rays) / (r.milliseconds * 1e3) : 0.0);
    return text;
}

}  // namespace

int runBenchSoftReference(const BenchOptions& options) {
    const BenchInput input = readBenchInput(options);
    if (input.refused) return input.refused;
    const Scene& scene = *input.loaded.scene;
    const Settings& given = *input.settings;
    const std::vector<std::size_t> casting = castingLights(given, scene);
    if (casting.empty()) return fail("bench --soft-reference: no light of " + scene.name + " casts a shadow");
    std::string error;
    const std::optional<Settings> settings = isolateLight(given, scene, casting.front(), error);
    if (!settings) return fail("bench --soft-reference: " + error);
    const LightSettings& lightSettings = settings->lights[0];
    const SoftLight disc = softLight(lightSettings, settings->reference.softRays);
    if (!disc.soft())
        return fail("bench --soft-reference: lights." + std::to_string(casting.front()) +
                    ".size is 0 (a hard light has no soft reference): set it, e.g. --set lights." +
                    std::to_string(casting.front()) + ".size=0.53");
    try {
        HeadlessContext context;
        const glm::dvec3 origin = renderOriginOf(scene.bounds);
        const GpuScene gpuScene(scene, origin);
        const Camera camera = cameraFor(settings->camera, scene, double(options.width) / options.height);
        const glm::dmat4 viewProjection =
            camera.projection(double(options.width) / options.height) * camera.view(origin);
        GBufferPass gbuffer;
        SurfaceSamples samples;
        if (std::string e = gbuffer.render(gpuScene, viewProjection, options.width, options.height,
                                           camera.position - origin, samples);
            !e.empty())
            return fail(e);
        const EmbreeScene bvh(scene, origin, castingInstances(scene, settings->casters));
        const ReferenceLight light = referenceLight(lightSettings, origin);
        const double radius = scene.bounds.empty ? 1.0 : double(scene.bounds.radius());
        const VisibilityResult hard = traceVisibility(bvh, samples, light, radius, nullptr);
        const SoftVisibilityResult eachRay =
            traceSoftVisibility(bvh, samples, hard.classes, light, disc, radius, nullptr, 0, SoftTracing::EachRay);
        const SoftVisibilityResult stream =
            traceSoftVisibility(bvh, samples, hard.classes, light, disc, radius, nullptr, 0, SoftTracing::Stream);
        std::size_t traced = 0, differ = 0;
        double maxDifference = 0.0;
        for (std::size_t i = 0; i < samples.size(); ++i) {
            traced += hard.classes[i] == PixelClass::Lit || hard.classes[i] == PixelClass::Shadowed;
            const double d = std::abs(double(eachRay.visibility[i]) - double(stream.visibility[i]));
            differ += d > 0.0;
            maxDifference = std::max(maxDifference, d);
        }
        const double speedup = stream.milliseconds > 0.0 ? eachRay.milliseconds / stream.milliseconds : 0.0;
        const std::string cpu = cpuName();
        std::cout << "bench --soft-reference: " << scene.name << " at " << options.width << "x" << options.height
                  << ", light " << casting.front() << " (" << lightTypeName(lightSettings.type) << ", size "
                  << lightSettings.size << (lightSettings.type == LightType::Directional ? " degrees" : " world units")
                  << "), " << disc.rays << " rays per pixel, " << traced << " pixels traced; " << bvh.triangles()
                  << " triangles; CPU: " << cpu << ", " << stream.threads << " threads\n"
                  << describe("one rtcOccluded1 per ray:", eachRay) << "\n"
                  << describe("a pixel's rays in one stream query:", stream) << "\n";
        char text[200];
        std::snprintf(text, sizeof text,
                      "  speed-up %.2fx; V differs in %zu of %zu pixels, max |dV| = %.6f (%g rays of %d)\n", speedup,
                      differ, traced, maxDifference, maxDifference * disc.rays, disc.rays);
        std::cout << text;
        if (!options.json.empty()) {
            const nlohmann::json doc = {
                {"scene", scene.name},           {"width", options.width},
                {"height", options.height},      {"light", casting.front()},
                {"size", lightSettings.size},    {"raysPerPixel", disc.rays},
                {"pixelsTraced", traced},        {"triangles", bvh.triangles()},
                {"cpu", cpu},                    {"threads", stream.threads},
                {"eachRayMs", eachRay.milliseconds}, {"eachRayRays", eachRay.rays},
                {"streamMs", stream.milliseconds},   {"streamRays", stream.rays},
                {"speedup", speedup},            {"pixelsDiffering", differ},
                {"maxAbsDifference", maxDifference}};
            if (std::string e = writeJsonOutput(options.json, doc); !e.empty()) return fail(e);
        }
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    return 0;
}

}  // namespace shadowlab::cli
