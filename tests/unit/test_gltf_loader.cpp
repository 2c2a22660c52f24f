// glTF loading: tiny files written here (hierarchy, mirrors, lights, materials, broken data), the real scenes in
// ../shared/scenes, and every glTF in the assimp-testmodels corpus (good and broken: never a crash).
#include "scene/gltf_loader.h"
#include "scene/scene_source.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <set>

using namespace shadowlab;
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

constexpr int kFloat = 5126, kUShort = 5123, kUByte = 5121, kUInt = 5125;

struct TempDir {
    fs::path path;
    TempDir() {
        std::random_device rd;
        path = fs::temp_directory_path() / ("shadowlab_gltf_test_" + std::to_string(rd()) + std::to_string(rd()));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

void writeBytes(const std::string& path, const void* data, std::size_t size) {
    std::ofstream(path, std::ios::binary).write(static_cast<const char*>(data), std::streamsize(size));
}

void writeText(const std::string& path, const std::string& text) { writeBytes(path, text.data(), text.size()); }

// Builds a glTF: one binary buffer, JSON edited directly by the tests.
struct GltfBuilder {
    json j = {{"asset", {{"version", "2.0"}}}};
    std::vector<std::uint8_t> bin;

    int view(const void* data, std::size_t bytes, int stride = 0) {
        while (bin.size() % 4) bin.push_back(0);
        json v = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
        if (stride) v["byteStride"] = stride;
        const auto* p = static_cast<const std::uint8_t*>(data);
        bin.insert(bin.end(), p, p + bytes);
        j["bufferViews"].push_back(v);
        return int(j["bufferViews"].size()) - 1;
    }
    int accessor(json a) {
        j["accessors"].push_back(std::move(a));
        return int(j["accessors"].size()) - 1;
    }
    template <typename T>
    int accessor(const std::vector<T>& data, int componentType, std::size_t count, const char* type) {
        const int v = view(data.data(), data.size() * sizeof(T));
        return accessor({{"bufferView", v}, {"componentType", componentType}, {"count", count}, {"type", type}});
    }
    int positions(const std::vector<glm::vec3>& p) {
        std::vector<float> f;
        for (const glm::vec3& v : p) f.insert(f.end(), {v.x, v.y, v.z});
        return accessor(f, kFloat, p.size(), "VEC3");
    }
    int indices(const std::vector<std::uint16_t>& i) { return accessor(i, kUShort, i.size(), "SCALAR"); }
    int mesh(json primitives) {
        j["meshes"].push_back({{"primitives", std::move(primitives)}});
        return int(j["meshes"].size()) - 1;
    }
    int node(json n) {
        j["nodes"].push_back(std::move(n));
        return int(j["nodes"].size()) - 1;
    }
    void scene(const std::vector<int>& roots) {
        j["scenes"] = {{{"nodes", roots}}};
        j["scene"] = 0;
    }

    // Writes NAME.gltf (+ NAME.bin unless writeBin is false); returns the .gltf path.
    std::string write(const TempDir& dir, const std::string& name, bool writeBin = true) {
        if (!bin.empty()) j["buffers"] = {{{"uri", name + ".bin"}, {"byteLength", bin.size()}}};
        if (writeBin && !bin.empty()) writeBytes(dir.file(name + ".bin"), bin.data(), bin.size());
        writeText(dir.file(name + ".gltf"), j.dump(1));
        return dir.file(name + ".gltf");
    }
    // Writes a GLB (JSON + BIN chunks).
    std::string writeGlb(const TempDir& dir, const std::string& fileName) {
        json jj = j;
        if (!bin.empty()) jj["buffers"] = {{{"byteLength", bin.size()}}};
        std::string text = jj.dump();
        while (text.size() % 4) text.push_back(' ');
        std::vector<std::uint8_t> body = bin;
        while (body.size() % 4) body.push_back(0);
        std::vector<std::uint8_t> out;
        auto u32 = [&](std::uint32_t v) { for (int i = 0; i < 4; ++i) out.push_back(std::uint8_t(v >> (8 * i))); };
        u32(0x46546C67);  // "glTF"
        u32(2);
        u32(std::uint32_t(12 + 8 + text.size() + (body.empty() ? 0 : 8 + body.size())));
        u32(std::uint32_t(text.size()));
        u32(0x4E4F534A);  // "JSON"
        out.insert(out.end(), text.begin(), text.end());
        if (!body.empty()) {
            u32(std::uint32_t(body.size()));
            u32(0x004E4942);  // "BIN\0"
            out.insert(out.end(), body.begin(), body.end());
        }
        writeBytes(dir.file(fileName), out.data(), out.size());
        return dir.file(fileName);
    }
};

// A unit quad in the xy plane facing +z (two CCW triangles).
int addQuadMesh(GltfBuilder& g, json extraPrimitive = json::object()) {
    const int pos = g.positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    const int idx = g.indices({0, 1, 2, 0, 2, 3});
    json prim = {{"attributes", {{"POSITION", pos}}}, {"indices", idx}};
    prim.update(extraPrimitive);
    return g.mesh(json::array({prim}));
}

bool anyWarningContains(const Scene& s, const std::string& text) {
    for (const std::string& w : s.warnings)
        if (w.find(text) != std::string::npos) return true;
    return false;
}

std::string allWarnings(const Scene& s) {
    std::string out;
    for (const std::string& w : s.warnings) out += "\n  " + w;
    return out;
}

// Uncompressed 32-bit TGA, top-left origin (stb_image decodes it; no encoder needed in the test).
void writeTga(const std::string& path, int w, int h, const std::vector<std::uint8_t>& rgba) {
    std::vector<std::uint8_t> out(18, 0);
    out[2] = 2;
    out[12] = std::uint8_t(w);
    out[13] = std::uint8_t(w >> 8);
    out[14] = std::uint8_t(h);
    out[15] = std::uint8_t(h >> 8);
    out[16] = 32;
    out[17] = 0x28;  // 8 alpha bits, origin top-left
    for (std::size_t i = 0; i < rgba.size(); i += 4) out.insert(out.end(), {rgba[i + 2], rgba[i + 1], rgba[i], rgba[i + 3]});
    writeBytes(path, out.data(), out.size());
}

void expectVecNear(const glm::vec3& a, const glm::vec3& e, float tol) {
    EXPECT_NEAR(a.x, e.x, tol);
    EXPECT_NEAR(a.y, e.y, tol);
    EXPECT_NEAR(a.z, e.z, tol);
}

const std::string kAssimpGltf2 = "/usr/share/assimp/models/glTF2";

}  // namespace

// ---- small files written by the tests ----------------------------------------------------------------------------

TEST(GltfLoader, MinimalQuadGetsSmoothNormalsAndName) {
    TempDir dir;
    GltfBuilder g;
    g.scene({g.node({{"mesh", addQuadMesh(g)}})});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "quad"));
    ASSERT_TRUE(r.ok()) << r.error;
    const Scene& s = *r.scene;
    EXPECT_EQ(s.name, "quad");
    EXPECT_EQ(s.invariantError(), "");
    EXPECT_EQ(s.triangleCount(), 2u);
    for (const glm::vec3& n : s.meshes[0].normals) expectVecNear(n, {0, 0, 1}, 1e-6f);
    expectVecNear(s.bounds.min, {0, 0, 0}, 0);
    expectVecNear(s.bounds.max, {1, 1, 0}, 0);
    EXPECT_TRUE(s.warnings.empty()) << allWarnings(s);
}

