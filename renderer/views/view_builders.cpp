#include "views/view_builders.h"

namespace shadowlab {

const std::vector<ViewBuilder>& viewBuilders() {
    // In order: the first that applies builds the light's views.
    static const std::vector<ViewBuilder> builders = {
        {"cascades", cascadesApply, buildCascadeViews},      // directional, fit = cascades
        {"cube faces", cubeFacesApply, buildCubeFaceViews},  // point lights
        {"scene fit", sceneFitApplies, buildSceneFitView},   // directional (fit = scene) and spot lights
    };
    return builders;
}

}  // namespace shadowlab
