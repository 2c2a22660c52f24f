#include "reference/embree_scene.h"

#include "frame/face_culling.h"
#include "scene/scene_fingerprint.h"

#include <embree3/rtcore.h>

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace shadowlab {

// One mesh's BVH: its triangles around the centre of its finite vertices (the instance transform adds the centre
// back, composed in double), so a mesh far from its own origin keeps float's precision.
struct EmbreeScene::MeshBvh {
    RTCScene scene = nullptr;
    const float* vertices = nullptr;
    const unsigned* indices = nullptr;
    glm::dvec3 centre{0.0};
    std::size_t triangles = 0;
    bool doubleSided = false;
    bool alphaMask = false;
    ~MeshBvh() {
        if (scene) rtcReleaseScene(scene);
    }
};

namespace {

using Clock = std::chrono::steady_clock;

double elapsedMsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Every query passes one of these (its first member is Embree's context, so the filters can reach the rules).
struct QueryContext {
    RTCIntersectContext base;
    const EmbreeScene* scene = nullptr;
    const HitRules* rules = nullptr;  // null: plain occlusion (alpha-tested, nothing culled)
};

// Embree calls this for each candidate hit on a MASK geometry: a transparent texel is no hit.
void alphaOcclusionFilter(const RTCFilterFunctionNArguments* args) {
    const auto* query = reinterpret_cast<const QueryContext*>(args->context);
    if (query->rules && query->rules->ignoreAlpha) return;
    const auto* mask = static_cast<const AlphaMask*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned primitive = RTCHitN_primID(args->hit, args->N, i);
        const float u = RTCHitN_u(args->hit, args->N, i);
        const float v = RTCHitN_v(args->hit, args->N, i);
        if (!mask->opaqueAt(primitive, u, v)) args->valid[i] = 0;
    }
}

// Would the shadow pass cull this face? face_culling.h's rule, with the face's winding seen from the light.
bool culledByShadowPass(const EmbreeScene::GeometryInfo& g, unsigned primitive, const HitRules& rules) {
    if (!shadowPassCullsAny(rules.cullMode, g.doubleSided)) return false;  // no need for the winding
    const float* v = g.vertices;
    const unsigned* tri = g.indices + 3 * std::size_t(primitive);
    auto world = [&](unsigned i) {
        return glm::vec3(g.toWorld * glm::vec4(v[3 * i], v[3 * i + 1], v[3 * i + 2], 1.0f));
    };
    const glm::vec3 p0 = world(tri[0]), p1 = world(tri[1]), p2 = world(tri[2]);
    glm::vec3 front = glm::cross(p1 - p0, p2 - p0);
    if (g.mirrored) front = -front;
    const glm::vec3 towardLight = rules.positional ? rules.lightPosition - p0 : -rules.lightDirection;
    return shadowPassCulls(rules.cullMode, g.doubleSided, glm::dot(front, towardLight) > 0.0f);
}

RTCRay makeRay(const glm::vec3& origin, const glm::vec3& direction, float tFar) {
    RTCRay ray;
    ray.org_x = origin.x;
    ray.org_y = origin.y;
    ray.org_z = origin.z;
    ray.dir_x = direction.x;
    ray.dir_y = direction.y;
    ray.dir_z = direction.z;
    ray.tnear = 0.0f;
    ray.tfar = tFar;
    ray.time = 0.0f;
    ray.mask = 0xFFFFFFFFu;
    ray.id = 0;
    ray.flags = 0;
    return ray;
}

void cullingFilter(const RTCFilterFunctionNArguments* args) {
    const auto* query = reinterpret_cast<const QueryContext*>(args->context);
    if (!query->rules || !query->rules->shadowPassCulling) return;
    // The candidate's instance: the one being traversed (a mesh BVH holds one geometry; primID is its triangle).
    const unsigned instance = args->context->instID[0];
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned primitive = RTCHitN_primID(args->hit, args->N, i);
        if (culledByShadowPass(query->scene->geometry(instance), primitive, *query->rules)) args->valid[i] = 0;
    }
}

// The centre of the finite vertices' box, in double (exact for float vertices), or the origin if none is finite.
glm::dvec3 finiteCentre(const std::vector<glm::vec3>& positions) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const glm::vec3& p : positions)
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
            lo = glm::min(lo, glm::dvec3(p));
            hi = glm::max(hi, glm::dvec3(p));
        }
    return lo.x <= hi.x ? 0.5 * (lo + hi) : glm::dvec3(0.0);
}

bool casts(const std::vector<char>& castingInstances, std::size_t n) {
    return n >= castingInstances.size() || castingInstances[n];
}

// The instance transform Embree applies: mesh BVH space (centred) -> render-origin-relative world, composed in
// double and stored in float only once relative, as the renderer's model matrices are.
glm::mat4 instanceToWorld(const Instance& instance, const glm::dvec3& centre, const glm::dvec3& origin) {
    return glm::mat4(glm::translate(glm::dmat4(1.0), -origin) * glm::dmat4(instance.transform) *
                     glm::translate(glm::dmat4(1.0), centre));
}