TEST(GltfLoader, HierarchyWithTrsAndMatrix) {
    TempDir dir;
    GltfBuilder g;
    const int mesh = addQuadMesh(g);
    // child: matrix = translate(0,2,0); parent: translate(1,0,0) * rotate 90 deg about y.
    const int child = g.node({{"mesh", mesh}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 2, 0, 1}}});
    const float s = std::sqrt(0.5f);
    g.scene({g.node({{"children", {child}}, {"translation", {1, 0, 0}}, {"rotation", {0, s, 0, s}}})});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "hier"));
    ASSERT_TRUE(r.ok()) << r.error;
    ASSERT_EQ(r.scene->instances.size(), 1u);
    const glm::mat4& m = r.scene->instances[0].transform;
    expectVecNear(glm::vec3(m * glm::vec4(0, 0, 0, 1)), {1, 2, 0}, 1e-6f);
    expectVecNear(glm::vec3(m * glm::vec4(1, 0, 0, 0)), {0, 0, -1}, 1e-6f);  // +x turned 90 deg about +y
}

TEST(GltfLoader, MirroredInstanceKeepsItsTransform) {
    TempDir dir;
    GltfBuilder g;
    const int mesh = addQuadMesh(g);
    g.scene({g.node({{"mesh", mesh}}), g.node({{"mesh", mesh}, {"scale", {-1, 1, 1}}, {"translation", {-3, 0, 0}}})});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "mirror"));
    ASSERT_TRUE(r.ok()) << r.error;
    const Scene& s = *r.scene;
    ASSERT_EQ(s.instances.size(), 2u);
    EXPECT_EQ(s.meshes.size(), 1u);  // one glTF mesh, instanced twice
    EXPECT_FALSE(s.instances[0].mirrored());
    EXPECT_TRUE(s.instances[1].mirrored());
    EXPECT_FLOAT_EQ(s.instances[1].transform[0][0], -1.0f);
    expectVecNear(s.bounds.min, {-4, 0, 0}, 1e-6f);
}

TEST(GltfLoader, KhrLightsPunctual) {
    TempDir dir;
    GltfBuilder g;
    g.j["extensionsUsed"] = {"KHR_lights_punctual"};
    g.j["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "directional"}, {"name", "sun"}, {"color", {1.0, 0.9, 0.8}}, {"intensity", 3.0}},
        {{"type", "spot"}, {"range", 20.0}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}},
        {{"type", "point"}, {"intensity", 7.0}}};
    auto lightNode = [](int light, json n) {
        n["extensions"]["KHR_lights_punctual"]["light"] = light;
        return n;
    };
    const float h = std::sqrt(0.5f);
    // Sun: -90 deg about x turns -Z into -Y (straight down).
    const int sun = g.node(lightNode(0, {{"rotation", {-h, 0, 0, h}}}));
    // Spot: child of a parent translated to (0,5,0), itself turned 90 deg about y: -Z becomes -X.
    const int spot = g.node(lightNode(1, {{"translation", {1, 0, 0}}}));
    const int parent = g.node({{"translation", {0, 5, 0}}, {"rotation", {0, h, 0, h}}, {"children", {spot}}});
    const int point = g.node(lightNode(2, {{"translation", {2, 3, 4}}}));
    g.scene({g.node({{"mesh", addQuadMesh(g)}}), sun, parent, point});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "lights"));
    ASSERT_TRUE(r.ok()) << r.error;
    const auto& lights = r.scene->lights;
    ASSERT_EQ(lights.size(), 3u);
    EXPECT_EQ(lights[0].type, SceneLightType::Directional);
    EXPECT_EQ(lights[0].name, "sun");
    expectVecNear(lights[0].direction, {0, -1, 0}, 1e-6f);
    expectVecNear(lights[0].color, {1.0f, 0.9f, 0.8f}, 1e-6f);
    EXPECT_FLOAT_EQ(lights[0].intensity, 3.0f);
    EXPECT_EQ(lights[1].type, SceneLightType::Spot);
    expectVecNear(lights[1].position, {0, 5, -1}, 1e-6f);  // (1,0,0) turned 90 deg about y is (0,0,-1)
    expectVecNear(lights[1].direction, {-1, 0, 0}, 1e-6f);
    EXPECT_FLOAT_EQ(lights[1].outerConeRad, 0.5f);
    EXPECT_FLOAT_EQ(lights[1].range, 20.0f);
    EXPECT_EQ(lights[2].type, SceneLightType::Point);
    expectVecNear(lights[2].position, {2, 3, 4}, 1e-6f);
    EXPECT_FLOAT_EQ(lights[2].range, 0.0f);  // infinite
    EXPECT_FLOAT_EQ(lights[2].intensity, 7.0f);
}

