// HARD_CASES 18: cascade splits at extreme near / far. The practical splits C_i = λ n (f/n)^(i/N) + (1-λ)(n + (f-n)
// i/N), N = 4, against the document's figures; strictly increasing and finite for every λ in [0, 1] (a fine sweep)
// at n = 0.1, 0.001, a near plane whose f/n overflows a double (the logarithmic term starts at f x float's epsilon)
// and a range two ulps wide (whose slices round to zero width and are merged); n = f and f < n refused with a
// message naming the key; every cascade's matrix finite (double and float) for both fits. The splits and views are the renderer's own (views/cascade_views.h, buildLightViews): no GL.
#include "hardcases/cases.h"

#include "views/cascade_views.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <sstream>

namespace shadowlab::hardcases {

namespace {

// A camera at eye height over a 2 km city looking along -Z, with the case's near and far planes (fov 50, 16:9).
ViewCamera caseCamera(double nearPlane, double farPlane) {
    ViewCamera c;
    c.eye = {0.0, 1.7, 0.0};
    c.forward = {0.0, 0.0, -1.0};
    c.right = {1.0, 0.0, 0.0};
    c.up = {0.0, 1.0, 0.0};
    c.tanHalfFovY = std::tan(glm::radians(25.0));
    c.aspect = 16.0 / 9.0;
    c.nearPlane = nearPlane;
    c.farPlane = farPlane;
    return c;
}

Bounds cityBounds() {
    Bounds b;
    b.extend(glm::vec3(-1000.0f, 0.0f, -1000.0f));
    b.extend(glm::vec3(1000.0f, 120.0f, 1000.0f));
    return b;
}

LightSettings sun(CascadeFit fit, float lambda) {
    LightSettings l;
    l.direction = {-0.5f, -1.0f, -0.3f};
    l.shadow.resolution = 1024;
    l.projection.fit = ProjectionFit::Cascades;
    l.projection.cascadeCount = 4;
    l.projection.cascadeFit = fit;
    l.projection.splitLambda = lambda;
    return l;
}

std::string listOf(const std::vector<double>& depths) {
    std::ostringstream out;
    out.precision(4);
    for (std::size_t i = 0; i + 1 < depths.size(); ++i) out << (i ? ", " : "") << depths[i];
    return out.str();
}

// The view's matrix finite in double and in float, as the GPU gets it.
bool finiteMatrix(const LightSpace& space) {
    const glm::dmat4 m = space.viewProjection();
    const glm::mat4 gpu(m);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r]) || !std::isfinite(gpu[c][r])) return false;
    return true;
}

}  // namespace

