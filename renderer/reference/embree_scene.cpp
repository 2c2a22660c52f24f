#include "reference/embree_scene.h"

#include "frame/face_culling.h"

#include <embree3/rtcore.h>

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/geometric.hpp>

#include <chrono>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace shadowlab {

namespace {

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
    const glm::vec3 p0(v[3 * tri[0]], v[3 * tri[0] + 1], v[3 * tri[0] + 2]);
    const glm::vec3 p1(v[3 * tri[1]], v[3 * tri[1] + 1], v[3 * tri[1] + 2]);
    const glm::vec3 p2(v[3 * tri[2]], v[3 * tri[2] + 1], v[3 * tri[2] + 2]);
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
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned geometry = RTCHitN_geomID(args->hit, args->N, i);
        const unsigned primitive = RTCHitN_primID(args->hit, args->N, i);
        if (culledByShadowPass(query->scene->geometry(geometry), primitive, *query->rules)) args->valid[i] = 0;
    }
}

}  // namespace

EmbreeScene::EmbreeScene(const Scene& scene, const glm::dvec3& origin, const std::vector<char>& castingInstances) {
    const auto start = std::chrono::steady_clock::now();
    RTCDevice device = rtcNewDevice(nullptr);
    if (!device) throw std::runtime_error("Embree: cannot create a device (error " +
                                          std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    device_ = device;
    RTCScene rtcScene = rtcNewScene(device);
    scene_ = rtcScene;
    rtcSetSceneBuildQuality(rtcScene, RTC_BUILD_QUALITY_MEDIUM);
    rtcSetSceneFlags(rtcScene, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);

    for (std::size_t n = 0; n < scene.instances.size(); ++n) {
        const Instance& instance = scene.instances[n];
        const Mesh& mesh = scene.meshes[std::size_t(instance.mesh)];
        if (mesh.indices.empty() || (n < castingInstances.size() && !castingInstances[n])) continue;
        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        // Positions made relative to the render origin in double, then stored as float: exact for large worlds.
        const glm::dmat4 model = glm::dmat4(instance.transform);
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.positions.size()));
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const glm::dvec3 p = glm::dvec3(model * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0)) - origin;
            vertices[3 * i] = float(p.x);
            vertices[3 * i + 1] = float(p.y);
            vertices[3 * i + 2] = float(p.z);
        }
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.triangleCount()));
        std::memcpy(indices, mesh.indices.data(), mesh.triangleCount() * 3 * sizeof(unsigned));
        triangles_ += mesh.triangleCount();

        const Material* material = scene.materialOf(mesh);
        GeometryInfo info;
        info.vertices = vertices;
        info.indices = indices;
        info.mirrored = instance.mirrored();
        info.doubleSided = material && material->doubleSided;
        info.alphaMask = material && material->alphaMode == AlphaMode::Mask;
        if (material && material->alphaMode == AlphaMode::Mask) {
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
        const unsigned id = rtcAttachGeometry(rtcScene, geometry);
        if (geometries_.size() <= id) geometries_.resize(id + 1);
        geometries_[id] = info;
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(rtcScene);
    if (const RTCError error = rtcGetDeviceError(device); error != RTC_ERROR_NONE)
        throw std::runtime_error("Embree: building the BVH failed (error " + std::to_string(int(error)) + ")");
    buildMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

EmbreeScene::~EmbreeScene() {
    if (scene_) rtcReleaseScene(static_cast<RTCScene>(scene_));
    if (device_) rtcReleaseDevice(static_cast<RTCDevice>(device_));
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

}  // namespace shadowlab

namespace shadowlab {

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
    result.hit = true;
    result.t = ray.tfar;
    result.geometry = rayHit.hit.geomID;
    result.primitive = rayHit.hit.primID;
    result.alphaMask = geometries_[result.geometry].alphaMask;
    result.doubleSided = geometries_[result.geometry].doubleSided;
    return result;
}

}  // namespace shadowlab
