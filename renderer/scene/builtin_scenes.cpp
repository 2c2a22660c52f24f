#include "scene/builtin_scenes.h"

#include "scene/scene_animation.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <numbers>
#include <utility>

namespace shadowlab {
namespace {

using namespace builtin;

// The six faces of an axis-aligned box: outward normal and an in-face axis (the other is cross(normal, axis)).
struct BoxFace {
    glm::vec3 normal, axis;
};
constexpr BoxFace kBoxFaces[6] = {{{1, 0, 0}, {0, 1, 0}}, {{-1, 0, 0}, {0, 1, 0}}, {{0, 1, 0}, {0, 0, 1}},
                                  {{0, -1, 0}, {0, 0, 1}}, {{0, 0, 1}, {1, 0, 0}}, {{0, 0, -1}, {1, 0, 0}}};

// Builds one Mesh from planar quads (flat normals) and spheres (analytic normals), all CCW seen from outside.
struct MeshBuilder {
    Mesh mesh;

    explicit MeshBuilder(std::string name, int material) {
        mesh.name = std::move(name);
        mesh.material = material;
    }

    // Corners c-u-v, c+u-v, c+u+v, c-u+v; the face looks along cross(u, v). UV (0,0) at c-u+v (glTF: v runs down).
    void quad(const glm::vec3& c, const glm::vec3& u, const glm::vec3& v, bool withUv = false) {
        const auto base = std::uint32_t(mesh.positions.size());
        const glm::vec3 n = glm::normalize(glm::cross(u, v));
        const glm::vec3 corners[4] = {c - u - v, c + u - v, c + u + v, c - u + v};
        const glm::vec2 uvs[4] = {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}};
        for (int i = 0; i < 4; ++i) {
            mesh.positions.push_back(corners[i]);
            mesh.normals.push_back(n);
            if (withUv) mesh.uvs.push_back(uvs[i]);
        }
        for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
    }

    // Axis-aligned box, then rotated by `frame` (a rotation) about the origin: world = frame * (center + local).
    void box(const glm::vec3& center, const glm::vec3& size, const glm::mat3& frame = glm::mat3(1.0f)) {
        const glm::vec3 h = 0.5f * size;
        const std::size_t first = mesh.positions.size();
        for (const BoxFace& f : kBoxFaces) quad(center + f.normal * h, f.axis * h, glm::cross(f.normal, f.axis) * h);
        for (std::size_t i = first; i < mesh.positions.size(); ++i) {
            mesh.positions[i] = frame * mesh.positions[i];
            mesh.normals[i] = frame * mesh.normals[i];
        }
    }

