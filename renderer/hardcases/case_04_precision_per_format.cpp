// HARD_CASES 4: depth precision per format for a perspective (spot) map with n = 0.01, f = 1000. Two parallel planes
// face the light at distance z = 1, 10, 100; the nearer (the caster) covers half the cone. The caster-over-receiver
// order is resolved once their separation exceeds the world depth step at z plus the bias (DepthBias 1, one step).
// For each format the separation is stepped up a ladder and the smallest one that shadows the receiver is compared
// with the prediction from the format's step (the document's table beside it).
//   world depth step(z) = r * z^2 (f - n) / (f n),  window depth d(z) = f (z - n) / (z (f - n))
//   r: D16 2^-16, D24 2^-24, D32F 2^-24 (GL's [-1, 1] clip depth: the remap to [0, 1] keeps a float's step at 1),
//   D32F reversed-Z: the float step of 1 - d(z).
// The camera sits at the light looking along it; the caster is single-sided and faces away, so the camera sees
// the receiver through it (the main pass culls its back face, the shadow pass draws every face).
#include "hardcases/cases.h"

#include "hardcases/hard_case_scenes.h"
#include "settings/settings_fields.h"

#include <glm/ext/matrix_transform.hpp>

#include <cmath>

namespace shadowlab::hardcases {

namespace {

constexpr double kNear = 0.01, kFar = 1000.0;

struct Format {
    const char* name;
    DepthFormat format;
    bool reversedZ;
    double table10, table100;  // the document's world depth steps at z = 10 and 100
};
constexpr Format kFormats[] = {
    {"d16", DepthFormat::D16, false, 0.153, 15.3},
    {"d24", DepthFormat::D24, false, 6.0e-4, 0.060},
    {"d32f", DepthFormat::D32F, false, 6.0e-4, 0.060},
    {"d32f reversed-Z", DepthFormat::D32F, true, 1.2e-6, 7.3e-6},
};

double predictedStep(const Format& f, double z) {
    double r = f.format == DepthFormat::D16 ? std::ldexp(1.0, -16) : std::ldexp(1.0, -24);
    if (f.reversedZ) {
        const double reversed = 1.0 - kFar * (z - kNear) / (z * (kFar - kNear));
        int exponent = 0;
        std::frexp(reversed, &exponent);
        r = std::ldexp(1.0, exponent - 24);
    }
    return r * z * z * (kFar - kNear) / (kFar * kNear);
}

// The caster (facing -y, x in [-w, 0]) at depth z below the light at the origin, the receiver (facing +y) sep farther.
Scene planes(double z, double sep) {
    Scene scene = meshKit("parallel-planes");
    const float w = float(z);
    const float s = w / 20.0f;
    glm::mat4 caster = glm::translate(glm::mat4(1.0f), {-0.5f * w, float(-z), 0.0f});
    caster = glm::rotate(caster, glm::radians(180.0f), glm::vec3(1, 0, 0));
    scene.instances.push_back({0, glm::scale(caster, glm::vec3(s, 1.0f, s))});
    const glm::mat4 receiver = glm::translate(glm::mat4(1.0f), {0.0f, float(-(z + sep)), 0.0f});
    scene.instances.push_back({0, glm::scale(receiver, glm::vec3(s, 1.0f, s))});
    scene.computeBounds();
    return scene;
}

// The share of the receiver behind the caster (the view's left part) or beside it (the right part) that is
// shadowed (S < 0.5), leaving out the band around the caster's edge.
double shadowedShare(const RenderedView& v, bool behindCaster) {
    int dark = 0, total = 0;
    for (int y = v.height / 4; y < 3 * v.height / 4; ++y)
        for (int x = 0; x < v.width; ++x) {
            if (std::abs(x - v.width / 2) < v.width / 8 || (x < v.width / 2) != behindCaster) continue;
            ++total;
            dark += v.red(x, y) < 128;
        }
    return total ? double(dark) / double(total) : 0.0;
}

// Resolved: the receiver behind the caster is shadowed (95 % of it).
bool resolved(const RenderedView& v) { return shadowedShare(v, true) >= 0.95; }

}  // namespace

void runPrecisionPerFormat(CaseContext& context, CaseResult& result) {
    const std::vector<double> depths = context.quick() ? std::vector<double>{10.0, 100.0}
                                                       : std::vector<double>{1.0, 10.0, 100.0};
    const int perDecade = context.pick(4, 2);
    Settings s;
    LightSettings& light = s.lights[0];
    light.type = LightType::Spot;
    light.position = {0.0f, 0.0f, 0.0f};
    light.direction = {0.0f, -1.0f, 0.0f};
    light.spotConeDeg = 30.0f;
    light.projection.autoFit = false;
    light.projection.nearPlane = float(kNear);
    light.projection.farPlane = float(kFar);
    light.shadow.resolution = 256;
    light.shadow.depthBias = 1.0f;  // one step of the format
    light.shadow.slopeScaledDepthBias = 0.0f;
    light.shadow.normalOffset = 0.0f;
    s.filter.kind = FilterKind::Point;
    s.view = ViewMode::Shadow;
    s.camera.autoFrame = false;
    s.camera.position = {0.0, 0.0, 0.0};
    s.camera.target = {0.0, -1.0, 0.0};
    s.camera.fovYDeg = 20.0f;
    for (const Format& format : kFormats) {
        Settings f = s;
        f.lights[0].shadow.format = format.format;
        if (format.reversedZ) {
            if (std::string missing = CaseContext::reversedZMissing(); !missing.empty()) {
                result.notRun(std::string(format.name) + ": smallest resolvable separation", "vs the table", missing);
                continue;
            }
            if (std::string error = applySettingOverride(f, "lights.0.shadow.reversedZ=true"); !error.empty())
                throw std::runtime_error(error);
        }
        for (double z : depths) {
            // The ladder: 10^(k / perDecade) from 1e-8 z up to 2 z; the smallest separation from which every larger
            // one on the ladder is resolved.
            double smallest = -1.0;
            for (int k = 8 * perDecade; k >= 0; --k) {
                const double sep = z * std::pow(10.0, -double(k) / perDecade) * 2.0;
                const Scene scene = planes(z, sep);
                const RenderedView v = context.render(scene, f, 48, 48, "");
                if (!v.stats.ok) throw std::runtime_error(v.stats.error);
                if (resolved(v)) {
                    if (smallest < 0.0) smallest = sep;
                } else {
                    smallest = -1.0;  // not resolved here: only larger separations can count
                }
            }
            const std::string picture = std::string(format.reversedZ ? "d32f-reversed" : format.name) + "-z" +
                                        std::to_string(int(z)) + "-sep0.01";
            const RenderedView at = context.render(planes(z, 0.01), f, 48, 48, picture);
            const bool atOneHundredth = resolved(at);
            const double step = predictedStep(format, z);
            const double table = z == 10.0 ? format.table10 : z == 100.0 ? format.table100 : 0.0;
            const double expected = 2.0 * step;  // the step plus a one-step bias
            const double ladder = std::pow(10.0, 1.0 / perDecade);
            // Within a factor 2 and one ladder step of the prediction (the ladder cannot place it closer).
            const bool tracks = smallest > 0.0 && smallest <= expected * ladder * 2.0 && smallest >= expected / (ladder * 2.0);
            result.check(std::string(format.name) + ", z = " + figure(z) + ": smallest resolvable separation",
                         smallest > 0 ? figure(smallest, "units") : "none",
                         "step + bias = " + figure(expected) + " x/÷ 2 and a ladder step (step " + figure(step) +
                             (table > 0 ? ", table " + figure(table) : "") + ")",
                         tracks);
            result.check(std::string(format.name) + ", z = " + figure(z) + ": planes 0.01 apart resolved",
                         atOneHundredth ? "yes" : "no", expected < 0.01 ? "yes (step + bias < 0.01)" : "no (step + bias > 0.01)",
                         atOneHundredth == (expected < 0.01) || std::abs(std::log10(expected / 0.01)) < 0.5);
            result.info(std::string(format.name) + ", z = " + figure(z) + ": receiver beside the caster shadowed",
                        percent(100.0 * shadowedShare(at, false)), "acne of the receiver itself at DepthBias 1");
        }
    }
}

}  // namespace shadowlab::hardcases