TEST(GltfLoader, IndicesOutOfRangeDropThatPrimitiveOnly) {
    TempDir dir;
    GltfBuilder g;
    const int pos = g.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int good = g.indices({0, 1, 2});
    const int bad = g.indices({0, 1, 7});
    g.scene({g.node({{"mesh", g.mesh({{{"attributes", {{"POSITION", pos}}}, {"indices", bad}},
                                      {{"attributes", {{"POSITION", pos}}}, {"indices", good}}})}})});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "oor"));
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene->triangleCount(), 1u);
    EXPECT_TRUE(anyWarningContains(*r.scene, "out of range")) << allWarnings(*r.scene);
}

TEST(GltfLoader, OnlyBrokenPrimitivesMeansNoTriangleGeometry) {
    TempDir dir;
    GltfBuilder g;
    const int pos = g.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    g.scene({g.node({{"mesh", g.mesh({{{"attributes", {{"POSITION", pos}}}, {"indices", g.indices({5, 6, 7})}}})}})});
    const std::string path = g.write(dir, "allbad");
    const SceneLoadResult r = loadGltfScene(path);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error.find(path), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("no triangle geometry"), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("out of range"), std::string::npos) << r.error;
}

TEST(GltfLoader, MissingBinIsAClearError) {
    TempDir dir;
    GltfBuilder g;
    g.scene({g.node({{"mesh", addQuadMesh(g)}})});
    const std::string path = g.write(dir, "nobin", /*writeBin=*/false);
    const SceneLoadResult r = loadScene(path);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error.find(path), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("nobin.bin"), std::string::npos) << r.error;
}

TEST(GltfLoader, ShortBinAndShortGlbChunkAreClearErrors) {
    TempDir dir;
    GltfBuilder g;
    g.scene({g.node({{"mesh", addQuadMesh(g)}})});
    const std::string path = g.write(dir, "short");
    writeBytes(dir.file("short.bin"), g.bin.data(), g.bin.size() / 2);  // the .bin lost its second half
    const SceneLoadResult r = loadGltfScene(path);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error.find("short.bin"), std::string::npos) << r.error;

    // A GLB whose buffer claims more bytes than its BIN chunk holds.
    const std::size_t realSize = g.bin.size();
    g.bin.resize(realSize / 2);
    const SceneLoadResult glb = loadGltfScene(g.writeGlb(dir, "short.glb"));
    EXPECT_FALSE(glb.ok());
    EXPECT_NE(glb.error.find("short.glb"), std::string::npos) << glb.error;
    std::cout << "  " << r.error << "\n  " << glb.error << "\n";
}

TEST(GltfLoader, AccessorPastTheEndOfItsViewIsRejected) {
    TempDir dir;
    GltfBuilder g;
    const int pos = g.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    g.j["accessors"][pos]["count"] = 300;  // claims more than the view holds
    g.scene({g.node({{"mesh", g.mesh({{{"attributes", {{"POSITION", pos}}}}})}})});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "short"));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error.find("do not fit"), std::string::npos) << r.error;
}

TEST(GltfLoader, CyclicNodeGraphIsCut) {
    TempDir dir;
    GltfBuilder g;
    const int mesh = addQuadMesh(g);
    g.node({{"children", {1}}});
    g.node({{"mesh", mesh}, {"children", {0}}});
    g.scene({0});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "cycle"));
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene->instances.size(), 1u);
    EXPECT_TRUE(anyWarningContains(*r.scene, "cycle")) << allWarnings(*r.scene);
}

TEST(GltfLoader, NonFinitePositionsDropTheirTriangles) {
    TempDir dir;
    GltfBuilder g;
    const float inf = std::numeric_limits<float>::infinity();
    const int pos = g.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {inf, 0, 0}, {1, 1, 0}});
    const int idx = g.indices({0, 1, 2, 1, 3, 4, 1, 4, 2});
    g.scene({g.node({{"mesh", g.mesh({{{"attributes", {{"POSITION", pos}}}, {"indices", idx}}})}})});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "inf"));
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene->triangleCount(), 2u);
    EXPECT_EQ(r.scene->meshes[0].positions.size(), 4u);  // the inf vertex is gone
    EXPECT_EQ(r.scene->invariantError(), "");
    expectVecNear(r.scene->bounds.max, {1, 1, 0}, 0);
    EXPECT_TRUE(anyWarningContains(*r.scene, "non-finite")) << allWarnings(*r.scene);
}

