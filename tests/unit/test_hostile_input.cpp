// Issue 12: hostile input never crashes, hangs or destroys a file. Each input is built here, tiny, as an attacker
// would write it; each must end in a clean refusal that names the file or key and the real cause.
#include "image/image_io.h"
#include "scene/gltf_loader.h"
#include "settings/atomic_file.h"
#include "settings/json_nesting.h"
#include "settings/preset_io.h"
#include "settings/regular_file.h"
#include "settings/settings_fields.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

using namespace shadowlab;
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

struct TempDir {
    fs::path path;
    TempDir() {
        std::random_device rd;
        path = fs::temp_directory_path() / ("shadowlab_hostile_" + std::to_string(rd()) + std::to_string(rd()));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

void writeText(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string nested(std::size_t depth, const std::string& inner = "") {
    return std::string(depth, '[') + inner + std::string(depth, ']');
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const auto& l : lines) out += l + "\n";
    return out;
}

const std::string kPresetHead = R"({"schema": "shadowlab-preset", "schemaVersion": 1)";

// A one-triangle glTF, its buffer inline (data: URI); `edit` changes the JSON before it is written.
std::string triangleGltf(const std::function<void(json&)>& edit = {}) {
    const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    static const char* b64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string enc;
    const auto* p = reinterpret_cast<const unsigned char*>(tri);
    for (std::size_t i = 0; i < sizeof tri; i += 3) {
        const unsigned v = unsigned(p[i]) << 16 | unsigned(p[i + 1]) << 8 | p[i + 2];
        for (int k = 3; k >= 0; --k) enc += b64[(v >> (6 * k)) & 63];
    }
    json j = {{"asset", {{"version", "2.0"}}},
              {"buffers", {{{"byteLength", sizeof tri}, {"uri", "data:application/octet-stream;base64," + enc}}}},
              {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", sizeof tri}}}},
              {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}},
              {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
              {"nodes", {{{"mesh", 0}}}},
              {"scenes", {{{"nodes", {0}}}}},
              {"scene", 0}};
    if (edit) edit(j);
    return j.dump();
}

SceneLoadResult loadText(const TempDir& dir, const std::string& text, const std::string& name = "hostile.gltf") {
    writeText(dir.file(name), text);
    return loadGltfScene(dir.file(name));
}

}  // namespace

// ---- 1, 2: presets and --set ------------------------------------------------------------------------------------

TEST(HostilePreset, TenThousandLevelsDeepIsRefusedWithThePosition) {
    const std::string text = kPresetHead + R"(, "light": {"direction": )" + nested(10000) + "}}";
    const PresetLoadResult r = presetFromText(text);
    ASSERT_FALSE(r.settings);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_TRUE(contains(r.errors[0], "nests deeper than 64 levels")) << r.errors[0];
    EXPECT_TRUE(contains(r.errors[0], "1:")) << r.errors[0];  // line:column of the first bracket past the limit

    const std::string objects = kPresetHead + R"(, "light": )" + [] {
        std::string s;
        for (int i = 0; i < 10000; ++i) s += R"({"a":)";
        return s + "1" + std::string(10000, '}');
    }() + "}";
    EXPECT_TRUE(contains(joined(presetFromText(objects).errors), "nests deeper than 64 levels"));
}

TEST(HostilePreset, DeepValueJustUnderTheLimitGetsAShortMessage) {
    // 60 levels pass the nesting check and reach the key, whose message prints the value: short and bounded.
    const PresetLoadResult r = presetFromText(kPresetHead + R"(, "light": {"direction": )" + nested(60) + "}}");
    ASSERT_FALSE(r.settings);
    ASSERT_FALSE(r.errors.empty());
    EXPECT_TRUE(contains(r.errors[0], "light.direction: expected [x, y, z]")) << r.errors[0];
    EXPECT_LT(r.errors[0].size(), 200u) << r.errors[0];
}

TEST(HostileSet, DeepNestedValueIsRefusedNamingTheKey) {
    Settings s;
    const Settings before = s;
    const std::string error = applySettingOverride(s, "light.direction=" + nested(10000));
    EXPECT_TRUE(contains(error, "light.direction: the value nests deeper than 64 levels")) << error;
    EXPECT_EQ(presetToText(s), presetToText(before));
}

TEST(HostileSet, ValueThatIsNotUtf8IsRefusedNotThrown) {
    Settings s;
    std::string error;
    ASSERT_NO_THROW(error = applySettingOverride(s, "view=\xff"));
    EXPECT_TRUE(contains(error, "view: unknown value")) << error;
    EXPECT_TRUE(contains(error, "\xEF\xBF\xBD")) << error;  // the byte shows as U+FFFD: the message is valid UTF-8
    EXPECT_NO_THROW((void)json(error).dump());
    ASSERT_NO_THROW(error = applySettingOverride(s, "light.type=\xfe\xfe"));
    EXPECT_TRUE(contains(error, "light.type")) << error;
    ASSERT_NO_THROW(error = applySettingOverride(s, "\xff\xfe=1"));
    EXPECT_TRUE(contains(error, "unknown setting")) << error;
    EXPECT_NO_THROW((void)json(error).dump());
}

TEST(HostilePreset, KeyThatIsNotUtf8IsASyntaxErrorThatPrints) {
    const PresetLoadResult r = presetFromText(kPresetHead + ", \"shadow\": {\"depth\xff\xfe" + "Bias\": 1}}");
    ASSERT_FALSE(r.settings);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].rfind("1:", 0), 0u) << r.errors[0];  // line:column first
    EXPECT_TRUE(contains(r.errors[0], ": invalid JSON: ")) << r.errors[0];
    EXPECT_TRUE(contains(r.errors[0], "ill-formed UTF-8 byte")) << r.errors[0];
}

