// HARD_CASES 19: cascade seams. A stable fit (bounding sphere per slice), fov 50, 16:9, lambda 0.9 over [0.1, 1000],
// 1024² per cascade: each cascade's texel against the document's 0.048, 0.110, 0.307 and 1.86 world units (ours are
// the slice sphere's diameter over 1024 rounded up to 1/64 of its power of two, so the stable size never jitters:
// at most 1/64 above the document's exact sphere). Then builtin:city from its street under its own sun in that
// configuration (shadow distance 1000): wrong pixels and mean |S - V| in a band of ±2 % of each split's depth, with
// and without a blend band, against the coarser cascade: its interior (shown) and, judged, the coarser cascade
// alone shading the same band pixels with the same map (the blend band mixes it with the finer one, so its error is
// no higher). The interior is no fair yardstick: the band lies at the coarser cascade's nearest depths, where its
// texels are largest on screen, and holds other surfaces.
#include "hardcases/cases.h"

#include "scene/builtin_scenes.h"
#include "views/cascade_views.h"

#include <cmath>
#include <sstream>

namespace shadowlab::hardcases {

namespace {

constexpr double kBand = 0.02;  // the document's band: ±2 % of the split's depth
constexpr float kBlendBand = 0.2f;  // projection.blendBand of the blended frame

struct Region {
    std::size_t measured = 0, wrong = 0;
    double errorSum = 0.0;
    double wrongPercent() const { return measured ? 100.0 * double(wrong) / double(measured) : 0.0; }
    double meanError() const { return measured ? errorSum / double(measured) : 0.0; }
    void add(float s, bool lit) {
        const double error = std::abs(double(s) - (lit ? 1.0 : 0.0));
        ++measured;
        wrong += error >= 0.5;
        errorSum += error;
    }
};

std::string describe(const Region& r) {
    return percent(r.wrongPercent()) + " wrong, mean " + figure(r.meanError(), "", 3) + " (" +
           std::to_string(r.measured) + " px)";
}

LightSettings caseSun(float blendBand) {
    LightSettings l;
    l.projection.fit = ProjectionFit::Cascades;
    l.projection.cascadeCount = 4;
    l.projection.cascadeFit = CascadeFit::Stable;
    l.projection.splitLambda = 0.9f;
    l.projection.shadowDistance = 1000.0f;
    l.projection.blendBand = blendBand;
    l.shadow.resolution = 1024;
    return l;
}

}  // namespace

void runCascadeSeams(CaseContext& context, CaseResult& result) {
    const Scene city = *makeBuiltinScene("city");

    // The texels of the document's configuration: the renderer's own views for a camera with its planes.
    Camera camera;
    camera.position = {0.0, 1.7, 0.0};
    camera.target = {0.0, 1.7, -10.0};
    camera.fovYDeg = 50.0;
    camera.nearPlane = 0.1;
    camera.farPlane = 1000.0;
    const glm::dvec3 origin = renderOriginOf(city.bounds);
    const ViewCamera view = viewCameraOf(camera, 16.0 / 9.0, origin);
    LightSettings sun = caseSun(0.0f);
    sun.direction = city.lights.front().direction;
    std::string error;
    const auto views = buildLightViews(sun, 0, city.bounds, origin, &view, error);
    if (!views) throw std::runtime_error(error);
    const double documented[4] = {0.048, 0.110, 0.307, 1.86};
    const double printed[4] = {0.0005, 0.0005, 0.0005, 0.005};  // half the last digit the document prints
    std::ostringstream ours, theirs;
    bool match = views->size() == 4;
    for (std::size_t c = 0; c < views->size() && c < 4; ++c) {
        const double texel = (*views)[c].space.texelWorldSize;
        ours << (c ? ", " : "") << figure(texel, "", 4);
        theirs << (c ? ", " : "") << documented[c];
        match = match && texel >= documented[c] - printed[c] &&
                texel <= (documented[c] + printed[c]) * (1.0 + 1.0 / 64.0);
    }
    result.check("stable fit, texel per cascade (world units)", ours.str(),
                 theirs.str() + " (+ at most 1/64: the size is rounded up so it never jitters)", match);
    if (views->size() == 4)
        result.info("texel jump at the last split",
                    figure((*views)[3].space.texelWorldSize / (*views)[2].space.texelWorldSize, "x"),
                    "the document: 6x (a texel-relative bias changes its world size by as much)");

    // The seam on the city from its street: the same keys, the camera's own planes and the view's aspect.
    const int width = context.pick(480, 320), height = context.pick(270, 180);
    Settings s;
    s.useSceneLights = true;  // the city's low sun; lights[0] tunes it
    s.camera.fovYDeg = 50.0f;
    const Camera street = cameraFor(s.camera, city, double(width) / height);
    const ViewCamera streetView = viewCameraOf(street, double(width) / height, glm::dvec3(0.0));  // world points
    const SurfaceSamples samples = context.surfaces(city, [&] {
        Settings plain = s;
        plain.lights[0] = caseSun(0.0f);
        return plain;
    }(), width, height);
    if (samples.size() != std::size_t(width) * std::size_t(height)) throw std::runtime_error("no G-buffer of the city");

    // The hard seam, the blend band, and per split i the coarser cascade alone: split i moved to where the blend band
    // starts (blend band 0), so cascade i + 1 covers the same slice as in the blended frame, the same sphere, the same
    // map, and shades the whole band. The band's content is then the same in every comparison; the interior (other
    // surfaces, and the coarser cascade's farther depths where its texels are smaller on screen) is context.
    std::string why;
    const std::vector<CascadeSlice> slices = cascadeSlices(caseSun(0.0f).projection, streetView, why);
    const std::vector<CascadeSlice> blended = cascadeSlices(caseSun(kBlendBand).projection, streetView, why);
    if (slices.size() != 4 || blended.size() != 4) throw std::runtime_error("the case's slices: " + why);
    std::vector<AccuracyReport> frames;  // hard, blend, coarser alone at split 0, 1, 2
    for (int k = 0; k < 5; ++k) {
        s.lights[0] = caseSun(k == 1 ? kBlendBand : 0.0f);
        if (k >= 2)
            for (std::size_t i = 0; i < 3; ++i)
                s.lights[0].projection.splits[int(i)] =
                    float(i == std::size_t(k - 2) ? blended[i].blendStart : slices[i].farDepth);
        frames.push_back(context.measure(city, s, width, height, k == 0 ? "hard" : k == 1 ? "blend" : ""));
        if (!frames.back().ok) throw std::runtime_error("frame " + std::to_string(k) + ": " + frames.back().error);
    }
    const AccuracyReport &hard = frames[0], &blend = frames[1];
    // Per split i: the band in each frame, and cascade i + 1's interior (its depths outside every band, in the
    // blended frame also outside its own blend band).
    std::vector<Region> bandHard(3), bandBlend(3), bandCoarser(3), interiorHard(3), interiorBlend(3);
    for (std::size_t p = 0; p < samples.size(); ++p) {
        if (!samples.isSurface(p)) continue;
        bool measured = true;
        for (const AccuracyReport& f : frames) measured = measured && f.pixelMeasured[p];
        if (!measured) continue;
        const double depth = streetView.depthOf(samples.point[p]);
        const bool lit = isLit(hard.pixelClass[p]);
        bool inBand = false;
        for (std::size_t i = 0; i < 3; ++i) {
            if (std::abs(depth - slices[i].farDepth) > kBand * slices[i].farDepth) continue;
            bandHard[i].add(hard.pixelShadow[p], lit);
            bandBlend[i].add(blend.pixelShadow[p], lit);
            bandCoarser[i].add(frames[2 + i].pixelShadow[p], lit);
            inBand = true;
        }
        if (inBand) continue;
        for (std::size_t i = 0; i < 3; ++i) {
            if (depth <= slices[i].farDepth || depth >= (1.0 - kBand) * slices[i + 1].farDepth) continue;
            interiorHard[i].add(hard.pixelShadow[p], lit);
            if (depth < blended[i + 1].blendStart) interiorBlend[i].add(blend.pixelShadow[p], lit);
        }
    }
    for (std::size_t i = 0; i < 3; ++i) {
        const std::string split = "split " + std::to_string(i) + " at " + figure(slices[i].farDepth, "", 4) +
                                  ", band ±2 %: ";
        const std::string coarser = "cascade " + std::to_string(i + 1);
        result.info(split + "hard seam / blend band " + figure(kBlendBand) + " vs " + coarser + "'s interior",
                    describe(bandHard[i]) + " / " + describe(bandBlend[i]) + " vs " + describe(interiorHard[i]) +
                        " / " + describe(interiorBlend[i]),
                    "other surfaces, and depths where its texels are smaller on screen: context");
        const std::string what = split + "blend band " + figure(kBlendBand) + " vs " + coarser +
                                 " alone at the same pixels (its same map), mean |S - V|";
        const std::string numbers = describe(bandBlend[i]) + " vs " + describe(bandCoarser[i]);
        result.check(what, numbers, "band <= the coarser cascade's, band not empty",
                     bandBlend[i].measured > 0 && bandBlend[i].meanError() <= bandCoarser[i].meanError());
    }
    result.info("the 3-pixel seam band (measure's figure) vs every interior, hard / blend",
                percent(hard.cascades.seam.bandWrongPercent) + " vs " + percent(hard.cascades.seam.interiorWrongPercent) +
                    " / " + percent(blend.cascades.seam.bandWrongPercent) + " vs " +
                    percent(blend.cascades.seam.interiorWrongPercent) + " wrong",
                "cascade_accuracy.h: screen pixels next to another cascade's");
}

}  // namespace shadowlab::hardcases
