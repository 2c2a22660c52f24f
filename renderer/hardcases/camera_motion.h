#pragma once
// Case 7: the camera turned frame by frame while the light stands still (the flicker measure, accuracy/motion.h,
// plays translations only). The light's volume is fitted to the scene, not to the view, so the shadow map must not
// change: no view re-rendered, the light's matrix bit-equal.
#include "hardcases/hard_case.h"

#include <glm/ext/vector_double3.hpp>

namespace shadowlab::hardcases {

struct CameraMotion {
    int frames = 0;             // frames after the first
    int viewsRerendered = 0;    // shadow views rendered after the first frame (must be 0)
    int lightSpaceChanged = 0;  // frames whose first light space differs from the first frame's (must be 0)
};

// Renders `frames` + 1 frames from settings.camera (which must not auto-frame), moving the camera's position and
// target by `step` (world units) per frame, or turning it about its position by `turnDeg` around +y per frame.
// Writes the first and the last frame as `picture`-first / -last.
CameraMotion moveCamera(CaseContext& context, const Scene& scene, const Settings& settings, int width, int height,
                        int frames, const glm::dvec3& step, double turnDeg, const std::string& picture);

}  // namespace shadowlab::hardcases
