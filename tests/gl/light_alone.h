#pragma once
// One light of a set rendered alone in the shadow view (the same camera and size as the set): its shadow factor S,
// where it reaches (the same light with castsShadows off: S = 1 wherever it reaches, 0 elsewhere), and how many of
// the pixels it reaches it shadows. A casting light whose map is lost or never sampled shadows none.
#include "gl_fixture.h"

#include <cstddef>
#include <vector>

namespace shadowlab::test {

struct LightAlone {
    std::vector<double> shadowFactor;  // per pixel (GL order), S in [0, 1]; 0 where the light does not reach
    std::vector<double> reach;         // per pixel, 1 where the light reaches, 0 elsewhere
    long reached = 0;                  // scene pixels it reaches
    long shadowed = 0;                 // of those, pixels where its S < 0.25
};

// `settings` with only lights[light]; the view is forced to the shadow view.
LightAlone renderLightAlone(Renderer& renderer, const Scene& scene, const Settings& settings, std::size_t light,
                            int width, int height);

}  // namespace shadowlab::test