TEST(HostilePreset, PathThatIsNotUtf8LoadsAndIsNamed) {
    TempDir dir;
    const std::string path = dir.file("pre\xff\xfeset.json");
    writeText(path, kPresetHead + R"(, "view": "shadow"})");
    const PresetLoadResult r = loadPresetFile(path);
    ASSERT_TRUE(r.settings) << joined(r.errors);
    EXPECT_EQ(r.settings->view, ViewMode::Shadow);
}

TEST(HostilePreset, SchemaVersionOnePointZeroIsOneAndOnePointFiveIsNot) {
    const PresetLoadResult ok = presetFromText(R"({"schema": "shadowlab-preset", "schemaVersion": 1.0, "view": "shadow"})");
    ASSERT_TRUE(ok.settings) << joined(ok.errors);
    EXPECT_EQ(ok.settings->view, ViewMode::Shadow);
    const PresetLoadResult bad = presetFromText(R"({"schema": "shadowlab-preset", "schemaVersion": 1.5})");
    ASSERT_FALSE(bad.settings);
    EXPECT_TRUE(contains(bad.errors[0], "schemaVersion: expected an integer, got 1.5")) << bad.errors[0];
}

TEST(HostilePreset, HugeUnknownKeyIsNotSearchedAndNotPrintedWhole) {
    const std::string key(4u << 20, 'k');  // 4 MiB: the search used to cost seconds per MiB squared
    const auto start = std::chrono::steady_clock::now();
    const PresetLoadResult r = presetFromText(kPresetHead + ", \"" + key + "\": 1}");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_TRUE(r.settings);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_LT(r.warnings[0].size(), 200u);
    EXPECT_TRUE(contains(r.warnings[0], "(4194304 bytes)")) << r.warnings[0];
    EXPECT_LT(seconds, 2.0);

    Settings s;
    const std::string error = applySettingOverride(s, key + "=1");
    EXPECT_TRUE(contains(error, "unknown setting")) << error.substr(0, 200);
    EXPECT_LT(error.size(), 2000u);
}

