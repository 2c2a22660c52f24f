// HARD_CASES 16: degenerate geometry. BoxWithInfinites (+-inf x coordinates, accepted by tinygltf), 2CylinderEngine
// (10,419 zero-area triangles), and the ../shared *.original.gltf.json copies whose textures are missing: the fit
// ignores non-finite vertices, the map and the light's matrix stay valid, nothing crashes.
#include "hardcases/cases.h"

#include "hardcases/uniform_readback.h"
#include "light/light_space.h"
#include "scene/builtin_scenes.h"

#include <filesystem>
#include <limits>

#include <glm/geometric.hpp>

#include <cmath>

namespace shadowlab::hardcases {

namespace {

std::size_t zeroAreaTriangles(const Scene& scene) {
    std::size_t n = 0;
    for (const Mesh& m : scene.meshes)
        for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
            const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                            c = m.positions[m.indices[t + 2]];
            n += glm::length(glm::cross(b - a, c - a)) == 0.0f;
        }
    return n;
}

// Renders and measures `scene`; one row saying whether the frame, the light's matrix, the uniforms and the
// measurement stayed valid.
void checkScene(CaseContext& context, CaseResult& result, const Scene& scene, const std::string& label,
                const std::string& picture) {
    Settings s;
    s.lights[0].shadow.resolution = context.pick(2048, 512);
    const int width = context.pick(320, 160), height = context.pick(180, 90);
    const RenderedView view = context.render(scene, s, width, height);
    std::vector<std::string> bad;
    if (!view.stats.ok) bad.push_back(view.stats.error);
    if (view.stats.ok && !allFinite(view.stats.light.viewProjection())) bad.push_back("non-finite light matrix");
    if (view.stats.ok)
        for (const std::string& u : nonFiniteUniforms()) bad.push_back("non-finite uniform " + u);
    if (!std::isfinite(scene.bounds.radius())) bad.push_back("non-finite bounds");
    const AccuracyReport r = context.measure(scene, s, width, height, picture);
    if (!r.ok) bad.push_back("measure: " + r.error);
    const std::string fig = bad.empty() ? "valid (wrong pixels " + percent(r.wrongPercent) + ")" : bad.front();
    result.check(label + ": frame, light matrix, uniforms, measurement", fig, "all valid, no crash", bad.empty());
}

}  // namespace

void runDegenerateGeometry(CaseContext& context, CaseResult& result) {
    std::string why;
    const char* boxFile = "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb";
    if (std::optional<Scene> box = context.assimpScene(boxFile, why)) {
        checkScene(context, result, *box, "BoxWithInfinites", "box-with-infinites");
    } else if (std::filesystem::exists(context.options().assimpModels + "/" + boxFile)) {
        // Every triangle of the file has an infinite vertex: the loader skips them all and says so.
        result.check("BoxWithInfinites.glb: refused with a message", why, "a clear message, no crash",
                     why.find("non-finite") != std::string::npos);
    } else {
        result.notRun("BoxWithInfinites", "finite fit, valid map", why);
    }
    // The same vertices inside a scene with finite geometry: a triangle with an infinite corner beside textbook.
    Scene mixed = *makeBuiltinScene("textbook");
    Mesh broken;
    broken.name = "broken";
    const float inf = std::numeric_limits<float>::infinity();
    broken.positions = {{0, 5, 0}, {inf, 5, 0}, {0, 5, -inf}};
    broken.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    broken.indices = {0, 1, 2};
    mixed.meshes.push_back(broken);
    mixed.instances.push_back({int(mixed.meshes.size() - 1), glm::mat4(1.0f)});
    const Bounds before = makeBuiltinScene("textbook")->bounds;
    mixed.computeBounds();
    const bool ignored = mixed.bounds.min == glm::min(before.min, glm::vec3(0, 5, 0)) &&
                         mixed.bounds.max == glm::max(before.max, glm::vec3(0, 5, 0));
    result.check("textbook + a triangle with +-inf corners: the fit", ignored ? "the finite vertices only" : "changed",
                 "non-finite vertices ignored", ignored);
    checkScene(context, result, mixed, "textbook + infinite triangle", "infinite-triangle");
    if (std::optional<Scene> engine = context.assimpScene("2CylinderEngine-glTF-Binary/2CylinderEngine.glb", why)) {
        result.info("2CylinderEngine: zero-area triangles", std::to_string(zeroAreaTriangles(*engine)), "");
        checkScene(context, result, *engine, "2CylinderEngine", "2cylinder-engine");
    } else {
        result.notRun("2CylinderEngine", "valid map", why);
    }
    const char* copies[] = {"FlightHelmet_geometry/FlightHelmet.original.gltf.json",
                            "Lantern_geometry/Lantern.original.gltf.json",
                            "IntelSponza_Curtains_geometry/sponza_curtains.original.gltf.json"};
    for (const char* copy : copies) {
        if (context.quick() && std::string(copy).find("Lantern") == std::string::npos) continue;
        const std::optional<Scene> scene = context.sharedScene(copy, why);
        const std::string name = std::string(copy).substr(std::string(copy).find('/') + 1);
        if (!scene) {
            result.check(name + " (missing textures): loads", why, "loads with warnings", false);
            continue;
        }
        checkScene(context, result, *scene, name + " (" + std::to_string(scene->warnings.size()) + " warnings)",
                   name.substr(0, name.find('.')) + "-missing-textures");
    }
}

}  // namespace shadowlab::hardcases