TEST(GltfLoader, StripsAndFansBecomeTrianglesLinesAreSkipped) {
    TempDir dir;
    GltfBuilder g;
    const int pos = g.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
    const int fanPos = g.positions({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    g.scene({g.node({{"mesh", g.mesh({{{"attributes", {{"POSITION", pos}}}, {"mode", 5}},
                                      {{"attributes", {{"POSITION", fanPos}}}, {"mode", 6}},
                                      {{"attributes", {{"POSITION", pos}}}, {"mode", 1}}})}})});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "modes"));
    ASSERT_TRUE(r.ok()) << r.error;
    const Scene& s = *r.scene;
    ASSERT_EQ(s.meshes.size(), 2u);
    for (const Mesh& m : s.meshes) {
        ASSERT_EQ(m.triangleCount(), 2u);
        for (std::size_t t = 0; t < 6; t += 3) {  // every triangle keeps the strip's / fan's facing (+z)
            const glm::vec3 n = glm::cross(m.positions[m.indices[t + 1]] - m.positions[m.indices[t]],
                                           m.positions[m.indices[t + 2]] - m.positions[m.indices[t]]);
            EXPECT_GT(n.z, 0.0f);
        }
    }
    EXPECT_TRUE(anyWarningContains(s, "not triangles")) << allWarnings(s);
}

TEST(GltfLoader, InterleavedStrideAndNormalizedTexcoords) {
    TempDir dir;
    GltfBuilder g;
    // position (3 floats) + normal (3 floats), stride 24; normals deliberately not unit length.
    const std::vector<float> interleaved = {0, 0, 0, 0, 0, 2, 1, 0, 0, 0, 0, 2, 0, 1, 0, 0, 0, 2};
    const int v = g.view(interleaved.data(), interleaved.size() * 4, 24);
    const int pos = g.accessor({{"bufferView", v}, {"componentType", kFloat}, {"count", 3}, {"type", "VEC3"}});
    const int nrm = g.accessor(
        {{"bufferView", v}, {"byteOffset", 12}, {"componentType", kFloat}, {"count", 3}, {"type", "VEC3"}});
    const std::vector<std::uint16_t> uv16 = {0, 0, 65535, 0, 0, 32768};
    const int uv = g.accessor(
        {{"bufferView", g.view(uv16.data(), 12)}, {"componentType", kUShort}, {"normalized", true}, {"count", 3}, {"type", "VEC2"}});
    const std::vector<std::uint8_t> idx8 = {0, 1, 2};
    const int idx = g.accessor(idx8, kUByte, 3, "SCALAR");
    g.scene({g.node({{"mesh", g.mesh({{{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}},
                                       {"indices", idx}}})}})});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "stride"));
    ASSERT_TRUE(r.ok()) << r.error;
    const Mesh& m = r.scene->meshes[0];
    expectVecNear(m.positions[1], {1, 0, 0}, 0);
    expectVecNear(m.positions[2], {0, 1, 0}, 0);
    for (const glm::vec3& n : m.normals) expectVecNear(n, {0, 0, 1}, 1e-6f);
    ASSERT_EQ(m.uvs.size(), 3u);
    EXPECT_FLOAT_EQ(m.uvs[1].x, 1.0f);
    EXPECT_NEAR(m.uvs[2].y, 0.5f, 1e-4f);
    EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(GltfLoader, SparseAccessorOverridesZeros) {
    TempDir dir;
    GltfBuilder g;
    const std::vector<std::uint32_t> sparseIdx = {1, 2};
    const std::vector<float> sparseVal = {1, 0, 0, 0, 1, 0};
    const int iv = g.view(sparseIdx.data(), 8), vv = g.view(sparseVal.data(), 24);
    const int pos = g.accessor({{"componentType", kFloat}, {"count", 3}, {"type", "VEC3"},
                                {"sparse", {{"count", 2}, {"indices", {{"bufferView", iv}, {"componentType", kUInt}}},
                                            {"values", {{"bufferView", vv}}}}}});
    g.scene({g.node({{"mesh", g.mesh({{{"attributes", {{"POSITION", pos}}}}})}})});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "sparse"));
    ASSERT_TRUE(r.ok()) << r.error;
    const Mesh& m = r.scene->meshes[0];
    expectVecNear(m.positions[0], {0, 0, 0}, 0);
    expectVecNear(m.positions[1], {1, 0, 0}, 0);
    expectVecNear(m.positions[2], {0, 1, 0}, 0);
}

