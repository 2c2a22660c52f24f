#include "hardcases/camera_motion.h"

#include <glm/ext/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace shadowlab::hardcases {

CameraMotion moveCamera(CaseContext& context, const Scene& scene, const Settings& settings, int width, int height,
                        int frames, const glm::dvec3& step, double turnDeg, const std::string& picture) {
    Renderer renderer;  // its own: the first frame renders the map, every later one may not
    CameraMotion motion;
    Settings s = settings;
    RenderedView first;
    for (int f = 0; f <= frames; ++f) {
        const double k = double(f);
        s.camera.position = settings.camera.position + k * step;
        const glm::dvec3 look = settings.camera.target - settings.camera.position;
        const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::radians(k * turnDeg), glm::dvec3(0, 1, 0));
        s.camera.target = s.camera.position + glm::dvec3(turn * glm::dvec4(look, 0.0));
        const bool keep = f == 0 || f == frames;
        RenderedView view = context.render(scene, s, width, height,
                                           keep && !picture.empty() ? picture + (f == 0 ? "-first" : "-last") : "",
                                           &renderer);
        if (!view.stats.ok) throw std::runtime_error("frame " + std::to_string(f) + ": " + view.stats.error);
        if (f == 0) {
            first = std::move(view);
        } else {
            ++motion.frames;
            for (const ShadowViewStats& v : view.stats.views) motion.viewsRerendered += v.ran;
            motion.lightSpaceChanged += view.stats.light.viewProjection() != first.stats.light.viewProjection();
        }
    }
    return motion;
}

}  // namespace shadowlab::hardcases