    // UV sphere: `segments` around y, `rings` from pole to pole; single triangles at the poles (no zero-area ones).
    void sphere(const glm::vec3& center, float radius, int segments, int rings) {
        const auto base = std::uint32_t(mesh.positions.size());
        for (int j = 0; j <= rings; ++j) {
            const double theta = std::numbers::pi * j / rings;
            for (int i = 0; i < segments; ++i) {
                const double phi = 2.0 * std::numbers::pi * i / segments;
                const glm::vec3 dir(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                                    float(std::sin(theta) * std::sin(phi)));
                mesh.positions.push_back(center + radius * dir);
                mesh.normals.push_back(dir);
            }
        }
        auto at = [&](int j, int i) { return base + std::uint32_t(j * segments + (i % segments)); };
        for (int j = 0; j < rings; ++j) {
            for (int i = 0; i < segments; ++i) {
                const std::uint32_t a = at(j, i), b = at(j + 1, i), c = at(j + 1, i + 1), d = at(j, i + 1);
                if (j != 0) mesh.indices.insert(mesh.indices.end(), {a, d, c});          // a == d at the north pole
                if (j != rings - 1) mesh.indices.insert(mesh.indices.end(), {a, c, b});  // b == c at the south pole
            }
        }
    }
};

void addObject(Scene& scene, MeshBuilder&& builder) {
    scene.instances.push_back(Instance{int(scene.meshes.size()), glm::mat4(1.0f)});
    scene.meshes.push_back(std::move(builder.mesh));
}

Material opaque(const char* name, glm::vec4 color) {
    Material m;
    m.name = name;
    m.baseColorFactor = color;
    return m;
}

// Materials shared by every scene: 0 = floor, 1 = casters.
Scene baseScene(const std::string& name) {
    Scene scene;
    scene.name = name;
    scene.materials.push_back(opaque("floor", {0.8f, 0.8f, 0.8f, 1.0f}));
    scene.materials.push_back(opaque("caster", {0.85f, 0.45f, 0.25f, 1.0f}));
    return scene;
}

void addFloor(Scene& scene) {
    MeshBuilder floor("floor", 0);
    const float h = 0.5f * kFloorSize;
    floor.quad({0, 0, 0}, {h, 0, 0}, {0, 0, -h});  // cross(+x, -z) = +y
    addObject(scene, std::move(floor));
}

Scene textbook() {
    Scene scene = baseScene("textbook");
    addFloor(scene);
    MeshBuilder cube("cube", 1);
    cube.box(kCubeCenter, glm::vec3(kCubeSize));
    addObject(scene, std::move(cube));
    MeshBuilder sphere("sphere", 1);
    sphere.sphere(kTextbookSphereCenter, kTextbookSphereRadius, kTextbookSphereSegments, kTextbookSphereRings);
    addObject(scene, std::move(sphere));
    MeshBuilder floating("floating-box", 1);
    floating.box(kFloatingBoxCenter, kFloatingBoxSize);
    addObject(scene, std::move(floating));
    return scene;
}

Scene grazing() {
    Scene scene = baseScene("grazing");
    const glm::vec3 n = grazingPlaneNormal();
    const glm::vec3 t1 = glm::normalize(glm::cross(glm::vec3(0, 1, 0), n));  // horizontal, along the slope
    const glm::vec3 t2 = glm::cross(n, t1);                                  // up the slope; cross(t1, t2) = n
    MeshBuilder plane("plane", 0);
    const float h = 0.5f * kGrazingPlaneSize;
    plane.quad({0, 0, 0}, h * t1, h * t2);
    addObject(scene, std::move(plane));
    // Box built upright at the origin, then turned so its local +y is the plane normal.
    MeshBuilder box("box", 1);
    box.box({0.0f, 0.5f * kGrazingBoxSize, 0.0f}, glm::vec3(kGrazingBoxSize), glm::mat3(t1, n, glm::cross(t1, n)));
    addObject(scene, std::move(box));
    return scene;
}

Scene thinWalls() {
    Scene scene = baseScene("thin-walls");
    addFloor(scene);
    for (int i = 0; i < kThinWallCount; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "wall-%g", double(kThinWallThickness[i]));
        MeshBuilder wall(name, 1);
        wall.box({0.0f, 0.5f * kThinWallHeight, kThinWallCenterZ[i]},
                 {kThinWallLength, kThinWallHeight, kThinWallThickness[i]});
        addObject(scene, std::move(wall));
    }
    return scene;
}

// Alpha 255 on slats and on the rail, 0 in the gaps; RGB is a wood colour (only alpha matters for shadows).
Image fenceImage() {
    Image img;
    img.width = kFenceImageWidth;
    img.height = kFenceImageHeight;
    img.rgba.resize(std::size_t(img.width) * img.height * 4);
    const float texelX = (kFenceXMax - kFenceXMin) / float(img.width);
    const float texelY = kFenceHeight / float(img.height);
    for (int row = 0; row < img.height; ++row) {
        for (int col = 0; col < img.width; ++col) {
            // Texel centre in fence coordinates; row 0 is the top of the fence.
            const float x = kFenceXMin + (float(col) + 0.5f) * texelX;
            const float y = kFenceHeight - (float(row) + 0.5f) * texelY;
            std::uint8_t* p = &img.rgba[(std::size_t(row) * img.width + col) * 4];
            p[0] = 150;
            p[1] = 100;
            p[2] = 60;
            p[3] = fenceOpaqueAt(x, y) ? 255 : 0;
        }
    }
    return img;
}