TEST(GltfLoader, MaskMaterialTextureSamplerAndTransform) {
    TempDir dir;
    // 4x2 image: alpha = 0, 85, 170, 255 on the top row, 255 on the bottom row.
    std::vector<std::uint8_t> rgba;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) rgba.insert(rgba.end(), {10, 20, 30, std::uint8_t(y == 0 ? x * 85 : 255)});
    writeTga(dir.file("alpha.tga"), 4, 2, rgba);
    GltfBuilder g;
    g.j["images"] = {{{"uri", "alpha.tga"}}};
    g.j["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33071}}};
    g.j["textures"] = {{{"source", 0}, {"sampler", 0}}};
    g.j["materials"] = {
        {{"name", "leaves"}, {"alphaMode", "MASK"}, {"alphaCutoff", 0.3}, {"doubleSided", true},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {1, 1, 1, 0.8}},
           {"baseColorTexture",
            {{"index", 0}, {"extensions", {{"KHR_texture_transform",
                                            {{"offset", {0.5, 0.25}}, {"rotation", glm::half_pi<double>()}, {"scale", {2, 3}}}}}}}}}}},
        {{"name", "glass"}, {"alphaMode", "BLEND"}}};
    g.scene({g.node({{"mesh", addQuadMesh(g, {{"material", 0}})}}), g.node({{"mesh", addQuadMesh(g, {{"material", 1}})}})});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "mask"));
    ASSERT_TRUE(r.ok()) << r.error;
    const Scene& s = *r.scene;
    EXPECT_EQ(s.invariantError(), "");
    ASSERT_EQ(s.materials.size(), 2u);
    const Material& m = s.materials[0];
    EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
    EXPECT_TRUE(m.doubleSided);
    EXPECT_FALSE(m.wrapRepeat);
    EXPECT_FLOAT_EQ(m.baseColorFactor.a, 0.8f);
    EXPECT_EQ(s.materials[1].alphaMode, AlphaMode::Blend);
    EXPECT_TRUE(s.hasAlphaMaskedCasters());
    ASSERT_EQ(m.baseColorImage, 0);
    const Image& img = s.images[0];
    ASSERT_TRUE(img.valid());
    EXPECT_EQ(img.width, 4);
    EXPECT_EQ(img.height, 2);
    EXPECT_EQ(img.rgba[0 * 4 + 3], 0);  // row 0 = top row of the file
    EXPECT_EQ(img.rgba[2 * 4 + 3], 170);
    EXPECT_EQ(img.rgba[5 * 4 + 3], 255);
    EXPECT_EQ(img.rgba[4 * 4 + 0], 10);
    // uv' = T * R * S * uv: (1,0) -> scale (2,0) -> rotate 90 deg (uv space, v down) (0,-2) -> offset (0.5,-1.75).
    const glm::vec3 t = m.uvTransform * glm::vec3(1, 0, 1);
    EXPECT_NEAR(t.x, 0.5f, 1e-6f);
    EXPECT_NEAR(t.y, -1.75f, 1e-6f);
    const glm::vec3 t2 = m.uvTransform * glm::vec3(0, 1, 1);  // (0,3) -> (3,0) -> (3.5,0.25)
    EXPECT_NEAR(t2.x, 3.5f, 1e-6f);
    EXPECT_NEAR(t2.y, 0.25f, 1e-6f);
}

TEST(GltfLoader, MissingEmptyAndCorruptImagesAreWarnings) {
    TempDir dir;
    writeText(dir.file("empty.png"), "");
    writeText(dir.file("corrupt.png"), "this is not a png");
    GltfBuilder g;
    g.j["images"] = {{{"uri", "missing.png"}}, {{"uri", "empty.png"}}, {{"uri", "corrupt.png"}}};
    g.j["textures"] = {{{"source", 0}}, {{"source", 1}}, {{"source", 2}}};
    for (int i = 0; i < 3; ++i)
        g.j["materials"].push_back({{"alphaMode", "MASK"},
                                    {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 0.25}}, {"baseColorTexture", {{"index", i}}}}}});
    g.scene({g.node({{"mesh", addQuadMesh(g, {{"material", 0}})}}), g.node({{"mesh", addQuadMesh(g, {{"material", 1}})}}),
             g.node({{"mesh", addQuadMesh(g, {{"material", 2}})}})});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "images"));
    ASSERT_TRUE(r.ok()) << r.error;
    const Scene& s = *r.scene;
    for (const Material& m : s.materials) {
        EXPECT_EQ(m.baseColorImage, -1);
        EXPECT_FLOAT_EQ(m.baseColorFactor.a, 0.25f);
    }
    EXPECT_TRUE(s.images.empty());
    EXPECT_TRUE(anyWarningContains(s, "missing.png")) << allWarnings(s);
    EXPECT_TRUE(anyWarningContains(s, "empty.png")) << allWarnings(s);
    EXPECT_TRUE(anyWarningContains(s, "corrupt.png")) << allWarnings(s);
}

// Forty image entries naming one file, each through its own texture and drawn material, are one image decoded once;
// images no drawn material uses (an undrawn material's, one no texture names) are not decoded at all.
TEST(GltfLoader, AnImageIsDecodedOnceAndOnlyWhenADrawnMaterialUsesIt) {
    TempDir dir;
    std::vector<std::uint8_t> rgba;
    for (int i = 0; i < 8; ++i) rgba.insert(rgba.end(), {1, 2, 3, std::uint8_t(i * 30)});
    writeTga(dir.file("leaf.tga"), 4, 2, rgba);
    writeText(dir.file("corrupt.png"), "this is not a png");
    GltfBuilder g;
    std::vector<int> roots;
    for (int i = 0; i < 40; ++i) {
        g.j["images"].push_back({{"uri", "leaf.tga"}});
        g.j["textures"].push_back({{"source", i}});
        g.j["materials"].push_back({{"alphaMode", "MASK"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", i}}}}}});
        roots.push_back(g.node({{"mesh", addQuadMesh(g, {{"material", i}})}}));
    }
    g.j["images"].push_back({{"uri", "corrupt.png"}});  // image 40: an undrawn material's
    g.j["textures"].push_back({{"source", 40}});
    g.j["materials"].push_back({{"alphaMode", "MASK"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 40}}}}}});
    g.j["images"].push_back({{"uri", "corrupt.png"}, {"name", "no texture names it"}});
    g.scene(roots);
    const SceneLoadResult r = loadGltfScene(g.write(dir, "shared"));
    ASSERT_TRUE(r.ok()) << r.error;
    const Scene& s = *r.scene;
    EXPECT_EQ(s.invariantError(), "");
    ASSERT_EQ(s.images.size(), 1u);
    EXPECT_EQ(s.images[0].rgba, rgba);
    for (int i = 0; i < 40; ++i) EXPECT_EQ(s.materials[std::size_t(i)].baseColorImage, 0) << "material " << i;
    EXPECT_EQ(s.materials[40].baseColorImage, -1);
    EXPECT_FALSE(anyWarningContains(s, "corrupt.png")) << allWarnings(s);
}

