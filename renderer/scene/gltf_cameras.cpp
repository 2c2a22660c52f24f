#include "scene/gltf_cameras.h"

#include "scene/gltf_camera_precheck.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace shadowlab::gltf {

namespace {
// As the camera.position key allows: a float cannot place a view farther out.
constexpr double kMaxCameraPosition = 1e7;
constexpr double kPi = 3.14159265358979323846;
}  // namespace

std::optional<SceneCamera> importCamera(const tg::Model& model, int nodeIndex, const glm::dmat4& world,
                                        const Warn& warn) {
    const tg::Node& node = model.nodes[std::size_t(nodeIndex)];
    if (node.camera < 0) return std::nullopt;
    if (node.camera >= int(model.cameras.size())) {
        warn("node " + str(nodeIndex) + ": camera " + str(node.camera) + " does not exist; ignored");
        return std::nullopt;
    }
    const tg::Camera& gc = model.cameras[std::size_t(node.camera)];
    SceneCamera camera;
    camera.index = node.camera;
    camera.name = !gc.name.empty() ? gc.name : !node.name.empty() ? node.name : "camera " + str(node.camera);
    const std::string what = "camera " + str(node.camera) + " ('" + camera.name + "')";
    auto refuse = [&](const std::string& why) {
        warn(what + " refused: " + why);
        return std::nullopt;
    };
    // Stood in for before tinygltf read the file (gltf_camera_precheck.h): refused with the reason found then.
    if (gc.extras.IsObject() && gc.extras.Has(kRefusedCameraKey) && gc.extras.Get(kRefusedCameraKey).IsString())
        return refuse(gc.extras.Get(kRefusedCameraKey).Get<std::string>());
    const auto finite = [](double v) { return std::isfinite(v); };
    if (gc.type == "perspective") {
        const tg::PerspectiveCamera& p = gc.perspective;
        if (!finite(p.yfov) || !(p.yfov > 0.0) || !(p.yfov < kPi))
            return refuse("yfov " + str(p.yfov) + " is not an angle in (0, pi) radians");
        if (!finite(p.znear) || !(p.znear > 0.0)) return refuse("znear " + str(p.znear) + " is not > 0");
        // tinygltf reads an absent zfar as 0: the infinite projection.
        if (p.zfar != 0.0 && (!finite(p.zfar) || !(p.zfar > p.znear)))
            return refuse("zfar " + str(p.zfar) + " is not greater than znear " + str(p.znear));
        camera.yfovRad = p.yfov;
        camera.znear = p.znear;
        camera.zfar = p.zfar;
    } else if (gc.type == "orthographic") {
        const tg::OrthographicCamera& o = gc.orthographic;
        if (!finite(o.ymag) || o.ymag == 0.0) return refuse("ymag " + str(o.ymag) + " is zero or not finite");
        if (!finite(o.xmag) || o.xmag == 0.0) return refuse("xmag " + str(o.xmag) + " is zero or not finite");
        if (!finite(o.znear) || !(o.znear >= 0.0)) return refuse("znear " + str(o.znear) + " is not >= 0");
        if (!finite(o.zfar) || !(o.zfar > o.znear))
            return refuse("zfar " + str(o.zfar) + " is not greater than znear " + str(o.znear));
        camera.orthographic = true;
        camera.ymag = std::abs(o.ymag);
        camera.znear = o.znear;
        camera.zfar = o.zfar;
    } else {
        return refuse("unknown type '" + gc.type + "' (allowed perspective, orthographic)");
    }
    const NodeFrame frame = nodeFrame(world);  // a camera stands at its node's origin, looking along its -Z
    const glm::dvec3& position = frame.position;
    if (!(std::max({std::abs(position.x), std::abs(position.y), std::abs(position.z)}) <= kMaxCameraPosition))
        return refuse("its node " + str(nodeIndex) + " places it at (" + str(position.x) + ", " + str(position.y) +
                      ", " + str(position.z) + "), beyond " + str(kMaxCameraPosition) + " (the camera.position limit)");
    if (!frame.forward) return refuse("its node " + str(nodeIndex) + "'s transform has no -Z direction (zero scale)");
    camera.position = position;
    camera.forward = *frame.forward;
    return camera;
}

}  // namespace shadowlab::gltf
