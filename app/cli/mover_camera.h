#pragma once
// The camera `bench --animation --cache-error` measures from when the settings leave the camera to auto-framing: one
// that sees the casters the animation moves. A cache error is a property of the view: the default camera of a large
// scene (builtin:city-traffic's street eye) sees no pixel where a car's shadow moves within a second, and reads 0.
#include "frame/camera.h"
#include "scene/scene.h"
#include "settings/settings.h"

#include <cstddef>
#include <vector>

namespace shadowlab::cli {

// Looks along the scene's preferred direction (Scene::viewDirection, from above) at the box the `instances` sweep over
// the chosen animations at `times`, grown on every side by the largest one's size so the shadows they cast nearby are
// in view too; the box fills a view of `aspect` as auto-framing fills it with a scene (framePoints). The field of view
// is the settings'; near and far hold the whole scene.
Camera cameraOnMovers(const Scene& scene, const std::vector<int>& chosen, const std::vector<std::size_t>& instances,
                      const std::vector<double>& times, const CameraSettings& settings, double aspect);

}  // namespace shadowlab::cli