TEST(GltfLoader, GlbIsRecognisedByItsMagic) {
    TempDir dir;
    GltfBuilder g;
    g.scene({g.node({{"mesh", addQuadMesh(g)}})});
    for (const char* name : {"box.glb", "box_glb_named.gltf"}) {
        const SceneLoadResult r = loadGltfScene(g.writeGlb(dir, name));
        ASSERT_TRUE(r.ok()) << name << ": " << r.error;
        EXPECT_EQ(r.scene->triangleCount(), 2u);
    }
}

TEST(GltfLoader, NoScenesMeansAllRootNodes) {
    TempDir dir;
    GltfBuilder g;
    const int mesh = addQuadMesh(g);
    const int child = g.node({{"mesh", mesh}, {"translation", {0, 0, 5}}});
    g.node({{"mesh", mesh}, {"children", {child}}});
    g.node({{"mesh", mesh}, {"translation", {0, 0, -5}}});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "noscene"));
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene->instances.size(), 3u);
}

TEST(GltfLoader, RequiredDracoIsRefused) {
    TempDir dir;
    GltfBuilder g;
    g.j["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    g.scene({g.node({{"mesh", addQuadMesh(g)}})});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "draco"));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error.find("KHR_draco_mesh_compression"), std::string::npos) << r.error;
}

TEST(GltfLoader, NotGltfEmptyAndMissingFiles) {
    TempDir dir;
    writeText(dir.file("junk.gltf"), "{ this is not json");
    writeText(dir.file("empty.glb"), "");
    writeText(dir.file("model.obj"), "v 0 0 0\n");
    for (const std::string& p : {dir.file("junk.gltf"), dir.file("empty.glb"), dir.file("absent.gltf")}) {
        const SceneLoadResult r = loadScene(p);
        EXPECT_FALSE(r.ok());
        EXPECT_NE(r.error.find(p), std::string::npos) << r.error;
    }
    EXPECT_NE(loadScene(dir.file("absent.gltf")).error.find("not found"), std::string::npos);
    EXPECT_NE(loadScene(dir.file("model.obj")).error.find(".obj"), std::string::npos);
    EXPECT_FALSE(loadScene("").ok());
}

// ---- the real scenes in ../shared/scenes -------------------------------------------------------------------------

namespace {
std::string sharedScene(const std::string& rel) { return std::string(SHADOWLAB_SHARED_SCENES) + "/" + rel; }
#define SKIP_WITHOUT_SHARED_SCENES()                                                                 \
    if (!fs::is_directory(SHADOWLAB_SHARED_SCENES))                                                  \
        GTEST_SKIP() << "the shared scenes folder " << SHADOWLAB_SHARED_SCENES << " is absent"
}  // namespace

TEST(SharedScenes, GeometryScenesLoad) {
    SKIP_WITHOUT_SHARED_SCENES();
    const std::pair<const char*, std::size_t> cases[] = {
        {"AlphaBlendModeTest/AlphaBlendModeTest.gltf", 61},
        {"FlightHelmet_geometry/FlightHelmet.gltf", 94722},
        {"Lantern_geometry/Lantern.gltf", 5394},
        {"IntelSponza_Curtains_geometry/sponza_curtains.gltf", 55115}};
    for (const auto& [rel, triangles] : cases) {
        SCOPED_TRACE(rel);
        const SceneLoadResult r = loadScene(sharedScene(rel));
        ASSERT_TRUE(r.ok()) << r.error;
        const Scene& s = *r.scene;
        EXPECT_EQ(s.invariantError(), "");
        EXPECT_EQ(s.triangleCount(), triangles);
        EXPECT_FALSE(s.bounds.empty);
        EXPECT_TRUE(std::isfinite(s.bounds.radius()) && s.bounds.radius() > 0.1f);
        EXPECT_EQ(s.name, fs::path(rel).stem().string());
        std::cout << "  " << rel << ": " << s.triangleCount() << " triangles, " << s.meshes.size() << " meshes, "
                  << s.instances.size() << " instances, radius " << s.bounds.radius() << ", " << s.warnings.size()
                  << " warnings" << allWarnings(s) << "\n";
    }
}

TEST(SharedScenes, AlphaBlendModeTestMaskMaterialsAndCutoffs) {
    SKIP_WITHOUT_SHARED_SCENES();
    const SceneLoadResult r = loadScene(sharedScene("AlphaBlendModeTest/AlphaBlendModeTest.gltf"));
    ASSERT_TRUE(r.ok()) << r.error;
    const Scene& s = *r.scene;
    std::multiset<float> cutoffs;
    int blend = 0;
    for (const Material& m : s.materials) {
        if (m.alphaMode == AlphaMode::Blend) ++blend;
        if (m.alphaMode != AlphaMode::Mask) continue;
        cutoffs.insert(m.alphaCutoff);
        EXPECT_TRUE(m.doubleSided) << m.name;
        ASSERT_GE(m.baseColorImage, 0) << m.name;  // the alpha comes from a real texture
        const Image& img = s.images[std::size_t(m.baseColorImage)];
        ASSERT_TRUE(img.valid());
        int transparent = 0, opaque = 0;  // the texture's alpha actually varies
        for (std::size_t i = 3; i < img.rgba.size(); i += 4) (img.rgba[i] < 128 ? transparent : opaque)++;
        EXPECT_GT(transparent, 0) << m.name;
        EXPECT_GT(opaque, 0) << m.name;
    }
    EXPECT_EQ(cutoffs, (std::multiset<float>{0.25f, 0.5f, 0.75f}));
    EXPECT_EQ(blend, 1);
    EXPECT_TRUE(s.hasAlphaMaskedCasters());
}

TEST(SharedScenes, OriginalJsonWithMissingTexturesLoadWithWarnings) {
    SKIP_WITHOUT_SHARED_SCENES();
    for (const char* rel : {"FlightHelmet_geometry/FlightHelmet.original.gltf.json", "Lantern_geometry/Lantern.original.gltf.json",
                            "IntelSponza_Curtains_geometry/sponza_curtains.original.gltf.json"}) {
        SCOPED_TRACE(rel);
        const SceneLoadResult r = loadScene(sharedScene(rel));
        ASSERT_TRUE(r.ok()) << r.error;
        const Scene& s = *r.scene;
        EXPECT_EQ(s.invariantError(), "");
        EXPECT_FALSE(s.warnings.empty());
        EXPECT_TRUE(anyWarningContains(s, ".png")) << allWarnings(s);
        for (const Material& m : s.materials) EXPECT_EQ(m.baseColorImage, -1) << m.name;
        EXPECT_GT(s.triangleCount(), 1000u);
    }
}

// ---- the assimp-testmodels corpus --------------------------------------------------------------------------------

TEST(GltfCorpus, EveryAssimpGltfEndsInASceneOrAClearError) {
    if (!fs::is_directory(kAssimpGltf2)) GTEST_SKIP() << kAssimpGltf2 << " is absent (package assimp-testmodels)";
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(kAssimpGltf2)) {
        const std::string ext = entry.path().extension().string();
        if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb")) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    ASSERT_GT(files.size(), 30u);
    int loaded = 0, refused = 0;
    const auto start = std::chrono::steady_clock::now();
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        const auto t0 = std::chrono::steady_clock::now();
        const SceneLoadResult r = loadGltfScene(file.string());
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        const std::string rel = fs::relative(file, kAssimpGltf2).string();
        if (r.ok()) {
            ++loaded;
            const Scene& s = *r.scene;
            EXPECT_TRUE(r.error.empty());
            EXPECT_EQ(s.invariantError(), "");
            EXPECT_GT(s.triangleCount(), 0u);
            EXPECT_FALSE(s.bounds.empty);
            EXPECT_TRUE(std::isfinite(s.bounds.radius()));
            std::cout << "  ok      " << rel << " (" << s.triangleCount() << " tris, " << s.warnings.size()
                      << " warnings, " << int(ms) << " ms)" << allWarnings(s) << "\n";
        } else {
            ++refused;
            EXPECT_FALSE(r.error.empty());
            EXPECT_NE(r.error.find(file.string()), std::string::npos) << r.error;  // names the file
            std::cout << "  refused " << rel << " (" << int(ms) << " ms): " << r.error << "\n";
        }
    }
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "  " << files.size() << " files: " << loaded << " loaded, " << refused << " refused, " << total
              << " s\n";
    EXPECT_GT(loaded, refused);
}