Scene fence() {
    Scene scene = baseScene("fence");
    addFloor(scene);
    Material m = opaque("fence", {0.6f, 0.4f, 0.25f, 1.0f});
    m.alphaMode = AlphaMode::Mask;
    m.alphaCutoff = kFenceAlphaCutoff;
    m.doubleSided = true;
    m.baseColorImage = 0;
    m.wrapRepeat = false;
    scene.images.push_back(fenceImage());
    scene.materials.push_back(m);
    MeshBuilder quad("fence", 2);
    const float hx = 0.5f * (kFenceXMax - kFenceXMin), hy = 0.5f * kFenceHeight;
    quad.quad({0.5f * (kFenceXMin + kFenceXMax), hy, 0.0f}, {hx, 0, 0}, {0, hy, 0}, true);  // faces +z
    addObject(scene, std::move(quad));
    return scene;
}

Scene spherePlane() {
    Scene scene = baseScene("sphere-plane");
    addFloor(scene);
    MeshBuilder sphere("sphere", 1);
    sphere.sphere(kSpherePlaneCenter, kSpherePlaneRadius, kSpherePlaneSegments, kSpherePlaneRings);
    addObject(scene, std::move(sphere));
    return scene;
}

Scene roof() {
    Scene scene = baseScene("roof");
    addFloor(scene);
    scene.materials.push_back(opaque("roof", {0.55f, 0.6f, 0.7f, 1.0f}));  // single-sided (glTF's default)
    MeshBuilder panel("roof", 2);
    const float h = 0.5f * kRoofSize;
    panel.quad(kRoofCenter, {h, 0, 0}, {0, 0, h});  // cross(+x, +z) = -y: the front face looks down
    addObject(scene, std::move(panel));
    MeshBuilder box("box", 1);
    box.box(kRoofBoxCenter, glm::vec3(kRoofBoxSize));
    addObject(scene, std::move(box));
    return scene;
}

SceneLight pointLight(const char* name, const glm::vec3& position, float range, const glm::vec3& color,
                      float intensity) {
    SceneLight light;
    light.name = name;
    light.type = SceneLightType::Point;
    light.position = position;
    light.range = range;
    light.color = color;
    light.intensity = intensity;
    return light;
}

// Six single-sided quads facing into the room, one mesh each (floor, ceiling, four walls), and the pillar and the
// table; the point light at the centre is a SceneLight, so useSceneLights picks it up like a glTF light.
Scene room() {
    Scene scene = baseScene("room");
    scene.materials.push_back(opaque("wall", {0.75f, 0.78f, 0.82f, 1.0f}));  // single-sided (glTF's default)
    const glm::vec3 center = 0.5f * (kRoomMin + kRoomMax), h = 0.5f * (kRoomMax - kRoomMin);
    const char* names[6] = {"wall+x", "wall-x", "ceiling", "floor", "wall+z", "wall-z"};
    for (int i = 0; i < 6; ++i) {
        const BoxFace& f = kBoxFaces[i];
        MeshBuilder side(names[i], f.normal.y < 0.0f ? 0 : 2);  // the floor (outward normal -y) keeps "floor"
        side.quad(center + f.normal * h, glm::cross(f.normal, f.axis) * h, f.axis * h);  // swapped: faces inward
        addObject(scene, std::move(side));
    }
    MeshBuilder pillar("pillar", 1);
    pillar.box(kRoomPillarCenter, kRoomPillarSize);
    addObject(scene, std::move(pillar));

    // The table: a top on four legs, one mesh per box (each mesh is one convex object).
    MeshBuilder top("table-top", 1);
    const float legHeight = kRoomTableHeight - kRoomTableTopSize.y;
    top.box(kRoomTableCenter + glm::vec3(0.0f, legHeight + 0.5f * kRoomTableTopSize.y, 0.0f), kRoomTableTopSize);
    addObject(scene, std::move(top));
    const glm::vec2 legOffset = 0.5f * glm::vec2(kRoomTableTopSize.x, kRoomTableTopSize.z) - 1.5f * kRoomTableLegSize;
    for (const float sx : {-1.0f, 1.0f}) {
        for (const float sz : {-1.0f, 1.0f}) {
            MeshBuilder leg("table-leg", 1);
            leg.box(kRoomTableCenter + glm::vec3(sx * legOffset.x, 0.5f * legHeight, sz * legOffset.y),
                    {kRoomTableLegSize, legHeight, kRoomTableLegSize});
            addObject(scene, std::move(leg));
        }
    }

    scene.lights.push_back(pointLight("bulb", kRoomLight, kRoomLightRange, {1.0f, 0.95f, 0.85f}, 1.0f));
    return scene;
}