bool finiteInvertible(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    const float d = glm::determinant(glm::mat3(m));
    return std::isfinite(d) && d != 0.0f;
}

// Sets an instance geometry's transform; a collapsed or non-finite one (scene_animation.h collapses a pose that
// does not fit a float) hides the instance, as its degenerate triangles would.
void placeInstance(RTCGeometry geometry, const glm::mat4& toWorld) {
    rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &toWorld[0][0]);
    if (finiteInvertible(toWorld))
        rtcEnableGeometry(geometry);
    else
        rtcDisableGeometry(geometry);
    rtcCommitGeometry(geometry);
}

}  // namespace

EmbreeScene::EmbreeScene(const Scene& scene, const glm::dvec3& origin, const std::vector<char>& castingInstances)
    : layout_(layoutFingerprint(scene)) {
    const auto start = Clock::now();
    RTCDevice device = rtcNewDevice(nullptr);
    if (!device) throw std::runtime_error("Embree: cannot create a device (error " +
                                          std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    device_ = device;
    RTCScene top = rtcNewScene(device);
    scene_ = top;
    rtcSetSceneBuildQuality(top, RTC_BUILD_QUALITY_MEDIUM);
    rtcSetSceneFlags(top, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);

    // One BVH per mesh that a casting instance uses.
    meshBvhOf_.assign(scene.meshes.size(), -1);
    for (std::size_t n = 0; n < scene.instances.size(); ++n) {
        const auto m = std::size_t(scene.instances[n].mesh);
        if (!casts(castingInstances, n) || scene.meshes[m].indices.empty() || meshBvhOf_[m] >= 0) continue;
        const Mesh& mesh = scene.meshes[m];
        meshBvhOf_[m] = int(meshes_.size());
        auto bvh = std::make_unique<MeshBvh>();
        bvh->centre = finiteCentre(mesh.positions);
        bvh->triangles = mesh.triangleCount();
        bvh->scene = rtcNewScene(device);
        rtcSetSceneBuildQuality(bvh->scene, RTC_BUILD_QUALITY_MEDIUM);
        rtcSetSceneFlags(bvh->scene, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.positions.size()));
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const glm::dvec3 p = glm::dvec3(mesh.positions[i]) - bvh->centre;
            vertices[3 * i] = float(p.x);
            vertices[3 * i + 1] = float(p.y);
            vertices[3 * i + 2] = float(p.z);
        }
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.triangleCount()));
        std::memcpy(indices, mesh.indices.data(), mesh.triangleCount() * 3 * sizeof(unsigned));
        bvh->vertices = vertices;
        bvh->indices = indices;
        const Material* material = scene.materialOf(mesh);
        bvh->doubleSided = material && material->doubleSided;
        bvh->alphaMask = material && material->alphaMode == AlphaMode::Mask;
        if (bvh->alphaMask) {
            const Image* image = material->baseColorImage >= 0 &&
                                         material->baseColorImage < int(scene.images.size())
                                     ? &scene.images[std::size_t(material->baseColorImage)]
                                     : nullptr;
            masks_.push_back(std::make_unique<AlphaMask>(*material, image, mesh.uvs, mesh.indices));
            rtcSetGeometryUserData(geometry, masks_.back().get());
            rtcSetGeometryOccludedFilterFunction(geometry, alphaOcclusionFilter);
            rtcSetGeometryIntersectFilterFunction(geometry, alphaOcclusionFilter);
        }
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(bvh->scene, geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(bvh->scene);
        ++meshBuilds_;
        meshes_.push_back(std::move(bvh));
    }

    // The top level: one instance per casting instance.
    for (std::size_t n = 0; n < scene.instances.size(); ++n) {
        const Instance& instance = scene.instances[n];
        const int b = meshBvhOf_[std::size_t(instance.mesh)];
        if (b < 0 || !casts(castingInstances, n)) continue;
        const MeshBvh& bvh = *meshes_[std::size_t(b)];
        GeometryInfo info;
        info.vertices = bvh.vertices;
        info.indices = bvh.indices;
        info.toWorld = instanceToWorld(instance, bvh.centre, origin);
        info.instance = n;
        info.mesh = unsigned(instance.mesh);
        info.mirrored = instance.mirrored();
        info.doubleSided = bvh.doubleSided;
        info.alphaMask = bvh.alphaMask;
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(geometry, bvh.scene);
        rtcSetGeometryTimeStepCount(geometry, 1);
        placeInstance(geometry, info.toWorld);
        const unsigned id = rtcAttachGeometry(top, geometry);
        rtcReleaseGeometry(geometry);
        if (geometries_.size() <= id) geometries_.resize(id + 1);
        geometries_[id] = info;
        triangles_ += bvh.triangles;
    }
    rtcCommitScene(top);
    ++topCommits_;
    if (const RTCError error = rtcGetDeviceError(device); error != RTC_ERROR_NONE)
        throw std::runtime_error("Embree: building the BVH failed (error " + std::to_string(int(error)) + ")");
    buildMs_ = elapsedMsSince(start);
}