// Every one of its 24 positions has x = +-inf (the finite accessor is wired as NORMAL), so dropping the triangles
// that use non-finite positions leaves nothing: a clear refusal. Whatever comes back must never carry an inf.
TEST(GltfCorpus, BoxWithInfinitesNeverYieldsNonFiniteBounds) {
    const std::string path = kAssimpGltf2 + "/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb";
    if (!fs::exists(path)) GTEST_SKIP() << path << " is absent (package assimp-testmodels)";
    const SceneLoadResult r = loadGltfScene(path);
    if (!r.ok()) {
        EXPECT_NE(r.error.find("non-finite"), std::string::npos) << r.error;
        EXPECT_NE(r.error.find("no triangle geometry"), std::string::npos) << r.error;
        return;
    }
    const Scene& s = *r.scene;
    EXPECT_FALSE(s.bounds.empty);
    EXPECT_TRUE(std::isfinite(s.bounds.radius()));
    EXPECT_EQ(s.invariantError(), "");
}

// The same inf box, with one finite triangle added: the finite part loads, bounds stay finite.
TEST(GltfLoader, InfiniteBoxBesideAFiniteTriangleHasFiniteBounds) {
    TempDir dir;
    GltfBuilder g;
    const float inf = std::numeric_limits<float>::infinity();
    const int box = g.positions({{-inf, -0.5f, 0.5f}, {inf, -0.5f, 0.5f}, {-inf, 0.5f, 0.5f}});
    g.scene({g.node({{"mesh", g.mesh({{{"attributes", {{"POSITION", box}}}}})}}), g.node({{"mesh", addQuadMesh(g)}})});
    const SceneLoadResult r = loadGltfScene(g.write(dir, "infbox"));
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene->triangleCount(), 2u);
    EXPECT_TRUE(std::isfinite(r.scene->bounds.radius()));
    expectVecNear(r.scene->bounds.max, {1, 1, 0}, 0);
    EXPECT_TRUE(anyWarningContains(*r.scene, "non-finite")) << allWarnings(*r.scene);
}