SceneLight courtyardSpot(const char* name, const glm::vec3& position, const glm::vec3& target, float coneDeg,
                         const glm::vec3& color) {
    SceneLight spot;
    spot.name = name;
    spot.type = SceneLightType::Spot;
    spot.position = position;
    spot.direction = glm::normalize(target - position);
    spot.outerConeRad = 0.5f * glm::radians(coneDeg);  // glTF's outer cone is the half angle
    spot.range = kCourtyardSpotRange;
    spot.color = color;
    spot.intensity = 0.3f;
    return spot;
}

// Intensities sum to about 1 where every light reaches (N.L and the range window included), so no light's shadow is
// lost in a saturated pixel.
Scene courtyard() {
    Scene scene = baseScene("courtyard");
    addFloor(scene);
    scene.materials.push_back(opaque("building", {0.7f, 0.66f, 0.6f, 1.0f}));
    for (const CourtyardBox& b : kCourtyardBuildings) {
        MeshBuilder building(b.name, 2);
        building.box(b.center, b.size);
        addObject(scene, std::move(building));
    }
    for (const CourtyardBox& p : kCourtyardPosts) {
        MeshBuilder post(p.name, 1);
        post.box(p.center, p.size);
        addObject(scene, std::move(post));
    }
    SceneLight sun;
    sun.name = "sun";
    sun.direction = glm::normalize(kCourtyardSunDir);
    sun.color = {1.0f, 0.96f, 0.88f};
    sun.intensity = 0.5f;
    scene.lights.push_back(sun);
    scene.lights.push_back(courtyardSpot("spot-hall", kCourtyardHallSpot, kCourtyardHallSpotTarget,
                                         kCourtyardHallSpotConeDeg, {0.75f, 0.85f, 1.0f}));
    scene.lights.push_back(courtyardSpot("spot-tower", kCourtyardTowerSpot, kCourtyardTowerSpotTarget,
                                         kCourtyardTowerSpotConeDeg, {1.0f, 0.85f, 0.65f}));
    scene.lights.push_back(
        pointLight("lantern", kCourtyardLantern, kCourtyardLanternRange, {1.0f, 0.75f, 0.45f}, 0.35f));
    return scene;
}

// A fixed hash of three integers to [0, 1): the city's variety, the same on every machine (no seeded generator).
float cityHash(int a, int b, int c) {
    std::uint32_t h = std::uint32_t(a) * 73856093u ^ std::uint32_t(b) * 19349663u ^ std::uint32_t(c) * 83492791u;
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return float(h >> 8) * (1.0f / 16777216.0f);
}

