#pragma once
// The table of view builders: each fit mode or light kind is one builder (its own file) and one line in the table
// (views/view_builders.cpp). buildLightViews asks the first builder that applies to a light.
#include "views/shadow_view.h"

#include <string>
#include <vector>

namespace shadowlab {

struct ViewBuilder {
    const char* name;                               // "cascades", for messages and docs
    bool (*applies)(const LightSettings& light);
    // The light's views in order (their `light` is set by the caller), or none with `why` ("light.direction: ...").
    std::vector<ShadowView> (*build)(const ViewBuildInput& in, std::string& why);
};

const std::vector<ViewBuilder>& viewBuilders();

// The builders (each in its own file).
bool cascadesApply(const LightSettings& light);
std::vector<ShadowView> buildCascadeViews(const ViewBuildInput& in, std::string& why);
bool cubeFacesApply(const LightSettings& light);
std::vector<ShadowView> buildCubeFaceViews(const ViewBuildInput& in, std::string& why);
bool sceneFitApplies(const LightSettings& light);
std::vector<ShadowView> buildSceneFitView(const ViewBuildInput& in, std::string& why);

}  // namespace shadowlab
