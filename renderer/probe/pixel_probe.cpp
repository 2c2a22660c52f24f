#include "probe/pixel_probe.h"

#include "probe/moment_probe.h"

#include "accuracy/light_isolation.h"
#include "settings/settings_fields.h"

#include "shading/filter_taps.h"
#include "shading/filters/cube_face_frame.h"
#include "shading/filters/filter_technique.h"
#include "views/view_select.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace shadowlab {

std::optional<int> addressTexel(int i, int resolution, AddressMode mode) {
    switch (mode) {
        case AddressMode::Wrap: return ((i % resolution) + resolution) % resolution;
        case AddressMode::ClampToEdge: return std::clamp(i, 0, resolution - 1);
        case AddressMode::ClampToBorder:
            if (i < 0 || i >= resolution) return std::nullopt;
            return i;
    }
    return i;
}

namespace {

// Window-space texture coordinate (x, y in [0, 1]) and depth of a render-origin-relative point in the view's depth
// convention, as toLightTexture in shaders/shadow/light_data.glsl computes it (there in float).
glm::dvec3 toLightTexture(const LightSpace& light, const glm::dvec3& p) {
    return light.textureOf(light.viewProjection() * glm::dvec4(p, 1.0));
}

// Float rounding the GPU's lookup carries: its position is interpolated and transformed in float. Returns the
// uncertainty of the receiver's depth (depth units) and of its texel coordinate (texels), from the gradients of
// toLightTexture at the lookup and a position error of a few float steps of its largest coordinate.
std::pair<double, double> lookupUncertainty(const LightSpace& light, const glm::dvec3& lookup, int resolution) {
    const double scale = std::max({std::abs(lookup.x), std::abs(lookup.y), std::abs(lookup.z), 1e-6});
    const double positionError = scale * std::ldexp(1.0, -20);  // 16 float steps
    const double h = std::max(scale * 1e-6, 1e-9);
    double depthGradient = 0.0, texelGradient = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 e(0.0);
        e[axis] = h;
        const glm::dvec3 d = (toLightTexture(light, lookup + e) - toLightTexture(light, lookup - e)) / (2.0 * h);
        depthGradient += d.z * d.z;
        texelGradient = std::max(texelGradient, std::max(std::abs(d.x), std::abs(d.y)));
    }
    const double depthEps = positionError * std::sqrt(depthGradient) + std::ldexp(1.0, -21);
    const double texelEps = positionError * texelGradient * resolution * std::sqrt(3.0) +
                            resolution * std::ldexp(1.0, -21);
    return {depthEps, texelEps};
}

}  // namespace

std::vector<float> readShadowMapRect(const ShadowMap& map, int x0, int y0, int w, int h) {
    if (!map.valid() || w < 1 || h < 1) return std::vector<float>(std::size_t(std::max(w, 0)) * std::size_t(std::max(h, 0)));
    return map.readDepthRect(x0, y0, w, h);
}

std::string PixelProbe::capture(Renderer& renderer, const Scene& scene, const Settings& settings,
                                const Camera& camera, int width, int height, std::size_t lightIndex) {
    renderer_ = nullptr;
    // One light: the GPU's S at a pixel is then that light's alone, the one the CPU side recomputes.
    if (std::string error = singleLightError(settings, scene, "the pixel probe"); !error.empty()) return error;
    Settings shadowView = settings;
    shadowView.view = ViewMode::Shadow;  // the main pass writes S itself, into a float target
    if (std::string error = target_.resize(width, height, GL_RGBA32F); !error.empty()) return error;
    FrameStats stats = renderer.render(scene, shadowView, camera, target_);
    if (!stats.ok) return stats.error;
    const std::size_t count = std::size_t(width) * std::size_t(height);
    std::vector<float> rgba(count * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(target_.colorTexture(), 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)),
                      rgba.data());
    shadow_.assign(count, 0.0f);
    for (int row = 0; row < height; ++row)
        for (int x = 0; x < width; ++x)
            shadow_[std::size_t(row) * std::size_t(width) + std::size_t(x)] =
                rgba[(std::size_t(height - 1 - row) * std::size_t(width) + std::size_t(x)) * 4];
    if (std::string error = gbuffer_.render(*renderer.gpuScene(), stats.cameraViewProjection, width, height,
                                            camera.position - stats.renderOrigin, samples_);
        !error.empty())
        return error;
    glUseProgram(0);  // a host that saves and restores the current program (ImGui's backend) never holds ours
    renderer_ = &renderer;
    cubeFaces_.clear();
    scene_ = &scene;
    settings_ = settings;
    lightIndex_ = lightIndex;
    camera_ = camera;
    stats_ = std::move(stats);
    // The probed light's views (capture holds one light: the first that has a view), their stats beside them.
    views_.clear();
    viewStats_.clear();
    for (std::size_t v = 0; v < stats_.views.size(); ++v)
        if (stats_.views[v].hasView && (viewStats_.empty() || stats_.views[v].light == stats_.views[viewStats_[0]].light))
            viewStats_.push_back(v);
    if (!viewStats_.empty()) views_ = frameViewsOf(stats_, stats_.views[viewStats_[0]].light);
    for (ShadowView& v : views_) v.light = lightIndex;  // named as the caller's light (the frame holds it alone)
    return {};
}