// ---- 5: only regular files are read -----------------------------------------------------------------------------

TEST(HostileFiles, PresetPathThatIsAFifoFolderOrDeviceSaysWhatItIs) {
    TempDir dir;
    const std::string fifo = dir.file("preset.fifo");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto start = std::chrono::steady_clock::now();
    PresetLoadResult r = loadPresetFile(fifo);  // used to block forever in open()
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0], fifo + ": is a FIFO (named pipe), not a regular file");
    r = loadPresetFile("/dev/zero");
    EXPECT_EQ(r.errors.at(0), "/dev/zero: is a character device, not a regular file");
    r = loadPresetFile(dir.path.string());
    EXPECT_TRUE(contains(r.errors.at(0), "is a folder, not a regular file")) << r.errors[0];
}

TEST(HostileGltf, BufferUriThatIsAFifoFolderOrDeviceSaysWhatItIs) {
    TempDir dir;
    ASSERT_EQ(::mkfifo(dir.file("pipe.bin").c_str(), 0600), 0);
    fs::create_symlink("/dev/zero", dir.file("zero.bin"));
    for (const auto& [uri, expected] : std::vector<std::pair<std::string, std::string>>{
             {"pipe.bin", "is a FIFO (named pipe), not a regular file"},
             {".", "is a folder, not a regular file"},
             {"zero.bin", "is a character device, not a regular file"},
             {"/dev/zero", "a file it refers to is missing"}}) {  // glTF URIs are relative to the file's folder
        const auto start = std::chrono::steady_clock::now();
        const SceneLoadResult r = loadText(dir, triangleGltf([&](json& j) { j["buffers"][0]["uri"] = uri; }));
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0) << uri;
        ASSERT_FALSE(r.ok()) << uri;
        EXPECT_TRUE(contains(r.error, expected)) << uri << ": " << r.error;
        EXPECT_FALSE(contains(r.error, "out of memory")) << r.error;
    }
    // The scene file itself.
    const SceneLoadResult r = loadGltfScene(dir.file("pipe.bin"));
    EXPECT_TRUE(contains(r.error, "is a FIFO (named pipe)")) << r.error;
}

// ---- 3, 4, 6: glTF nesting, instances, decoded bytes -------------------------------------------------------------

TEST(HostileGltf, ExtrasNestedTwentyThousandDeepIsRefusedBeforeTinygltf) {
    TempDir dir;
    std::string text = triangleGltf();
    text.insert(text.size() - 1, ",\"extras\":" + nested(20000));
    const SceneLoadResult r = loadText(dir, text);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(contains(r.error, "hostile.gltf: 1:")) << r.error;
    EXPECT_TRUE(contains(r.error, "nests deeper than 64 levels")) << r.error;
}

TEST(HostileGltf, NodesListingTheNextTwiceStopAtTheInstanceCap) {
    TempDir dir;
    const std::string text = triangleGltf([](json& j) {
        j["nodes"] = json::array();
        for (int i = 0; i < 22; ++i) j["nodes"].push_back({{"children", {i + 1, i + 1}}, {"mesh", 0}});
        j["nodes"].push_back({{"mesh", 0}});
    });
    const auto start = std::chrono::steady_clock::now();
    const SceneLoadResult r = loadText(dir, text);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(contains(r.error, "more than 100000 mesh instances (the limit)")) << r.error;
}

TEST(HostileGltf, AccessorOfTwoToTheTwentySixZerosPassesTheDecodeLimit) {
    TempDir dir;
    const SceneLoadResult r = loadText(dir, triangleGltf([](json& j) {
        j["accessors"][0] = {{"componentType", 5126}, {"count", (1 << 26) - 1}, {"type", "VEC3"}};
    }));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(contains(r.error, "decodes to more than 1024 MiB (the limit for a scene)")) << r.error;
}

