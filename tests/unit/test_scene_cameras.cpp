// The file's cameras and nodes (tests/data/scenes/sky_box_city.gltf): cameras placed by their nodes, hostile ones
// refused one by one; node paths and the casters.excluded key. (The camera a sceneCamera gives:
// gl/test_scene_camera_view.cpp.)
#include "scene/gltf_loader.h"
#include "scene/scene_casters.h"
#include "settings/preset_io.h"
#include "settings/settings_fields.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

using namespace shadowlab;

namespace {

const std::string kCityPath = std::string(SHADOWLAB_SOURCE_DIR) + "/tests/data/scenes/sky_box_city.gltf";

Scene loadCity() {
    SceneLoadResult r = loadGltfScene(kCityPath);
    EXPECT_TRUE(r.scene) << r.error;
    return r.scene ? std::move(*r.scene) : Scene{};
}

bool hasWarning(const Scene& scene, const std::string& part) {
    return std::any_of(scene.warnings.begin(), scene.warnings.end(),
                       [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

int nodeByPath(const Scene& scene, const std::string& path) {
    for (std::size_t i = 0; i < scene.nodes.size(); ++i)
        if (scene.nodes[i].path == path) return int(i);
    return -1;
}

}  // namespace

TEST(SceneCameras, CamerasArePlacedByTheirNodesAndHostileOnesAreRefusedAlone) {
    const Scene scene = loadCity();
    EXPECT_EQ(scene.invariantError(), "");
    ASSERT_EQ(scene.cameras.size(), 3u);  // Street, Top, the unnamed infinite one; four refused
    const SceneCamera& street = scene.cameras[0];
    EXPECT_EQ(street.name, "Street");
    EXPECT_EQ(street.index, 0);
    EXPECT_FALSE(street.orthographic);
    EXPECT_NEAR(street.yfovRad, 0.9, 1e-12);
    EXPECT_NEAR(street.znear, 0.1, 1e-12);
    EXPECT_NEAR(street.zfar, 200.0, 1e-12);
    EXPECT_NEAR(glm::length(street.position - glm::dvec3(0.0, 6.0, 16.0)), 0.0, 1e-9);
    // Rotated -20 degrees about +x: looking along -z and down.
    EXPECT_NEAR(street.forward.x, 0.0, 1e-6);
    EXPECT_NEAR(street.forward.y, -std::sin(glm::radians(20.0)), 1e-6);
    EXPECT_NEAR(street.forward.z, -std::cos(glm::radians(20.0)), 1e-6);

    const SceneCamera& top = scene.cameras[1];
    EXPECT_EQ(top.name, "Top");
    EXPECT_TRUE(top.orthographic);
    EXPECT_NEAR(top.ymag, 12.0, 1e-12);
    EXPECT_NEAR(top.forward.y, -1.0, 1e-6);

    // Unnamed camera: its node's name; no zfar = infinite.
    EXPECT_EQ(scene.cameras[2].name, "Infinite");
    EXPECT_EQ(scene.cameras[2].zfar, 0.0);

    // Each hostile camera: one warning naming its index and why; the file still loads.
    EXPECT_TRUE(hasWarning(scene, "camera 3 ('zero fov') refused: yfov 0"));
    EXPECT_TRUE(hasWarning(scene, "camera 4 ('negative near') refused: znear -1"));
    EXPECT_TRUE(hasWarning(scene, "camera 5 ('far before near') refused: zfar 2 is not greater than znear 5"));
    EXPECT_TRUE(hasWarning(scene, "camera 6 ('flat ortho') refused: ymag 0"));
    EXPECT_GT(scene.instances.size(), 2u);
}

TEST(SceneCameras, CamerasTinygltfCannotParseAreRefusedAloneInGltfAndGlb) {
    std::ifstream file(kCityPath);
    std::stringstream text;
    text << file.rdbuf();
    nlohmann::json doc = nlohmann::json::parse(text.str());
    // Three cameras tinygltf alone would refuse the whole file for, each placed by a node of its own.
    const nlohmann::json broken = nlohmann::json::array(
        {{{"name", "no fov"}, {"type", "perspective"}, {"perspective", {{"znear", 0.1}}}},
         {{"name", "word fov"}, {"type", "perspective"}, {"perspective", {{"yfov", "wide"}, {"znear", 0.1}}}},
         {{"name", "no object"}, {"type", "orthographic"}}});
    for (const nlohmann::json& camera : broken) {
        doc["cameras"].push_back(camera);
        doc["nodes"][5]["children"].push_back(doc["nodes"].size());
        doc["nodes"].push_back({{"camera", doc["cameras"].size() - 1}});
    }
    const std::string gltf = doc.dump();
    // The same as a GLB: 12-byte header, one JSON chunk padded to 4 bytes (the buffer is a data: URI).
    std::string padded = gltf;
    while (padded.size() % 4) padded += ' ';
    std::vector<unsigned char> glb(12 + 8 + padded.size());
    const std::uint32_t header[5] = {0x46546C67u, 2u, std::uint32_t(glb.size()), std::uint32_t(padded.size()),
                                     0x4E4F534Au};
    std::memcpy(glb.data(), header, sizeof header);
    std::memcpy(glb.data() + 20, padded.data(), padded.size());

    for (const std::vector<unsigned char>& bytes :
         {std::vector<unsigned char>(gltf.begin(), gltf.end()), glb}) {
        SceneLoadResult r = loadGltfSceneFromMemory(bytes, "city", ".");
        ASSERT_TRUE(r.scene) << r.error;
        EXPECT_EQ(r.scene->cameras.size(), 3u) << "the good cameras still load";
        EXPECT_GT(r.scene->instances.size(), 2u);
        EXPECT_TRUE(hasWarning(*r.scene, "camera 7 ('no fov') refused: yfov is missing"));
        EXPECT_TRUE(hasWarning(*r.scene, "camera 8 ('word fov') refused: yfov \"wide\" is not a number"));
        EXPECT_TRUE(hasWarning(*r.scene, "camera 9 ('no object') refused: it has no \"orthographic\" object"));
    }
}

TEST(SceneCameras, NodePathsNameTheHierarchy) {
    const Scene scene = loadCity();
    EXPECT_GE(nodeByPath(scene, "Root/City/SkyBox"), 0);
    EXPECT_GE(nodeByPath(scene, "Root/City/Tower"), 0);
    EXPECT_GE(nodeByPath(scene, "Root/Cameras/#7"), 0);  // an unnamed node: its glTF index
    const SceneNode& city = scene.nodes[std::size_t(nodeByPath(scene, "Root/City"))];
    EXPECT_EQ(city.children.size(), 3u);
    EXPECT_EQ(scene.nodes[std::size_t(city.parent)].path, "Root");
    EXPECT_EQ(nodePathSegment("a/b\\c", 3), "a\\/b\\\\c");
    EXPECT_EQ(nodePathSegment("#3", 5), "\\#3");  // a name is never read as an unnamed node
    EXPECT_EQ(nodePathSegment("", 5), "#5");
}

TEST(SceneCasters, AnExcludedNodeTakesItsSubtreeAndUnknownPathsAreWarnings) {
    const Scene scene = loadCity();
    const int sky = nodeByPath(scene, "Root/City/SkyBox"), tower = nodeByPath(scene, "Root/City/Tower");
    CasterSettings casters;
    auto casting = [&](int node) {
        const std::vector<char> flags = castingInstances(scene, casters);
        for (std::size_t i = 0; i < scene.instances.size(); ++i)
            if (scene.instances[i].node == node) return bool(flags[i]);
        ADD_FAILURE() << "no instance of node " << node;
        return false;
    };
    EXPECT_TRUE(casting(sky));
    casters.excluded = {"Root/City/SkyBox"};
    EXPECT_FALSE(casting(sky));
    EXPECT_TRUE(casting(tower));
    casters.excluded = {"Root/City"};  // the subtree
    EXPECT_FALSE(casting(sky));
    EXPECT_FALSE(casting(tower));
    EXPECT_TRUE(unknownCasterPathWarnings(scene, casters).empty());

    casters.excluded = {"Root/City/Gone"};
    EXPECT_TRUE(casting(sky));
    const std::vector<std::string> warnings = unknownCasterPathWarnings(scene, casters);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("casters.excluded: no node 'Root/City/Gone' in scene sky_box_city"), std::string::npos);
}

TEST(SceneCasters, ExcludedKeyThroughSetAndPresets) {
    Settings s;
    EXPECT_TRUE(s.casters.excluded.empty());
    ASSERT_EQ(applySettingOverride(s, "casters.excluded=Root/City/SkyBox"), "");  // a bare path: a list of one
    EXPECT_EQ(s.casters.excluded, std::vector<std::string>{"Root/City/SkyBox"});
    ASSERT_EQ(applySettingOverride(s, R"(casters.excluded=["A", "B/C", "A"])"), "");  // repeats dropped
    EXPECT_EQ(s.casters.excluded, (std::vector<std::string>{"A", "B/C"}));
    const std::string error = applySettingOverride(s, "casters.excluded=[1]");
    EXPECT_NE(error.find("casters.excluded: entry 1 is not a non-empty string"), std::string::npos) << error;
    EXPECT_EQ(s.casters.excluded, (std::vector<std::string>{"A", "B/C"}));  // untouched on error

    // Round trip through a preset, as {"casters": {"excluded": [...]}}.
    const PresetLoadResult back = presetFromText(presetToText(s));
    ASSERT_TRUE(back.settings) << (back.errors.empty() ? "" : back.errors.front());
    EXPECT_EQ(back.settings->casters.excluded, s.casters.excluded);
    EXPECT_NE(presetToText(s).find(R"("casters": {)"), std::string::npos);

    // An old preset (no casters, no sceneCamera) loads unchanged: everything casts, the free camera.
    const PresetLoadResult old = presetFromText(R"({"schema": "shadowlab-preset", "schemaVersion": 2, "lights": [{}]})");
    ASSERT_TRUE(old.settings);
    EXPECT_TRUE(old.settings->casters.excluded.empty());
    EXPECT_EQ(old.settings->camera.sceneCamera, -1);
    EXPECT_TRUE(old.warnings.empty());
}