struct PixelProbe::Surface {
    glm::dvec3 p{0.0};              // render-origin-relative
    glm::dvec3 v[3];                // its triangle, render-origin-relative
    glm::dvec3 shadingNormal{0.0};  // flipped on back faces
};

PixelProbeReport PixelProbe::at(int x, int y, const AccuracyReport* measured, std::optional<std::size_t> view) const {
    PixelProbeReport r;
    r.x = x;
    r.y = y;
    r.width = samples_.width;
    r.height = samples_.height;
    if (!renderer_) {
        r.error = "no frame captured to probe";
        return r;
    }
    if (x < 0 || y < 0 || x >= samples_.width || y >= samples_.height) {
        r.error = "pixel " + std::to_string(x) + "," + std::to_string(y) + " is outside the " +
                  std::to_string(samples_.width) + "x" + std::to_string(samples_.height) + " view";
        return r;
    }
    const std::size_t i = std::size_t(y) * std::size_t(samples_.width) + std::size_t(x);
    if (samples_.draw[i] < 0 || samples_.triangle[i] < 0) {
        r.error = "pixel " + std::to_string(x) + "," + std::to_string(y) + " shows no surface (background)";
        return r;
    }
    if (!samples_.finite[i]) {
        r.error = "pixel " + std::to_string(x) + "," + std::to_string(y) + ": the surface point is not finite";
        return r;
    }
    if (views_.empty()) {
        r.error = "the light casts no shadow: nothing to probe";
        return r;
    }
    if (view && *view >= views_.size()) {
        r.error = "view " + std::to_string(*view) + " of a light with " + std::to_string(views_.size()) + " view(s)";
        return r;
    }
    const Scene& scene = *scene_;
    r.light = lightIndex_;
    r.lightType = settings_.lights.front().type;
    const glm::dvec3 origin = stats_.renderOrigin;
    Surface s;
    s.p = samples_.point[i];
    const glm::dvec3& p = s.p;

    // The surface: the G-buffer's exact point, its triangle, and the main pass's interpolated normal.
    r.world = p + origin;
    r.geometricNormal = samples_.normal[i];
    r.instance = samples_.instance[i];
    r.triangle = samples_.triangle[i];
    const Instance& instance = scene.instances[std::size_t(r.instance)];
    const Mesh& mesh = scene.meshes[std::size_t(instance.mesh)];
    r.meshName = mesh.name;
    const glm::dmat4 model = glm::dmat4(instance.transform);
    glm::dvec3 n[3];
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t index = mesh.indices[std::size_t(r.triangle) * 3 + std::size_t(k)];
        s.v[k] = glm::dvec3(model * glm::dvec4(glm::dvec3(mesh.positions[index]), 1.0)) - origin;
        n[k] = index < mesh.normals.size() ? glm::dvec3(mesh.normals[index]) : glm::dvec3(0.0);
    }
    const glm::dvec3 cross = glm::cross(s.v[1] - s.v[0], s.v[2] - s.v[0]);
    const double area2 = glm::dot(cross, cross);
    glm::dvec3 bary(1.0 / 3.0);
    if (area2 > 0.0) {
        bary.x = glm::dot(glm::cross(s.v[1] - p, s.v[2] - p), cross) / area2;
        bary.y = glm::dot(glm::cross(s.v[2] - p, s.v[0] - p), cross) / area2;
        bary.z = 1.0 - bary.x - bary.y;
    }
    const GpuDraw& draw = renderer_->gpuScene()->draws()[std::size_t(samples_.draw[i])];
    const glm::dvec3 eye = camera_.position - origin;
    // gl_FrontFacing: counter-clockwise in the window, clockwise for mirrored instances (face_culling.cpp).
    r.frontFacing = (glm::dot(cross, eye - p) > 0.0) != draw.mirrored;
    glm::dvec3 shading = glm::dmat3(draw.normalMatrix) * (bary.x * n[0] + bary.y * n[1] + bary.z * n[2]);
    shading = glm::length(shading) > 0.0 ? glm::normalize(shading) : r.geometricNormal;
    r.shadingNormal = r.frontFacing ? shading : -shading;
    s.shadingNormal = r.shadingNormal;

    // The view the GPU reads (views/view_select.h: a point light's face follows the lookup, chosen in lookupIn; a
    // cascade by the point's depth, with its blend partner), or the one asked for.
    const ViewChoice choice = selectView(views_, p);
    const bool cascaded = views_.front().kind == ShadowViewKind::Cascade;
    const bool beyond = cascaded && choice.view < 0;  // beyond the shadow distance: the GPU's S is 1
    const std::size_t own = view ? *view : beyond ? views_.size() - 1 : std::size_t(std::max(choice.view, 0));
    r.viewCount = int(views_.size());
    r.viewChosen = view.has_value();
    lookupIn(r, own, view.has_value(), s);
    if (!r.error.empty()) return r;
    r.shadowView = r.shadowCpu;
    r.shadowGpu = double(shadow_[i]);
    const bool blends = cascaded && !beyond && choice.next >= 0 && choice.weight > 0.0;
    if (view && cascaded && (int(*view) != choice.view || blends)) {
        // Another cascade than the GPU's (alone) here: its lookup, not compared.
        r.compared = false;
        r.blendNote = beyond ? "beyond the shadow distance: the GPU's S is 1 (lit); " + r.cascade +
                                   "'s lookup is shown, not compared"
                    : "the GPU reads cascade:" + std::to_string(choice.view) +
                          (blends ? " and cascade:" + std::to_string(choice.next) : std::string()) +
                          " here; " + r.cascade + "'s lookup is shown, not compared";
    } else if (beyond) {
        r.blendNote = "beyond the shadow distance: the GPU's S is 1 (lit); the taps below are the last cascade's";
        r.shadowCpu = r.shadowLow = r.shadowHigh = 1.0;
    } else if (blends && !view) {
        // The blend band: the GPU mixes the two cascades' S at the selection's weight, and so does the probe.
        PixelProbeReport next;
        next.x = r.x, next.y = r.y, next.width = r.width, next.height = r.height;
        lookupIn(next, std::size_t(choice.next), false, s);
        if (!next.error.empty()) {
            r.error = next.error;
            return r;
        }
        const double w = choice.weight;
        r.blendWeight = w;
        r.blendNote = "in the blend band: the GPU mixes " + r.cascade + " and " + next.cascade + ": S = (1 - " +
                      std::to_string(w) + ") x S(" + r.cascade + ") + " + std::to_string(w) + " x S(" + next.cascade +
                      ")";
        r.shadowCpu = (1.0 - w) * r.shadowView + w * next.shadowCpu;
        r.shadowLow = (1.0 - w) * r.shadowLow + w * next.shadowLow;
        r.shadowHigh = (1.0 - w) * r.shadowHigh + w * next.shadowHigh;
        r.tolerance = std::max(r.tolerance, next.tolerance);
        r.uncertainComparisons += next.uncertainComparisons;
        r.blend.push_back(std::move(next));
    } else if (view && views_.front().kind == ShadowViewKind::CubeFace && r.face != cubeFaceOf(
                   r.lookupWorld - origin - views_.front().space.position)) {
        r.compared = false;
        r.blendNote = std::string("the GPU reads cube face ") +
                      cubeFaces()[std::size_t(cubeFaceOf(r.lookupWorld - origin - views_.front().space.position))].name +
                      " here; " + cubeFaces()[std::size_t(r.face)].name + "'s lookup is shown, not compared";
    }
    r.agrees = !r.compared ||
               (r.shadowGpu >= r.shadowLow - r.tolerance && r.shadowGpu <= r.shadowHigh + r.tolerance);

    if (measured && measured->ok && measured->width == r.width && measured->height == r.height &&
        measured->pixelClass.size() > i) {
        r.measured = true;
        r.exact = measured->pixelClass[i];
        r.cause = measured->pixelCause[i];
        r.measuredShadow = measured->pixelShadow[i];
    }
    r.ok = true;
    return r;
}