TEST(HostileGltf, SeveralLargeAccessorsTogetherPassTheDecodeLimit) {
    // Each alone fits (12M vertices = 384 MiB decoded); three meshes of them do not.
    TempDir dir;
    const SceneLoadResult r = loadText(dir, triangleGltf([](json& j) {
        j["accessors"].push_back({{"componentType", 5126}, {"count", 12'000'000}, {"type", "VEC3"}});
        j["meshes"] = json::array();
        j["nodes"] = json::array();
        for (int i = 0; i < 3; ++i) {
            j["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", 1}}}}}}});
            j["nodes"].push_back({{"mesh", i}});
        }
        j["scenes"][0]["nodes"] = {0, 1, 2};
    }));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(contains(r.error, "the limit for a scene")) << r.error;
}

// ---- 9: messages that named the wrong cause -------------------------------------------------------------------------

TEST(HostileGltf, BoundsBeyondAFloatSaySo) {
    TempDir dir;
    for (double scale : {1e19, 1e30, 1e38}) {
        const SceneLoadResult r = loadText(dir, triangleGltf([&](json& j) {
            j["nodes"][0]["scale"] = {scale, scale, scale};
        }));
        ASSERT_FALSE(r.ok()) << scale;
        EXPECT_TRUE(contains(r.error, "the scene's bounds overflow a float")) << r.error;
    }
}

