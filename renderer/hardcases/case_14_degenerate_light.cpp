// HARD_CASES 14: degenerate light parameters. What glm turns into NaN / inf (a zero direction, an ortho volume of
// size 0, near == far, a perspective near of 0, a NaN bias) must be refused with a clear message naming the key; and
// for extreme but valid settings no non-finite value may reach the GPU (every uniform read back).
#include "hardcases/cases.h"

#include "gl/gl_errors.h"
#include "hardcases/uniform_readback.h"
#include "light/light_space.h"
#include "scene/builtin_scenes.h"
#include "settings/settings_fields.h"

#include <glm/ext/matrix_transform.hpp>

namespace shadowlab::hardcases {

namespace {

// Applies the overrides in order and validates: the first refusal, or "".
std::string refusal(const std::vector<std::string>& overrides) {
    Settings s;
    for (const std::string& o : overrides)
        if (std::string error = applySettingOverride(s, o); !error.empty()) return error;
    const std::vector<std::string> problems = s.validate();
    return problems.empty() ? "" : problems.front();
}

}  // namespace

void runDegenerateLight(CaseContext& context, CaseResult& result) {
    struct Input {
        const char* what;
        std::vector<std::string> overrides;
        const char* key;  // the message must name it
    };
    const Input inputs[] = {
        {"zero-length direction", {"lights.0.direction=[0,0,0]"}, "lights.0.direction"},
        {"ortho size 0", {"lights.0.projection.autoFit=false", "lights.0.projection.orthoSize=0"},
         "lights.0.projection.orthoSize"},
        {"near == far", {"lights.0.projection.autoFit=false", "lights.0.projection.near=5", "lights.0.projection.far=5"},
         "lights.0.projection.near"},
        {"spot near = 0", {"lights.0.type=spot", "lights.0.projection.autoFit=false", "lights.0.projection.near=0"},
         "lights.0.projection.near"},
        {"NaN depth bias", {"lights.0.shadow.depthBias=NaN"}, "lights.0.shadow.depthBias"},
        {"infinite slope bias", {"lights.0.shadow.slopeScaledDepthBias=1e999"}, "lights.0.shadow.slopeScaledDepthBias"},
        {"NaN bias clamp", {"lights.0.shadow.depthBiasClamp=nan"}, "lights.0.shadow.depthBiasClamp"},
    };
    for (const Input& in : inputs) {
        const std::string why = refusal(in.overrides);
        const bool named = why.find(in.key) != std::string::npos;
        result.check(std::string(in.what) + ": refused", why.empty() ? "accepted" : why,
                     std::string("a message naming ") + in.key, !why.empty() && named);
    }

    // Extreme but valid: every uniform read back after the frame must be finite.
    const Scene textbook = *makeBuiltinScene("textbook");
    Scene zeroScale = textbook;
    zeroScale.instances[1].transform = glm::scale(glm::mat4(1.0f), glm::vec3(0.0f));  // no inverse for normals
    zeroScale.computeBounds();
    struct Extreme {
        const char* name;
        const Scene* scene;
        std::vector<std::string> overrides;
    };
    const Extreme extremes[] = {
        {"straight down", &textbook, {"lights.0.direction=[0,-1,0]"}},
        {"straight up", &textbook, {"lights.0.direction=[0,1,0]"}},
        {"pole tilt 1e-7", &textbook, {"lights.0.direction=[1e-7,-1,0]"}},
        {"spot 170 deg", &textbook, {"lights.0.type=spot", "lights.0.spotConeDeg=170", "lights.0.direction=[0,-1,0]"}},
        {"spot inside the cube", &textbook,
         {"lights.0.type=spot", "lights.0.position=[0,1,0]", "lights.0.direction=[1,-0.2,0]"}},
        {"tiny ortho volume", &textbook,
         {"lights.0.projection.autoFit=false", "lights.0.projection.orthoSize=1e-3", "lights.0.projection.near=1e-4",
          "lights.0.projection.far=1e-3"}},
        {"normal offset 16 on a 16^2 D16 map", &textbook,
         {"lights.0.shadow.normalOffset=16", "lights.0.shadow.depthFormat=d16", "lights.0.shadow.resolution=16"}},
        {"point light at a corner, range 1e-3", &textbook,
         {"lights.0.type=point", "lights.0.position=[10,0,10]", "lights.0.range=1e-3"}},
        {"zero-scale instance", &zeroScale, {}},
    };
    int clean = 0;
    std::string firstBad;
    for (const Extreme& e : extremes) {
        Settings s;
        for (const std::string& o : e.overrides)
            if (std::string error = applySettingOverride(s, o); !error.empty())
                throw std::runtime_error(std::string(e.name) + ": " + error);
        gl::drainErrors();
        const RenderedView view = context.render(*e.scene, s, 64, 64);
        std::vector<std::string> bad = view.stats.ok ? nonFiniteUniforms() : std::vector<std::string>{view.stats.error};
        if (view.stats.ok && !allFinite(view.stats.light.viewProjection())) bad.push_back("the light's matrix");
        if (const std::string glError = gl::drainErrors(); !glError.empty()) bad.push_back(glError);
        if (bad.empty())
            ++clean;
        else if (firstBad.empty())
            firstBad = std::string(e.name) + ": " + bad.front();
    }
    const int n = int(std::size(extremes));
    result.check("extreme valid settings: frames with every uniform finite, no GL error",
                 std::to_string(clean) + " of " + std::to_string(n) + (firstBad.empty() ? "" : " (" + firstBad + ")"),
                 "all", clean == n);
}

}  // namespace shadowlab::hardcases