float PixelProbe::cubeDepth(int face, int x, int y) const {
    if (cubeFaces_.empty()) cubeFaces_.resize(6);
    std::vector<float>& texels = cubeFaces_[std::size_t(face)];
    int res = 0;
    for (std::size_t v : viewStats_) {
        const ShadowViewStats& view = stats_.views[v];
        if (view.face != face) continue;
        res = view.resolution;
        if (texels.empty())
            if (const ShadowMap* map = renderer_->viewMap({view.light, view.kind, view.index}))
                texels = readShadowMapRect(*map, 0, 0, res, res);
    }
    if (texels.size() != std::size_t(res) * std::size_t(res) || res == 0) return 1.0f;
    return texels[std::size_t(y) * std::size_t(res) + std::size_t(x)];
}

void PixelProbe::lookupIn(PixelProbeReport& r, std::size_t viewIndex, bool forced, const Surface& s,
                          const OwnLookupResult* search) const {
    const glm::dvec3& p = s.p;
    const glm::dvec3 origin = stats_.renderOrigin;
    const ShadowViewStats* view = &stats_.views[viewStats_[viewIndex]];
    const bool cube = view->face >= 0;
    const ShadowMap* faceMap = renderer_->viewMap({view->light, view->kind, view->index});
    r.face = view->face;
    r.viewName = view->name;
    r.cascade = view->kind == ShadowViewKind::Cascade ? viewSuffix(view->kind, view->index) : std::string();
    const LightSpace* space = &view->space;
    const int res = view->resolution;
    r.resolution = res;
    r.format = view->format;
    r.filter = settings_.filter;
    r.addressMode = settings_.sampler.addressMode;

    // The lookup: moved along the normal by normalOffset texels' world size, as main.frag.glsl does (a point light:
    // the texel's size at the point's distance along its own face's axis, the shader's max(|x|, |y|, |z|); a cascade:
    // its own texel).
    const LightSettings& probed = settings_.lights.front();  // capture() holds exactly the probed light
    const glm::dvec3 fromLight = p - space->position;
    const double texelWorld =
        cube ? 2.0 * space->tanHalfFov / space->resolution *
                   std::max({std::abs(fromLight.x), std::abs(fromLight.y), std::abs(fromLight.z)})
        : space->perspective ? 2.0 * space->tanHalfFov / space->resolution * glm::dot(fromLight, space->direction)
                             : space->texelWorldSize;
    const double offsetWorld = probed.shadow.normalOffset > 0.0f ? probed.shadow.normalOffset * texelWorld : 0.0;
    const glm::dvec3 lookup = p + s.shadingNormal * offsetWorld;
    // The GPU picks the cube face of the lookup (after the normal offset), not of the point.
    if (cube && !forced) {
        const int v = selectView(views_, lookup).view;
        view = &stats_.views[viewStats_[std::size_t(std::max(v, 0))]];
        faceMap = renderer_->viewMap({view->light, view->kind, view->index});
        space = &view->space;
        r.face = view->face;
        r.viewName = view->name;
    }
    const glm::dvec3* v = s.v;
    const LightSpace& light = *space;
    r.lookupWorld = lookup + origin;
    r.lightView = glm::dvec3(light.view * glm::dvec4(lookup, 1.0));
    r.lightTexture = toLightTexture(light, lookup);
    r.texelCoord = glm::dvec2(r.lightTexture) * double(res);
    r.texel = glm::ivec2(int(std::floor(r.texelCoord.x)), int(std::floor(r.texelCoord.y)));
    r.insideMap = r.lightTexture.x >= 0.0 && r.lightTexture.x <= 1.0 && r.lightTexture.y >= 0.0 &&
                  r.lightTexture.y <= 1.0;
    if (light.perspective && !cube) {  // a spot's cone; a cube face has none
        const glm::dvec3 toLight = glm::normalize(light.position - p);
        r.inCone = glm::dot(-toLight, light.direction) >= std::cos(std::atan(light.tanHalfFov));
    }
    r.reversedZ = light.reversedZ;
    r.receiverDepth = light.clampToFar(r.lightTexture.z);
    if (r.format != DepthFormat::D32F) r.receiverDepth = std::clamp(r.receiverDepth, 0.0, 1.0);  // fixed point clamps
    const auto [depthEps, texelEps] = lookupUncertainty(light, lookup, res);
    r.depthUncertainty = depthEps;

    // The surface's triangle in the map (x, y in texels, z stored depth): its slope sets the bias it gets as a caster,
    // its plane the receiver-plane term (main.frag.glsl takes the same plane from screen-space derivatives).
    glm::dvec3 window[3];
    for (int k = 0; k < 3; ++k) {
        const glm::dvec3 t = toLightTexture(light, v[k]);
        window[k] = {t.x * res, t.y * res, std::clamp(t.z, 0.0, 1.0)};
    }
    glm::dvec2 plane(0.0);  // d(depth)/d(texel) when receiver-plane bias applies
    const ShadowMapSettings& shadow = probed.shadow;
    if (shadow.receiverPlaneBias && filterTechnique(r.filter.kind).receiverPlane && light.cubeFace < 0) {
        glm::dvec3 unclamped[3];
        for (int k = 0; k < 3; ++k) unclamped[k] = {window[k].x, window[k].y, toLightTexture(light, v[k]).z};
        if (const std::optional<glm::dvec2> g = windowDepthGradient(unclamped[0], unclamped[1], unclamped[2])) {
            // The shader's clamp: at most 8 texel-world-sizes of depth along the light per texel across.
            const glm::dvec3 ray = light.perspective ? glm::normalize(lookup - light.position) : light.direction;
            const double limit = 8.0 * std::abs(toLightTexture(light, lookup + ray * texelWorld).z - r.lightTexture.z);
            const double length = glm::length(*g);
            plane = length > limit ? *g * (limit / length) : *g;
        }
    }
    r.receiverPlane = plane;

    // The taps: which texels each compares, read back from the map in one rectangle.
    const double texelStep = double(1.0f / float(res));  // uShadowTexel
    struct Candidate {
        std::vector<std::pair<int, double>> xs, ys;  // texel index (before addressing) and weight
        std::vector<int> altXs, altYs;                // a nearest tap's other possible texel under rounding
    };
    std::vector<Candidate> candidates;
    int minX = res, minY = res, maxX = -1, maxY = -1;
    auto note = [&](int tx, int ty) {
        const std::optional<int> ax = addressTexel(tx, res, r.addressMode), ay = addressTexel(ty, res, r.addressMode);
        if (!ax || !ay) return;
        minX = std::min(minX, *ax), maxX = std::max(maxX, *ax), minY = std::min(minY, *ay), maxY = std::max(maxY, *ay);
    };
    // A moments technique reads one bilinear lookup of moments instead of comparing taps (probeMomentLookup below).
    const bool momentLookup = filterTechnique(r.filter.kind).moments != nullptr;
    std::vector<FilterTap> filterTapList = momentLookup ? std::vector<FilterTap>{} : filterTaps(settings_.filter);
    // A point light's taps of a technique with a lookup of its own: each one's direction from the light selects the
    // face it is compared in (cube_face_frame.h), as the GPU's shadowCube.
    struct CubeTap {
        glm::vec2 offset;
        glm::vec3 direction;
    };
    std::vector<CubeTap> cubeTaps;
    // A technique with a lookup of its own (PCSS) searches the map first; its mirror gives the taps it compares.
    if (const OwnLookup* own = filterTechnique(r.filter.kind).ownLookup; own && faceMap) {
        r.ownLookup = true;
        filterTapList = {{glm::dvec2(0.0), true}};  // beyond the map: one comparison, the address mode's answer
        if (r.insideMap) {
            OwnLookupInput in;
            in.tex = glm::vec2(r.lightTexture);
            in.receiver = float(r.receiverDepth);
            in.plane = glm::vec2(plane);
            in.resolution = res;
            in.reversedZ = light.reversedZ;
            in.perspective = light.perspective;
            in.nearPlane = float(light.nearPlane);
            in.farPlane = float(light.farPlane);
            const glm::dvec3 ray = light.perspective ? glm::normalize(lookup - light.position) : light.direction;
            // A point light's shader measures the receiver along its face's axis (its frame's `major`, in float);
            // a spot's from its depth (0).
            in.cube = cube;
            in.fromLight = glm::vec3(lookup) - glm::vec3(light.position);
            if (cube) in.distance = cubeFaceFrame(in.fromLight, 1.0f / float(res)).major;
            in.depthPerWorld = float(toLightTexture(light, lookup + ray).z - r.lightTexture.z);
            in.texelWorld = float(light.perspective ? 2.0 * light.tanHalfFov / res : light.texelWorldSize);
            in.lightSize = lightSpread(probed);
            in.pixel = glm::uvec2(unsigned(r.x), unsigned(r.height - 1 - r.y));
            in.depthEps = depthEps;
            in.texelEps = texelEps;
            // The search's texels, read back once around the lookup (its widest radius: the search's largest times
            // the disk's farthest tap, and a texel of rounding). A cube's taps read whole faces (cubeDepth).
            float farthest = 0.0f;
            for (const glm::vec2& unit : filterTechnique(r.filter.kind).unitTaps(settings_.filter))
                farthest = std::max(farthest, glm::length(unit));
            const int reach = cube ? 0 : int(std::ceil(settings_.filter.blockerSearchTexels * farthest)) + 2;
            const int cx = int(std::floor(r.texelCoord.x)), cy = int(std::floor(r.texelCoord.y));
            const int x0 = std::clamp(cx - reach, 0, res - 1), y0 = std::clamp(cy - reach, 0, res - 1);
            const int x1 = std::clamp(cx + reach, 0, res - 1), y1 = std::clamp(cy + reach, 0, res - 1);
            const std::vector<float> around = readShadowMapRect(*faceMap, x0, y0, x1 - x0 + 1, y1 - y0 + 1);
            in.storedDepth = [&](int face, int x, int y) {
                if (face >= 0) return cubeDepth(face, x, y);
                x = std::clamp(x, x0, x1), y = std::clamp(y, y0, y1);
                return around[std::size_t(y - y0) * std::size_t(x1 - x0 + 1) + std::size_t(x - x0)];
            };
            r.search = search ? *search : own->mirror(in, settings_.filter);
            filterTapList.clear();
            if (!cube)
                for (const glm::vec2& offset : r.search.taps) filterTapList.push_back({glm::dvec2(offset), true});
            for (std::size_t k = 0; k < r.search.directions.size(); ++k)
                cubeTaps.push_back({r.search.taps[k], r.search.directions[k]});
        }
    }
    for (const FilterTap& tap : filterTapList) {
        ProbeTap t;
        t.offsetTexels = tap.offsetTexels;
        t.bilinear = tap.bilinear;
        t.texelCoord = (glm::dvec2(r.lightTexture) + tap.offsetTexels * texelStep) * double(res);
        // A lookup inside the map keeps its taps half a texel inside its edge (shaders/shadow/lookup_2d.glsl).
        if (r.insideMap) t.texelCoord = glm::clamp(t.texelCoord, glm::dvec2(0.5), glm::dvec2(double(res) - 0.5));
        Candidate c;
        for (int axis = 0; axis < 2; ++axis) {
            auto& list = axis == 0 ? c.xs : c.ys;
            auto& alt = axis == 0 ? c.altXs : c.altYs;
            if (tap.bilinear) {
                const double u = t.texelCoord[axis] - 0.5;
                const double i0 = std::floor(u);
                list = {{int(i0), 1.0 - (u - i0)}, {int(i0) + 1, u - i0}};
            } else {
                const double i0 = std::floor(t.texelCoord[axis]);
                const double frac = t.texelCoord[axis] - i0;
                list = {{int(i0), 1.0}};
                if (frac < texelEps) alt.push_back(int(i0) - 1);
                if (1.0 - frac < texelEps) alt.push_back(int(i0) + 1);
            }
        }
        for (const auto& [tx, wx] : c.xs)
            for (const auto& [ty, wy] : c.ys) note(tx, ty);
        for (int tx : c.altXs) note(tx, c.ys[0].first);
        for (int ty : c.altYs) note(c.xs[0].first, ty);
        for (int tx : c.altXs)
            for (int ty : c.altYs) note(tx, ty);
        r.taps.push_back(std::move(t));
        candidates.push_back(std::move(c));
    }
    const int rectW = maxX >= minX ? maxX - minX + 1 : 0, rectH = maxY >= minY ? maxY - minY + 1 : 0;
    if (!faceMap) {
        r.error = "no shadow map for " + view->name;
        return;
    }
    const std::vector<float> stored = readShadowMapRect(*faceMap, minX, minY, rectW, rectH);
    auto compare = [&](int tx, int ty, double weight, double receiver, double eps) {
        ProbeTexel texel;
        texel.weight = weight;
        const std::optional<int> ax = addressTexel(tx, res, r.addressMode), ay = addressTexel(ty, res, r.addressMode);
        texel.border = !ax || !ay;
        texel.texel = texel.border ? glm::ivec2(tx, ty) : glm::ivec2(*ax, *ay);
        texel.stored = texel.border ? double(conventionBorderDepth(settings_.sampler.borderDepth, light.reversedZ))
                                    : double(stored[std::size_t(*ay - minY) * std::size_t(rectW) + std::size_t(*ax - minX)]);
        texel.lit = light.litBy(receiver, texel.stored);
        texel.uncertain = std::abs(receiver - texel.stored) <= eps;
        return texel;
    };
    double sum = 0.0, low = 0.0, high = 0.0;
    bool anyBilinear = false;
    for (std::size_t k = 0; k < r.taps.size(); ++k) {
        ProbeTap& t = r.taps[k];
        const Candidate& c = candidates[k];
        t.value = t.low = t.high = 0.0;
        // Receiver-plane bias: a nearest tap compares the plane at its texel's centre, a bilinear one at the tap.
        // (to the tap actually read: after the clamp inside the map's edge, as shaders/shadow/lookup_2d.glsl does)
        const glm::dvec2 toPlane = t.bilinear ? t.texelCoord - r.texelCoord
                                              : glm::floor(t.texelCoord) + 0.5 - r.texelCoord;
        const double planeTerm = glm::dot(plane, toPlane);
        const double receiver = plane == glm::dvec2(0.0) ? r.receiverDepth : light.clampToFar(r.receiverDepth + planeTerm);
        // The GPU takes the plane from float differences of neighbouring pixels' positions: a relative error of its
        // own (2^-8 covers llvmpipe's on builtin:grazing, where a 20-unit DepthBias leaves that noise as acne).
        const double eps = depthEps + std::abs(planeTerm) * std::ldexp(1.0, -8);
        for (const auto& [tx, wx] : c.xs)
            for (const auto& [ty, wy] : c.ys) {
                ProbeTexel texel = compare(tx, ty, wx * wy, receiver, eps);
                t.value += texel.weight * (texel.lit ? 1.0 : 0.0);
                t.low += texel.weight * (texel.lit && !texel.uncertain ? 1.0 : 0.0);
                t.high += texel.weight * (texel.lit || texel.uncertain ? 1.0 : 0.0);
                r.uncertainComparisons += texel.uncertain ? 1 : 0;
                t.texels.push_back(texel);
            }
        // A nearest tap whose coordinate sits on a texel edge may read the neighbour instead.
        std::vector<std::pair<int, int>> others;
        for (int tx : c.altXs) others.emplace_back(tx, c.ys[0].first);
        for (int ty : c.altYs) others.emplace_back(c.xs[0].first, ty);
        for (int tx : c.altXs)
            for (int ty : c.altYs) others.emplace_back(tx, ty);
        for (const auto& [tx, ty] : others) {
            const ProbeTexel other = compare(tx, ty, 1.0, receiver, eps);
            t.low = std::min(t.low, other.lit && !other.uncertain ? 1.0 : 0.0);
            t.high = std::max(t.high, other.lit || other.uncertain ? 1.0 : 0.0);
            ++r.uncertainComparisons;
        }
        anyBilinear = anyBilinear || t.bilinear;
        sum += t.value, low += t.low, high += t.high;
    }
    // Cube taps (bilinear, seamless: the 2x2 texels beyond a face's edge are the neighbouring face's), each compared
    // with the receiver's depth in the face its direction selects, in float as cube_face_depth.glsl's faceDepth.
    const glm::vec3 fromLightF = glm::vec3(lookup) - glm::vec3(light.position);
    for (const CubeTap& cubeTap : cubeTaps) {
        ProbeTap t;
        t.offsetTexels = glm::dvec2(cubeTap.offset);
        t.bilinear = true;
        const CubeCoordinate c = cubeCoordinate(glm::dvec3(cubeTap.direction));
        t.texelCoord = c.st * double(res);
        const float faceReceiver =
            faceDepth(fromLightF, cubeTap.direction, float(light.nearPlane), float(light.farPlane), light.reversedZ);
        const double receiver = light.clampToFar(double(faceReceiver));
        const glm::dvec2 u = t.texelCoord - 0.5;
        const glm::dvec2 i0 = glm::floor(u), w1 = u - i0;
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                ProbeTexel texel;
                texel.weight = (dx ? w1.x : 1.0 - w1.x) * (dy ? w1.y : 1.0 - w1.y);
                const std::optional<CubeTexel> at = seamlessTexel(c.face, int(i0.x) + dx, int(i0.y) + dy, res);
                // A corner beyond both edges: the implementation's choice, so either answer.
                texel.uncertain = !at;
                texel.face = at ? at->face : c.face;
                texel.texel = at ? glm::ivec2(at->x, at->y) : glm::ivec2(int(i0.x) + dx, int(i0.y) + dy);
                texel.stored = at ? double(cubeDepth(at->face, at->x, at->y)) : receiver;
                texel.lit = light.litBy(receiver, texel.stored);
                texel.uncertain = texel.uncertain || std::abs(receiver - texel.stored) <= depthEps;
                t.value += texel.weight * (texel.lit ? 1.0 : 0.0);
                t.low += texel.weight * (texel.lit && !texel.uncertain ? 1.0 : 0.0);
                t.high += texel.weight * (texel.lit || texel.uncertain ? 1.0 : 0.0);
                r.uncertainComparisons += texel.uncertain ? 1 : 0;
                t.texels.push_back(texel);
            }
        anyBilinear = true;
        sum += t.value, low += t.low, high += t.high;
        r.taps.push_back(std::move(t));
    }
    const double taps = double(std::max<std::size_t>(r.taps.size(), 1));
    const double cone = r.inCone ? 1.0 : 0.0;
    r.shadowCpu = sum / taps * cone;
    r.shadowLow = low / taps * cone;
    r.shadowHigh = high / taps * cone;
    if (r.ownLookup && r.insideMap && r.taps.empty())  // the search found no blocker: lit, no filter
        r.shadowCpu = r.shadowLow = r.shadowHigh = cone;
    if (r.search.uncertain && !r.search.alternativesComplete) {  // a search test within rounding: any outcome
        r.shadowLow = 0.0;
        r.shadowHigh = cone;
    } else if (r.search.uncertain) {  // the GPU may reach one of the other outcomes listed: S within their bounds too
        for (const OwnLookupResult& other : r.search.alternatives) {
            PixelProbeReport alternative;
            alternative.x = r.x, alternative.y = r.y, alternative.width = r.width, alternative.height = r.height;
            lookupIn(alternative, viewIndex, forced, s, &other);
            r.shadowLow = std::min(r.shadowLow, alternative.shadowLow);
            r.shadowHigh = std::max(r.shadowHigh, alternative.shadowHigh);
        }
    }
    // Bilinear comparisons weigh texels with the GPU's sub-texel precision (8 bits in D3D's rules and llvmpipe).
    r.tolerance = (anyBilinear ? 2.0 / 256.0 : 0.0) + 1e-6;

    if (momentLookup)
        probeMomentLookup(r, *renderer_, {view->light, view->kind, view->index}, settings_,
                          {&light, lookup, fineDerivatives(stats_.cameraViewProjection, r.width, r.height, r.x, r.y, s.v)});

    // The bias this surface gets as a caster: its own triangle's slope in the map, r at its largest depth.
    const double slope = windowDepthSlope(window[0], window[1], window[2]);
    const double maxDepth = std::max({window[0].z, window[1].z, window[2].z});
    const double atDepth = std::clamp(r.receiverDepth, 0.0, 1.0);
    r.bias.depthSlope = std::max(slope, 0.0);
    r.bias.step = depthStepAt(r.format, maxDepth);
    r.bias.constant = biasTerm(light, double(shadow.depthBias) * r.bias.step, atDepth);
    r.bias.slope = biasTerm(light, double(shadow.slopeScaledDepthBias) * r.bias.depthSlope, atDepth);
    r.bias.clamp = biasTerm(light, double(shadow.depthBiasClamp), atDepth);
    r.bias.total = biasTerm(light, polygonOffsetDepth(shadow, r.format, maxDepth, r.bias.depthSlope), atDepth);
    r.bias.normalOffsetWorld = offsetWorld;
    r.bias.normalOffsetTexels = double(shadow.normalOffset);
}

}  // namespace shadowlab