TEST(GltfCorpus, BrokenAssimpFilesGiveClearMessages) {
    if (!fs::is_directory(kAssimpGltf2)) GTEST_SKIP() << kAssimpGltf2 << " is absent (package assimp-testmodels)";
    for (const char* rel : {"IndexOutOfRange/IndexOutOfRange.gltf", "IndexOutOfRange/AllIndicesOutOfRange.gltf"}) {
        const SceneLoadResult r = loadGltfScene(kAssimpGltf2 + "/" + rel);
        const bool mentioned = r.ok() ? anyWarningContains(*r.scene, "out of range")
                                      : r.error.find("out of range") != std::string::npos;
        EXPECT_TRUE(mentioned) << rel << ": " << (r.ok() ? allWarnings(*r.scene) : r.error);
    }
    const SceneLoadResult missing = loadGltfScene(kAssimpGltf2 + "/MissingBin/BoxTextured.gltf");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error.find("BoxTextured0.bin"), std::string::npos) << missing.error;

    const SceneLoadResult recursive = loadGltfScene(kAssimpGltf2 + "/RecursiveNodes/RecursiveNodes.gltf");
    ASSERT_FALSE(recursive.ok());  // a cycle of two empty nodes: nothing to draw, and no hang
    EXPECT_NE(recursive.error.find("no triangle geometry"), std::string::npos) << recursive.error;

    const SceneLoadResult draco = loadGltfScene(kAssimpGltf2 + "/draco/2CylinderEngine.gltf");
    ASSERT_FALSE(draco.ok());
    EXPECT_NE(draco.error.find("KHR_draco_mesh_compression"), std::string::npos) << draco.error;
}

TEST(GltfCorpus, ZeroAreaTrianglesAreKeptAndCounted) {
    const std::string path = kAssimpGltf2 + "/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    if (!fs::exists(path)) GTEST_SKIP() << path << " is absent (package assimp-testmodels)";
    const SceneLoadResult r = loadGltfScene(path);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_TRUE(anyWarningContains(*r.scene, "zero-area")) << allWarnings(*r.scene);
    EXPECT_EQ(r.scene->invariantError(), "");
}

// KHR_texture_transform's rotation sign is ambiguous in the extension README (KhronosGroup/glTF#1563). The sample
// model settles it: with the transform applied, the arrow tip (which points at the "Not Supported" marker when the
// transform is ignored) must land on the "Correct" marker placed beside each quad.
TEST(GltfCorpus, TextureTransformMatchesTheSampleModelsMarkers) {
    const std::string path = kAssimpGltf2 + "/textureTransform/TextureTransformTest.gltf";
    if (!fs::exists(path)) GTEST_SKIP() << path << " is absent (package assimp-testmodels)";
    const SceneLoadResult r = loadGltfScene(path);
    ASSERT_TRUE(r.ok()) << r.error;
    const Scene& s = *r.scene;
    auto centres = [&](const std::string& meshName) {  // world centres of every instance of that mesh
        std::vector<glm::vec2> out;
        for (const Instance& inst : s.instances) {
            const Mesh& m = s.meshes[std::size_t(inst.mesh)];
            if (m.name != meshName) continue;
            glm::vec3 c(0.0f);
            for (const glm::vec3& p : m.positions) c += p / float(m.positions.size());
            out.emplace_back(inst.transform * glm::vec4(c, 1.0f));
        }
        return out;
    };
    auto nearest = [](const std::vector<glm::vec2>& points, glm::vec2 to) {
        glm::vec2 best = points.at(0);
        for (const glm::vec2& p : points)
            if (glm::distance(p, to) < glm::distance(best, to)) best = p;
        return best;
    };
    for (const char* quadName : {"Rotation", "Scale"}) {
        SCOPED_TRACE(quadName);
        const Instance* inst = nullptr;
        for (const Instance& i : s.instances)
            if (s.meshes[std::size_t(i.mesh)].name == quadName) inst = &i;
        ASSERT_NE(inst, nullptr);
        const Mesh& quad = s.meshes[std::size_t(inst->mesh)];
        ASSERT_EQ(quad.uvs.size(), quad.positions.size());
        // The quad's affine map uv -> world xy, from its first triangle.
        glm::vec2 p[3], t[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = glm::vec2(inst->transform * glm::vec4(quad.positions[quad.indices[std::size_t(k)]], 1.0f));
            t[k] = quad.uvs[quad.indices[std::size_t(k)]];
        }
        const glm::mat2 a = glm::mat2(p[1] - p[0], p[2] - p[0]) * glm::inverse(glm::mat2(t[1] - t[0], t[2] - t[0]));
        auto toWorld = [&](glm::vec2 uv) { return p[0] + a * (uv - t[0]); };
        auto toUv = [&](glm::vec2 w) { return t[0] + glm::inverse(a) * (w - p[0]); };

        const glm::vec2 centre = toWorld({0.5f, 0.5f});
        const glm::vec2 notSupported = nearest(centres("Not Supported Marker"), centre);
        const glm::vec2 tipUv = toUv(notSupported);
        const glm::mat3& m = s.materialOf(quad)->uvTransform;
        const glm::vec2 shownAt = toWorld(glm::vec2(glm::inverse(m) * glm::vec3(tipUv, 1.0f)));
        EXPECT_LT(glm::distance(shownAt, nearest(centres("Correct Marker"), centre)), 1e-3f);
        EXPECT_GT(glm::distance(shownAt, notSupported), 0.1f);  // and the transform did move it
    }
}