void runCascadeSplits(CaseContext& context, CaseResult& result) {
    // The document's figures: the three inner splits, each to the digits it prints.
    struct Figures {
        double nearPlane, lambda;
        double split[3];
        double tolerance[3];  // half the last printed digit
    };
    const Figures figures[] = {
        {0.1, 1.0, {1.0, 10.0, 100.0}, {0.5, 0.5, 0.5}},
        {0.1, 0.9, {25.9, 59.0, 165.0}, {0.05, 0.05, 0.05}},
        {0.1, 0.5, {125.5, 255.0, 425.0}, {0.05, 0.05, 0.05}},
        {0.001, 1.0, {0.0316, 1.0, 31.6}, {0.00005, 0.05, 0.05}},
    };
    ProjectionSettings projection;
    projection.cascadeCount = 4;
    for (const Figures& fig : figures) {
        projection.splitLambda = float(fig.lambda);
        std::string why;
        const std::vector<double> far = cascadeFarDepths(projection, caseCamera(fig.nearPlane, 1000.0), why);
        bool match = far.size() == 4 && far[3] == 1000.0;
        for (int i = 0; match && i < 3; ++i)
            match = std::abs(far[std::size_t(i)] - fig.split[i]) <= fig.tolerance[i];
        std::ostringstream doc;
        doc << fig.split[0] << ", " << fig.split[1] << ", " << fig.split[2];
        result.check("splits n = " + figure(fig.nearPlane) + ", f = 1000, lambda " + figure(fig.lambda),
                     far.empty() ? why : listOf(far), doc.str() + " (to the digits printed)", match);
        if (fig.nearPlane == 0.001) {
            const double lastShare = far.size() == 4 ? (far[3] - far[2]) / (far[3] - fig.nearPlane) : 0.0;
            result.info("n = 0.001: the first cascade's depth, the last one's share of the range",
                        figure(far.empty() ? 0.0 : far[0] - fig.nearPlane, "world units") + ", " +
                            percent(100.0 * lastShare),
                        "the document: 3 cm and 97 %");
        }
    }

    // Every λ in [0, 1]: strictly increasing, finite, ending at f; every cascade's matrix finite for both fits.
    struct Range {
        const char* what;
        double nearPlane, farPlane;
    };
    const double twoUlps = std::nextafter(std::nextafter(1.0, 2.0), 2.0);
    const Range ranges[] = {
        {"n = 0.1, f = 1000", 0.1, 1000.0},
        {"n = 0.001, f = 1000", 0.001, 1000.0},
        {"n = 1e-307, f = 1e4 (f/n overflows a double)", 1e-307, 1e4},
        {"n = 1, f = 1 + 2 ulps (slices round to zero width)", 1.0, twoUlps},
    };
    const int steps = context.pick(1000, 100);
    const Bounds bounds = cityBounds();
    for (const Range& range : ranges) {
        const ViewCamera camera = caseCamera(range.nearPlane, range.farPlane);
        int bad = 0, badViews = 0, fewest = 4;
        std::string firstBad;
        for (int k = 0; k <= steps; ++k) {
            const float lambda = float(double(k) / steps);
            projection.splitLambda = lambda;
            std::string why;
            const std::vector<double> far = cascadeFarDepths(projection, camera, why);
            bool ok = !far.empty() && far.back() == range.farPlane;
            double before = range.nearPlane;
            for (double depth : far) {
                ok = ok && std::isfinite(depth) && depth > before;
                before = depth;
            }
            fewest = std::min(fewest, int(far.size()));
            if (!ok && bad++ == 0)
                firstBad = "lambda " + figure(lambda) + ": " +
                           (far.empty() ? why : listOf(far) + ", " + figure(far.back()));
            for (CascadeFit fit : {CascadeFit::Stable, CascadeFit::Tight}) {
                std::string error;
                const auto views =
                    buildLightViews(sun(fit, lambda), 0, bounds, bounds.centreOrOrigin(), &camera, error);
                bool finite = views && views->size() == far.size();
                if (views)
                    for (const ShadowView& v : *views)
                        finite = finite && finiteMatrix(v.space) &&
                                 std::isfinite(v.space.texelWorldSize) && v.space.texelWorldSize > 0.0;
                if (!finite && badViews++ == 0 && firstBad.empty())
                    firstBad = "lambda " + figure(lambda) + ": " + (views ? "a matrix is not finite" : error);
            }
        }
        const std::string sweep = std::to_string(steps + 1) + " lambdas";
        result.check(std::string(range.what) + ": splits strictly increasing and finite over " + sweep,
                     bad ? std::to_string(bad) + " bad (" + firstBad + ")" : "all",
                     "every lambda in [0, 1]", bad == 0);
        result.check(std::string(range.what) + ": every cascade's matrix finite (stable and tight)",
                     badViews ? std::to_string(badViews) + " fits failed (" + firstBad + ")" : "all",
                     "every lambda, both fits, in double and float", badViews == 0);
        if (range.farPlane == twoUlps)
            result.check(std::string(range.what) + ": zero-width slices merged",
                         std::to_string(fewest) + " cascade(s) of 4 at the fewest", "fewer than 4, none empty",
                         bad == 0 && fewest < 4);
    }

    // n = f, f < n: nothing to split; refused with a message naming the key.
    projection.splitLambda = 0.5f;
    for (const auto& [what, shadowDistance] : {std::pair<const char*, float>{"n = f", 0.1f}, {"f < n", 0.05f}}) {
        ProjectionSettings p = projection;
        p.shadowDistance = shadowDistance;
        std::string why;
        // The near plane is the float key's own value, so that n = f holds exactly.
        const std::vector<double> far = cascadeFarDepths(p, caseCamera(double(0.1f), 1000.0), why);
        const bool named = why.find("projection.shadowDistance") != std::string::npos;
        result.check(std::string(what) + " (shadow distance " + figure(shadowDistance) + ", near 0.1): refused",
                     far.empty() ? why : "accepted: " + listOf(far), "a message naming projection.shadowDistance",
                     far.empty() && named);
    }

    // The tight fit's splits span only the depths the scene covers in reach; a scene beyond the shadow distance or a
    // flat one facing the camera leaves no such range: the camera's is kept (no zero-width slices).
    const ViewCamera camera = caseCamera(0.1, 1000.0);
    Bounds beyond, flat;
    beyond.extend(glm::vec3(-10.0f, 0.0f, -300.0f));
    beyond.extend(glm::vec3(10.0f, 5.0f, -200.0f));
    flat.extend(glm::vec3(-10.0f, -5.0f, -30.0f));
    flat.extend(glm::vec3(10.0f, 5.0f, -30.0f));
    for (const auto& [what, box] : {std::pair<const char*, const Bounds*>{"a scene beyond the shadow distance", &beyond},
                                    {"a flat scene facing the camera", &flat}}) {
        LightSettings light = sun(CascadeFit::Tight, 0.9f);
        light.projection.shadowDistance = 50.0f;
        std::string error;
        const auto views = buildLightViews(light, 0, *box, glm::dvec3(0.0), &camera, error);
        bool ok = views && !views->empty() && views->back().slice.farDepth == 50.0;
        std::vector<double> far;
        if (views)
            for (const ShadowView& v : *views) {
                ok = ok && finiteMatrix(v.space) && v.slice.farDepth > v.slice.nearDepth;
                far.push_back(v.slice.farDepth);
            }
        result.check(std::string("tight fit, ") + what + ": cascades over the camera's range",
                     views ? listOf(far) + ", " + figure(far.empty() ? 0.0 : far.back()) : error,
                     "4 non-empty slices ending at the shadow distance 50", ok);
    }
}

}  // namespace shadowlab::hardcases
