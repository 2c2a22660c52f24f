#include "cli/mover_camera.h"

#include "scene/scene_animation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadowlab::cli {

Camera cameraOnMovers(const Scene& scene, const std::vector<int>& chosen, const std::vector<std::size_t>& instances,
                      const std::vector<double>& times, const CameraSettings& settings, double aspect) {
    // Each mesh's box in its own space: its corners at each pose bound what the caster sweeps.
    struct Box {
        glm::dvec3 lo{std::numeric_limits<double>::max()}, hi{-std::numeric_limits<double>::max()};
    };
    std::vector<Box> boxes;
    for (std::size_t instance : instances) {
        Box box;
        for (const glm::vec3& p : scene.meshes[std::size_t(scene.instances[instance].mesh)].positions)
            if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
                box.lo = glm::min(box.lo, glm::dvec3(p));
                box.hi = glm::max(box.hi, glm::dvec3(p));
            }
        boxes.push_back(box);
    }
    glm::dvec3 sweptLo(std::numeric_limits<double>::max()), sweptHi(-std::numeric_limits<double>::max());
    double size = 0.0;
    Scene posed = scene;
    for (double t : times) {
        poseScene(posed, chosen, t);
        for (std::size_t k = 0; k < instances.size(); ++k) {
            const glm::dmat4 toWorld(posed.instances[instances[k]].transform);
            const Box& box = boxes[k];
            glm::dvec3 poseLo(std::numeric_limits<double>::max()), poseHi(-std::numeric_limits<double>::max());
            for (int c = 0; c < 8; ++c) {
                const glm::dvec3 corner((c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y,
                                        (c & 4) ? box.hi.z : box.lo.z);
                const glm::dvec3 world(toWorld * glm::dvec4(corner, 1.0));
                if (!std::isfinite(world.x) || !std::isfinite(world.y) || !std::isfinite(world.z)) continue;
                poseLo = glm::min(poseLo, world);
                poseHi = glm::max(poseHi, world);
            }
            if (poseLo.x > poseHi.x) continue;  // no finite corner at this pose
            size = std::max(size, glm::length(poseHi - poseLo));
            sweptLo = glm::min(sweptLo, poseLo);
            sweptHi = glm::max(sweptHi, poseHi);
        }
    }
    Camera camera;
    camera.fovYDeg = settings.fovYDeg;
    if (sweptLo.x > sweptHi.x) return cameraFor(settings, scene, aspect);  // none at a finite pose: nothing to frame
    sweptLo -= glm::dvec3(size);
    sweptHi += glm::dvec3(size);
    std::vector<glm::dvec3> corners;
    for (int c = 0; c < 8; ++c)
        corners.emplace_back((c & 1) ? sweptHi.x : sweptLo.x, (c & 2) ? sweptHi.y : sweptLo.y,
                             (c & 4) ? sweptHi.z : sweptLo.z);
    camera.target = 0.5 * (sweptLo + sweptHi);
    camera.position = camera.target + glm::normalize(glm::dvec3(scene.viewDirection));
    framePoints(camera, corners, aspect);
    fitDepthRange(camera, scene.bounds);
    return camera;
}

}  // namespace shadowlab::cli