void addBox(Scene& scene, const char* name, int material, const glm::vec3& center, const glm::vec3& size) {
    MeshBuilder box(name, material);
    box.box(center, size);
    addObject(scene, std::move(box));
}

// One block's buildings on the lots of its inner square; `centre` is the block's centre on the ground.
void addCityBuildings(Scene& scene, int i, int j, const glm::vec3& centre, int material) {
    const float inner = kCityBlockSize - 2.0f * kCitySidewalkWidth;
    const int lotsX = 1 + int(cityHash(i, j, 1) * 3.0f), lotsZ = 1 + int(cityHash(i, j, 2) * 3.0f);
    // Taller toward the city's centre: 1 at the edge, up to 3 in the middle.
    const float r = glm::length(glm::vec2(centre.x, centre.z)) / (0.5f * kCityBlocks * kCityPeriod);
    const float downtown = 1.0f + 2.0f * std::exp(-4.0f * r * r);
    const float lotX = inner / float(lotsX), lotZ = inner / float(lotsZ);
    for (int a = 0; a < lotsX; ++a) {
        for (int b = 0; b < lotsZ; ++b) {
            const int lot = 16 * a + b;
            const float height = (8.0f + 22.0f * cityHash(i, j, 100 + lot)) * downtown;
            const bool tower = cityHash(i, j, 200 + lot) < 0.06f;
            const float h = std::min(tower ? 2.2f * height + 20.0f : height, kCityMaxHeight);
            const glm::vec3 c(centre.x - 0.5f * inner + (float(a) + 0.5f) * lotX, 0.0f,
                              centre.z - 0.5f * inner + (float(b) + 0.5f) * lotZ);
            addBox(scene, tower ? "tower" : "building", material, c + glm::vec3(0.0f, kCityCurbHeight + 0.5f * h, 0.0f),
                   {lotX, h, lotZ});
            if (tower) {  // a narrower top, a tenth of the height again (still under kCityMaxHeight)
                const float top = std::min(0.1f * h, kCityMaxHeight - h);
                if (top > 1.0f)
                    addBox(scene, "tower-top", material, c + glm::vec3(0.0f, kCityCurbHeight + h + 0.5f * top, 0.0f),
                           {0.6f * lotX, top, 0.6f * lotZ});
            }
        }
    }
}

// The furniture of one sidewalk of the street x = 0 beside a block: `side` = -1 (x < 0) or +1, `z` the block's
// centre. Everything stands on the sidewalk (y = kCityCurbHeight).
void addCityFurniture(Scene& scene, float side, float z, int metal, int wood) {
    const float curb = 0.5f * kCityStreetWidth, y0 = kCityCurbHeight;
    for (const float dz : kCityLampOffsets) {
        const float x = side * (curb + kCityLampCurb), w = kCityLampPoleWidth;
        addBox(scene, "lamp-post", metal, {x, y0 + 0.5f * kCityLampHeight, z + dz}, {w, kCityLampHeight, w});
        const float arm = 1.5f;  // over the road, just under the pole's top
        addBox(scene, "lamp-arm", metal, {x - side * (0.5f * arm + 0.5f * w), y0 + kCityLampHeight - 0.1f, z + dz},
               {arm, 0.08f, 0.08f});
        addBox(scene, "lamp-head", metal, {x - side * (arm + 0.2f), y0 + kCityLampHeight - 0.2f, z + dz},
               {0.6f, 0.15f, 0.3f});
    }
    // A bench along the street near the facade, its back to the building: seat, back, two end legs.
    const float bx = side * (curb + kCitySidewalkWidth - 1.0f), bz = z + kCityBenchOffset;
    const float seatDepth = 0.45f, seat = kCityBenchSeatHeight;
    addBox(scene, "bench-seat", wood, {bx, y0 + seat - 0.03f, bz}, {seatDepth, 0.06f, kCityBenchLength});
    addBox(scene, "bench-back", wood, {bx + side * 0.5f * seatDepth, y0 + seat + 0.25f, bz},
           {0.05f, 0.4f, kCityBenchLength});
    for (const float end : {-1.0f, 1.0f})
        addBox(scene, "bench-leg", metal, {bx, y0 + 0.5f * (seat - 0.06f), bz + end * 0.4f * kCityBenchLength},
               {seatDepth, seat - 0.06f, 0.06f});
    // Bollards along the curb at both corners of the block.
    for (const float corner : {-1.0f, 1.0f}) {
        for (int k = 0; k < kCityBollardsPerCorner; ++k) {
            const float along = 0.5f * kCityBlockSize - 1.0f - 1.5f * float(k);
            addBox(scene, "bollard", metal, {side * (curb + 0.4f), y0 + 0.5f * kCityBollardHeight, z + corner * along},
                   {kCityBollardWidth, kCityBollardHeight, kCityBollardWidth});
        }
    }
}