TEST(HostileGltf, SpotLightFarAwayIsIgnoredNamingTheLimit) {
    TempDir dir;
    const SceneLoadResult r = loadText(dir, triangleGltf([](json& j) {
        j["nodes"][0]["children"] = {1};
        j["nodes"].push_back({{"translation", {1e30, 0, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
        j["extensionsUsed"] = {"KHR_lights_punctual"};
        j["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "spot"}, {"spot", json::object()}}}}}}};
    }));
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_TRUE(r.scene->lights.empty());
    std::string all;
    for (const auto& w : r.scene->warnings) all += w + "\n";
    EXPECT_TRUE(contains(all, "position (1e+30, 0, 0) has a component beyond 1e+07 (the light.position limit)")) << all;
}

TEST(HostileGltf, EveryNodeAChildSaysNoSceneRoot) {
    TempDir dir;
    const SceneLoadResult r = loadText(dir, triangleGltf([](json& j) {
        j.erase("scenes");
        j.erase("scene");
        j["nodes"] = {{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}};
    }));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(contains(r.error, "no scene root")) << r.error;
}

TEST(HostileGltf, DataUriLengthMismatchSaysBothSizesWithoutThePayload) {
    TempDir dir;
    const std::string payload(400000, 'A');  // 300,000 bytes of zeros, base64
    const SceneLoadResult r = loadText(dir, triangleGltf([&](json& j) {
        j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + payload;
    }));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(contains(r.error, "buffers[0]: its data: URI holds 300000 bytes but byteLength says 36")) << r.error;
    EXPECT_LT(r.error.size(), 400u);
}

TEST(HostileGltf, PngClaimingHundredThousandSquaredSaysItsSize) {
    TempDir dir;
    const unsigned char png[33] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                   0, 1, 0x86, 0xa0, 0, 1, 0x86, 0xa0, 8, 6, 0, 0, 0, 0, 0, 0, 0};
    std::ofstream(dir.file("huge.png"), std::ios::binary).write(reinterpret_cast<const char*>(png), sizeof png);
    const SceneLoadResult r = loadText(dir, triangleGltf([](json& j) {
        j["images"] = {{{"uri", "huge.png"}}};
        j["textures"] = {{{"source", 0}}};
        j["materials"] = {{{"alphaMode", "MASK"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
        j["meshes"][0]["primitives"][0]["material"] = 0;
    }));
    ASSERT_TRUE(r.ok()) << r.error;
    std::string all;
    for (const auto& w : r.scene->warnings) all += w + "\n";
    EXPECT_TRUE(contains(all, "is 100000x100000 pixels: decoded (RGBA8) it would take 38147.0 MiB, more than the "
                              "8192x8192 (256.0 MiB) limit for a texture")) << all;
    EXPECT_FALSE(contains(all, "Unknown image format")) << all;
}

namespace {

// One mesh and node per material, so that every material is drawn (the triangle's accessor shared).
void drawEachMaterial(json& j, int materials) {
    j["meshes"] = json::array();
    j["nodes"] = json::array();
    j["scenes"][0]["nodes"] = json::array();
    for (int i = 0; i < materials; ++i) {
        j["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"material", i}}}}});
        j["nodes"].push_back({{"mesh", i}});
        j["scenes"][0]["nodes"].push_back(i);
    }
}

// Image i -> texture i -> MASK material i, drawn.
void texturedMaterials(json& j, const std::vector<std::string>& uris) {
    j["images"] = json::array();
    for (std::size_t i = 0; i < uris.size(); ++i) {
        j["images"].push_back({{"uri", uris[i]}});
        j["textures"].push_back({{"source", i}});
        j["materials"].push_back({{"alphaMode", "MASK"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", i}}}}}});
    }
    drawEachMaterial(j, int(uris.size()));
}

// A PNG signature and IHDR claiming w x h RGBA, no pixels: its header gives the size, decoding it would allocate
// for that size. `tag` (a byte after IHDR) makes files of the same size differ.
void writePngHeader(const std::string& path, std::uint32_t w, std::uint32_t h, unsigned char tag = 0) {
    std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R'};
    for (std::uint32_t v : {w, h})
        for (int shift = 24; shift >= 0; shift -= 8) png.push_back(static_cast<unsigned char>(v >> shift));
    png.insert(png.end(), {8, 6, 0, 0, 0, 0, 0, 0, 0, tag});
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
}

}  // namespace

// The texture limit holds for every format, read from the header before decoding: a 16000x16000 JPEG (2.45 GB
// decoded before) and a 9000x9000 TGA are refused with their size, the file tiny.
TEST(HostileGltf, EveryImageFormatHasTheTextureSizeLimit) {
    TempDir dir;
    const unsigned char jpeg[] = {0xFF, 0xD8, 0xFF, 0xC0, 0x00, 0x11, 8, 0x3E, 0x80, 0x3E, 0x80, 3,
                                  1, 0x11, 0, 2, 0x11, 0, 3, 0x11, 0};  // SOI, SOF0: 16000x16000, 3 components
    std::ofstream(dir.file("huge.jpg"), std::ios::binary).write(reinterpret_cast<const char*>(jpeg), sizeof jpeg);
    unsigned char tga[18] = {0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x28, 0x23, 0x28, 0x23, 32, 0x28};  // 9000x9000 RGBA
    std::ofstream(dir.file("huge.tga"), std::ios::binary).write(reinterpret_cast<const char*>(tga), sizeof tga);
    const auto start = std::chrono::steady_clock::now();
    const SceneLoadResult r = loadText(dir, triangleGltf([](json& j) { texturedMaterials(j, {"huge.jpg", "huge.tga"}); }));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
    ASSERT_TRUE(r.ok()) << r.error;
    const std::string all = joined(r.scene->warnings);
    EXPECT_TRUE(contains(all, "image 0 'huge.jpg' is 16000x16000 pixels: decoded (RGBA8) it would take 976.6 MiB, "
                              "more than the 8192x8192 (256.0 MiB) limit for a texture")) << all;
    EXPECT_TRUE(contains(all, "image 1 'huge.tga' is 9000x9000 pixels")) << all;
    EXPECT_TRUE(r.scene->images.empty());
}

// Decoded images count against the scene's limit, from their headers, before any is decoded: five distinct
// 8192x8192 textures (256 MiB each decoded, 40 bytes each on disk) pass the 1 GiB limit and the scene is refused
// naming the image, its decoded size and the limit.
TEST(HostileGltf, DecodedImagesCountAgainstTheSceneLimitBeforeDecoding) {
    TempDir dir;
    std::vector<std::string> uris;
    for (int i = 0; i < 5; ++i) {
        uris.push_back("big" + std::to_string(i) + ".png");
        writePngHeader(dir.file(uris.back()), 8192, 8192, static_cast<unsigned char>(i));
    }
    const auto start = std::chrono::steady_clock::now();
    const SceneLoadResult r = loadText(dir, triangleGltf([&](json& j) { texturedMaterials(j, uris); }));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(contains(r.error, dir.file("hostile.gltf") + ": image 3 'big3.png' (base colour of material "
                                  "'material 3') decodes to 8192x8192 RGBA8 = 256 MiB, which passes the scene's "
                                  "1024 MiB limit: 768 MiB of buffers, vertex data and images come before it"))
        << r.error;
}

TEST(HostileGltf, NegativeByteOffsetsAreRefusedNotReadAsZero) {
    TempDir dir;
    SceneLoadResult r = loadText(dir, triangleGltf([](json& j) { j["accessors"][0]["byteOffset"] = -4; }));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(contains(r.error, "accessors[0].byteOffset: -4 is negative")) << r.error;
    r = loadText(dir, triangleGltf([](json& j) { j["bufferViews"][0]["byteOffset"] = -12; }));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(contains(r.error, "bufferViews[0].byteOffset: -12 is negative")) << r.error;
}

TEST(HostileGltf, AlphaCutoffBeyondOneIsOutOfRange) {
    TempDir dir;
    const SceneLoadResult r = loadText(dir, triangleGltf([](json& j) {
        j["materials"] = {{{"alphaMode", "MASK"}, {"alphaCutoff", 1e308}}};
        j["meshes"][0]["primitives"][0]["material"] = 0;
    }));
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_FLOAT_EQ(r.scene->materials.at(0).alphaCutoff, 0.5f);
    std::string all;
    for (const auto& w : r.scene->warnings) all += w + "\n";
    EXPECT_TRUE(contains(all, "alphaCutoff 1e+308 is out of range (allowed [0, 1]); 0.5 used")) << all;
}

// ---- 7, 8: only regular files are written, atomically ---------------------------------------------------------------

TEST(HostileWrites, DevNullFifoSocketAndFolderAreRefusedAndLeftAlone) {
    TempDir dir;
    const std::string fifo = dir.file("out.fifo");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const std::string sock = dir.file("out.sock");
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    std::strncpy(addr.sun_path, sock.c_str(), sizeof addr.sun_path - 1);
    ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
    for (const auto& [path, kind] : std::vector<std::pair<std::string, std::string>>{
             {"/dev/null", "a character device"}, {fifo, "a FIFO (named pipe)"}, {sock, "a socket"},
             {dir.path.string(), "a folder"}}) {
        const std::string error = writeFileAtomically(path, "{}\n");
        EXPECT_EQ(error, "it is " + kind + ", not a regular file; ShadowLab writes only regular files") << path;
    }
    ::close(fd);
    EXPECT_TRUE(fs::is_fifo(fifo));
    EXPECT_TRUE(fs::is_socket(sock));
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
    const std::uint8_t pixel[4] = {1, 2, 3, 4};
    EXPECT_TRUE(contains(writePng(fifo, 1, 1, 4, pixel, false), "is a FIFO")) << writePng(fifo, 1, 1, 4, pixel, false);
    EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST(HostileWrites, SymlinkIsFollowedOnlyToARegularFileAndADanglingOneIsRefused) {
    TempDir dir;
    writeText(dir.file("real.json"), "old\n");
    fs::create_symlink(dir.file("real.json"), dir.file("link.json"));
    EXPECT_EQ(writeFileAtomically(dir.file("link.json"), "new\n"), "");
    EXPECT_TRUE(fs::is_symlink(dir.file("link.json")));
    EXPECT_EQ(readText(dir.file("real.json")), "new\n");

    fs::create_symlink(dir.file("nowhere.json"), dir.file("dangling.json"));
    const std::string error = writeFileAtomically(dir.file("dangling.json"), "x\n");
    EXPECT_TRUE(contains(error, "symbolic link to '" + dir.file("nowhere.json") + "', which does not exist")) << error;
    EXPECT_FALSE(fs::exists(dir.file("nowhere.json")));
    EXPECT_TRUE(fs::is_symlink(dir.file("dangling.json")));

    fs::create_symlink("/dev/null", dir.file("null.json"));
    EXPECT_TRUE(contains(writeFileAtomically(dir.file("null.json"), "x\n"), "a character device"));
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

// A full disk, as RLIMIT_FSIZE: a write past the limit fails with EFBIG (SIGXFSZ ignored) like ENOSPC would.
class FullDisk : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_), 0);
        oldHandler_ = std::signal(SIGXFSZ, SIG_IGN);
    }
    void limit(rlim_t bytes) {
        rlimit small = old_;
        small.rlim_cur = bytes;
        ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    }
    void TearDown() override {
        ::setrlimit(RLIMIT_FSIZE, &old_);
        std::signal(SIGXFSZ, oldHandler_);
    }
    rlimit old_{};
    void (*oldHandler_)(int) = nullptr;
};

TEST_F(FullDisk, PngExrAndPresetKeepTheOldFileAndSayWhy) {
    TempDir dir;
    const std::string png = dir.file("old.png"), exr = dir.file("old.exr"), preset = dir.file("old.json");
    std::vector<std::uint8_t> pixels(64 * 64 * 4, 200);
    std::vector<float> depth(64 * 64, 0.5f);
    std::mt19937 random(12);
    ASSERT_EQ(writePng(png, 2, 2, 4, pixels.data(), false), "");
    ASSERT_EQ(writeExrDepth(exr, 2, 2, depth.data(), false), "");
    ASSERT_EQ(savePresetFile(preset, Settings{}), "");
    const std::string oldPng = readText(png), oldExr = readText(exr), oldPreset = readText(preset);

    for (auto& p : pixels) p = std::uint8_t(random());  // incompressible: larger than the limit once encoded
    for (auto& d : depth) d = float(random()) / float(random.max());
    limit(512);
    const std::string pngError = writePng(png, 64, 64, 4, pixels.data(), false);
    const std::string exrError = writeExrDepth(exr, 64, 64, depth.data(), false);
    Settings big;
    const std::string presetError = savePresetFile(preset, big, std::string(4096, 'n'));
    TearDown();

    EXPECT_TRUE(contains(pngError, "File too large")) << pngError;
    EXPECT_TRUE(contains(pngError, png)) << pngError;
    EXPECT_TRUE(contains(exrError, "File too large")) << exrError;
    EXPECT_TRUE(contains(presetError, "File too large")) << presetError;
    EXPECT_EQ(readText(png), oldPng);
    EXPECT_EQ(readText(exr), oldExr);
    EXPECT_EQ(readText(preset), oldPreset);
    for (const auto& entry : fs::directory_iterator(dir.path))  // no temporary left behind
        EXPECT_EQ(entry.path().filename().string().rfind(".", 0), std::string::npos) << entry.path();
}

TEST(JsonNesting, CountsBracketsOutsideStringsOnly) {
    EXPECT_EQ(checkJsonNesting(nested(64)), "");
    EXPECT_EQ(checkJsonNesting("\"" + std::string(1000, '[') + "\""), "");
    EXPECT_EQ(checkJsonNesting("[\"\\\"[\"]"), "");
    EXPECT_EQ(checkJsonNesting("\n  " + nested(65)), "2:67: JSON nests deeper than 64 levels (the limit)");
}