EmbreeScene::~EmbreeScene() {
    if (scene_) rtcReleaseScene(static_cast<RTCScene>(scene_));
    meshes_.clear();  // their scenes before the device
    if (device_) rtcReleaseDevice(static_cast<RTCDevice>(device_));
}

bool EmbreeScene::sameGeometry(const Scene& scene, const std::vector<char>& castingInstances) const {
    // Only transforms changed: scene_fingerprint.h's layout key, by address (the alpha masks read the scene's own uv,
    // index and image buffers, so a copy with the same contents is no match here).
    if (layoutFingerprint(scene) != layout_) return false;
    // The same casting instances in the top level, in order (the layout key holds each instance's mesh).
    std::size_t id = 0;
    for (std::size_t n = 0; n < scene.instances.size(); ++n) {
        if (!casts(castingInstances, n) || scene.meshes[std::size_t(scene.instances[n].mesh)].indices.empty()) continue;
        if (id >= geometries_.size() || geometries_[id].instance != n) return false;
        ++id;
    }
    return id == geometries_.size();
}

std::size_t EmbreeScene::updateTransforms(const Scene& scene, const glm::dvec3& origin) {
    const auto start = Clock::now();
    auto* top = static_cast<RTCScene>(scene_);
    std::size_t moved = 0;
    for (std::size_t id = 0; id < geometries_.size(); ++id) {
        GeometryInfo& info = geometries_[id];
        const Instance& instance = scene.instances[info.instance];
        const glm::mat4 toWorld =
            instanceToWorld(instance, meshes_[std::size_t(meshBvhOf_[info.mesh])]->centre, origin);
        if (toWorld == info.toWorld) continue;
        info.toWorld = toWorld;
        info.mirrored = instance.mirrored();
        placeInstance(rtcGetGeometry(top, unsigned(id)), toWorld);
        ++moved;
    }
    if (moved > 0) {
        rtcCommitScene(top);
        ++topCommits_;
        if (const RTCError error = rtcGetDeviceError(static_cast<RTCDevice>(device_)); error != RTC_ERROR_NONE)
            throw std::runtime_error("Embree: updating the instances failed (error " + std::to_string(int(error)) +
                                     ")");
    }
    updateMs_ = elapsedMsSince(start);
    return moved;
}

bool EmbreeScene::occluded(const glm::vec3& origin, const glm::vec3& direction, float tFar) const {
    QueryContext query;
    rtcInitIntersectContext(&query.base);
    query.scene = this;
    RTCIntersectContext& context = query.base;
    RTCRay ray = makeRay(origin, direction, tFar);
    rtcOccluded1(static_cast<RTCScene>(scene_), &context, &ray);
    return ray.tfar == -std::numeric_limits<float>::infinity();
}

void EmbreeScene::occluded(const glm::vec3& origin, const glm::vec3* directions, std::size_t count, float tFar,
                           std::uint8_t* blocked) const {
    QueryContext query;
    rtcInitIntersectContext(&query.base);
    query.base.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    query.scene = this;
    thread_local std::vector<RTCRay> rays;  // reused: a pixel's rays, every pixel of a row
    rays.resize(count);
    for (std::size_t r = 0; r < count; ++r) rays[r] = makeRay(origin, directions[r], tFar);
    rtcOccluded1M(static_cast<RTCScene>(scene_), &query.base, rays.data(), unsigned(count), sizeof(RTCRay));
    for (std::size_t r = 0; r < count; ++r)
        blocked[r] = rays[r].tfar == -std::numeric_limits<float>::infinity() ? 1 : 0;
}

RayHit EmbreeScene::firstHit(const glm::vec3& origin, const glm::vec3& direction, float tFar,
                             const HitRules& rules) const {
    QueryContext query;
    rtcInitIntersectContext(&query.base);
    query.scene = this;
    query.rules = &rules;
    if (rules.shadowPassCulling) query.base.filter = cullingFilter;
    RTCRayHit rayHit;
    rayHit.ray = makeRay(origin, direction, tFar);
    const RTCRay& ray = rayHit.ray;
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(static_cast<RTCScene>(scene_), &query.base, &rayHit);
    RayHit result;
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return result;
    // The hit's geomID is the mesh BVH's own (0); the top-level instance says which instance, mesh and material.
    const GeometryInfo& info = geometries_[rayHit.hit.instID[0]];
    result.hit = true;
    result.t = ray.tfar;
    result.geometry = rayHit.hit.instID[0];
    result.primitive = rayHit.hit.primID;
    result.alphaMask = info.alphaMask;
    result.doubleSided = info.doubleSided;
    return result;
}

}  // namespace shadowlab