Scene city() {
    Scene scene = baseScene("city");
    scene.materials[0].baseColorFactor = {0.42f, 0.42f, 0.44f, 1.0f};  // asphalt
    scene.materials[1].baseColorFactor = {0.3f, 0.32f, 0.33f, 1.0f};   // painted metal
    const int building = int(scene.materials.size());
    scene.materials.push_back(opaque("building", {0.78f, 0.72f, 0.62f, 1.0f}));
    const int sidewalk = int(scene.materials.size());
    scene.materials.push_back(opaque("sidewalk", {0.66f, 0.65f, 0.62f, 1.0f}));
    const int wood = int(scene.materials.size());
    scene.materials.push_back(opaque("wood", {0.55f, 0.36f, 0.2f, 1.0f}));

    MeshBuilder ground("floor", 0);
    const float g = 0.5f * kCityGroundSize;
    ground.quad({0, 0, 0}, {g, 0, 0}, {0, 0, -g});  // cross(+x, -z) = +y
    addObject(scene, std::move(ground));
    const float first = -0.5f * float(kCityBlocks - 1) * kCityPeriod;
    for (int i = 0; i < kCityBlocks; ++i) {
        for (int j = 0; j < kCityBlocks; ++j) {
            const glm::vec3 c(first + float(i) * kCityPeriod, 0.0f, first + float(j) * kCityPeriod);
            addBox(scene, "sidewalk", sidewalk, c + glm::vec3(0.0f, 0.5f * kCityCurbHeight, 0.0f),
                   {kCityBlockSize, kCityCurbHeight, kCityBlockSize});
            addCityBuildings(scene, i, j, c, building);
        }
    }
    // The street x = 0 runs between block columns kCityBlocks / 2 - 1 and kCityBlocks / 2.
    for (int j = 0; j < kCityBlocks; ++j)
        for (const float side : {-1.0f, 1.0f}) addCityFurniture(scene, side, first + float(j) * kCityPeriod, 1, wood);

    SceneLight sun;
    sun.name = "sun";
    sun.direction = glm::normalize(kCitySunDir);
    sun.color = {1.0f, 0.93f, 0.8f};
    scene.lights.push_back(sun);
    scene.viewpoint = Scene::Viewpoint{glm::dvec3(kCityEye), glm::dvec3(kCityEyeTarget)};
    return scene;
}

// A car's loop: the rectangle of street centre lines x0 < x1, z0 < z1 it drives around on its inner lane,
// counter-clockwise seen from above when `ccw`, starting at `phase` (a share of the loop) at t = 0.
struct CityCarLoop {
    float x0, x1, z0, z1;
    float phase;
    bool ccw;
};
constexpr CityCarLoop kCityCarLoops[] = {
    {0.0f, 100.0f, 200.0f, 400.0f, 0.69f, false},    // away from the eye on x = 3.5, 60 m ahead
    {-100.0f, 0.0f, 300.0f, 400.0f, 0.40f, false},   // toward the eye on x = -3.5, 80 m ahead
    {0.0f, 200.0f, -300.0f, 100.0f, 0.1f, true},
    {-300.0f, -100.0f, 100.0f, 400.0f, 0.6f, true},
    {100.0f, 300.0f, 100.0f, 400.0f, 0.35f, false},
    {-100.0f, 100.0f, 400.0f, 500.0f, 0.155f, false},  // across the street 36 m ahead, its shadow in the sun
};
static_assert(std::size(kCityCarLoops) == std::size_t(kCityCars));

// One car's loop as node animation keys: a LINEAR translation through the phase
// point and the four corners of its inner lane, back to the phase point at kCityTrafficSeconds, and a STEP rotation
// to the heading of the side each key starts.
void addCarChannels(Animation& traffic, int node, const CityCarLoop& loop) {
    const float xa = loop.x0 + kCityLaneInset, xb = loop.x1 - kCityLaneInset;
    const float za = loop.z0 + kCityLaneInset, zb = loop.z1 - kCityLaneInset;
    // Counter-clockwise seen from above turns the heading +z -> +x -> -z -> -x (positive turns about +y).
    std::vector<glm::vec2> corners = {{xa, za}, {xa, zb}, {xb, zb}, {xb, za}};
    if (!loop.ccw) std::reverse(corners.begin() + 1, corners.end());
    std::vector<float> start(5, 0.0f);  // distance along the loop at each corner (start[4]: the perimeter)
    for (int k = 0; k < 4; ++k) start[k + 1] = start[k] + glm::length(corners[(k + 1) % 4] - corners[k]);
    const float perimeter = start[4];
    const float d0 = loop.phase * perimeter;
    int side = 0;
    while (side < 3 && d0 >= start[side + 1]) ++side;
    auto at = [&](int k, float along) {
        const glm::vec2 from = corners[k % 4], to = corners[(k + 1) % 4];
        return from + (to - from) * (along / glm::length(to - from));
    };
    AnimationChannel move{node, AnimationPath::Translation, Interpolation::Linear, {}, {}};
    AnimationChannel turn{node, AnimationPath::Rotation, Interpolation::Step, {}, {}};
    auto key = [&](float distance, const glm::vec2& p, int k) {
        const glm::vec2 heading = corners[(k + 1) % 4] - corners[k % 4];
        const double half = 0.5 * std::atan2(double(heading.x), double(heading.y));  // +z turned to the heading
        move.times.push_back(distance / perimeter * kCityTrafficSeconds);
        move.values.insert(move.values.end(), {p.x, 0.0f, p.y});
        turn.times.push_back(move.times.back());
        turn.values.insert(turn.values.end(), {0.0f, float(std::sin(half)), 0.0f, float(std::cos(half))});
    };
    const glm::vec2 first = at(side, d0 - start[side]);
    key(0.0f, first, side);
    for (int k = side + 1; k <= side + 4; ++k) {
        const float distance = start[k % 4] + (k >= 4 ? perimeter : 0.0f) - d0;
        if (distance > 0.0f && distance < perimeter) key(distance, corners[k % 4], k);
    }
    key(perimeter, first, side);
    traffic.channels.push_back(std::move(move));
    traffic.channels.push_back(std::move(turn));
}

// The cars of "city-traffic": a node and an instance each, posed at t = 0 by their animation.
void addCityTraffic(Scene& scene) {
    const int paint = int(scene.materials.size());
    scene.materials.push_back(opaque("car", {0.62f, 0.12f, 0.1f, 1.0f}));
    Animation traffic;
    traffic.name = "traffic";
    traffic.end = kCityTrafficSeconds;
    for (int n = 0; n < kCityCars; ++n) {
        MeshBuilder car("car", paint);
        car.box({0.0f, kCityCarClearance + 0.5f * kCityCarBody.y, 0.0f}, kCityCarBody);
        SceneNode node;
        node.name = node.path = "car-" + std::to_string(n);
        node.gltfIndex = n;
        const int index = int(scene.nodes.size());
        scene.nodes.push_back(node);
        scene.instances.push_back(Instance{int(scene.meshes.size()), glm::mat4(1.0f), index});
        scene.meshes.push_back(std::move(car.mesh));
        addCarChannels(traffic, n, kCityCarLoops[n]);
        // The node's rest transform is its pose at t = 0.
        const AnimationChannel& move = traffic.channels[traffic.channels.size() - 2];
        const AnimationChannel& turn = traffic.channels.back();
        scene.nodes.back().local.translation = {move.values[0], move.values[1], move.values[2]};
        scene.nodes.back().local.rotation = glm::dquat(turn.values[3], turn.values[0], turn.values[1], turn.values[2]);
    }
    scene.animations.push_back(std::move(traffic));
    poseScene(scene, {0}, 0.0);
}

Scene cityTraffic() {
    Scene scene = city();
    scene.name = "city-traffic";
    addCityTraffic(scene);
    return scene;
}

struct Entry {
    const char* name;
    const char* description;
    Scene (*make)();
};

constexpr Entry kScenes[] = {
    {"textbook", "floor, cube, sphere and a floating box (detached shadow): the default scene", textbook},
    {"grazing", "a 40x40 plane at 80 deg to the default light with a box on it: acne without bias", grazing},
    {"thin-walls", "walls 0.02, 0.1 and 0.5 thick on a floor: too much bias detaches their shadows", thinWalls},
    {"fence", "an alpha-tested (MASK) double-sided fence of slats and a rail over a floor", fence},
    {"sphere-plane", "a finely tessellated unit sphere floating over a floor: the analytic check", spherePlane},
    {"roof", "a single-sided roof facing down over a floor, lit from above: cullMode=back drops its shadow", roof},
    {"room", "a closed room lit by a point light at its centre, a pillar and a table: cube-map seams cross the "
             "floor and walls", room},
    {"courtyard", "buildings and thin posts lit by a sun, two spot lights and a point-light lantern", courtyard},
    {"city", "2 km of box buildings on a street grid seen from eye height in a street, a low sun; lamp posts, "
             "benches and bollards thinner than a scene-fitted map's texel", city},
    {"city-traffic", "builtin:city with 6 cars driving loops around blocks (animation \"traffic\", 60 s), "
                     "three of them in the street in front of the eye", cityTraffic},
};

const Entry* find(const std::string& name) {
    for (const Entry& e : kScenes)
        if (name == e.name) return &e;
    return nullptr;
}

}  // namespace

glm::vec3 builtin::grazingPlaneNormal() {
    // Tilt the normal away from the light, in the vertical plane that holds the light, until the angle is 80 deg.
    const glm::dvec3 toLight = glm::normalize(-glm::dvec3(kDefaultLightDir));
    const glm::dvec3 up(0, 1, 0);
    const glm::dvec3 towardLight = glm::normalize(toLight - up * toLight.y);  // horizontal
    const double zenith = std::acos(toLight.y);
    const double tilt = double(kGrazingAngleDeg) * std::numbers::pi / 180.0 - zenith;
    return glm::vec3(glm::normalize(std::cos(tilt) * up - std::sin(tilt) * towardLight));
}

std::vector<std::string> builtinSceneNames() {
    std::vector<std::string> names;
    for (const Entry& e : kScenes) names.emplace_back(e.name);
    return names;
}

std::string builtinSceneDescription(const std::string& name) {
    const Entry* e = find(name);
    return e ? e->description : "";
}

std::optional<Scene> makeBuiltinScene(const std::string& name) {
    const Entry* e = find(name);
    if (!e) return std::nullopt;
    Scene scene = e->make();
    scene.computeBounds();
    extendBoundsOverAnimations(scene);
    return scene;
}

}  // namespace shadowlab
