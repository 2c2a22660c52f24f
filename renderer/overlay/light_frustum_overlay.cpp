#include "overlay/light_frustum_overlay.h"

#include "gl/program.h"
#include "shading/cascade_tints.h"
#include "views/cascade_views.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include <cmath>

namespace shadowlab {

namespace {

constexpr int kConeSegments = 48;

glm::dvec3 unproject(const glm::dmat4& inverse, const glm::dvec3& ndc) {
    const glm::dvec4 p = inverse * glm::dvec4(ndc, 1.0);
    return glm::dvec3(p) / p.w;
}

void addLine(std::vector<glm::dvec3>& lines, const glm::dvec3& a, const glm::dvec3& b) {
    lines.push_back(a);
    lines.push_back(b);
}

}  // namespace

std::vector<glm::dvec3> lightVolumeCorners(const LightSpace& light) {
    const glm::dmat4 inverse = glm::inverse(light.volumeViewProjection());
    const double xy[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    std::vector<glm::dvec3> corners;
    for (double z : {-1.0, 1.0})
        for (const auto& c : xy) corners.push_back(unproject(inverse, {c[0], c[1], z}));
    return corners;
}

std::vector<LightSpace> lightVolumes(const FrameStats& stats, std::size_t light) {
    std::vector<LightSpace> volumes;
    for (const ShadowViewStats& view : stats.views)
        if (view.hasView && view.light == light) volumes.push_back(view.space);
    return volumes;
}

std::vector<glm::dvec3> lightVolumeLines(const LightSpace& light) {
    const std::vector<glm::dvec3> c = lightVolumeCorners(light);
    std::vector<glm::dvec3> lines;
    for (int i = 0; i < 4; ++i) {
        addLine(lines, c[i], c[(i + 1) % 4]);          // near face
        addLine(lines, c[4 + i], c[4 + (i + 1) % 4]);  // far face
    }
    const glm::dmat4 lightToWorld = glm::inverse(light.view);
    const glm::dvec3 farCenter = (c[4] + c[5] + c[6] + c[7]) * 0.25;
    if (light.perspective) {
        // The pyramid from the light itself (through the near corners) and the cone's circle on the far plane.
        const glm::dvec3 apex = glm::dvec3(lightToWorld * glm::dvec4(0.0, 0.0, 0.0, 1.0));
        for (int i = 0; i < 4; ++i) addLine(lines, apex, c[4 + i]);
        addLine(lines, apex, farCenter);
        const double radius = light.farPlane * light.tanHalfFov;
        glm::dvec3 previous{};
        for (int i = 0; i <= kConeSegments; ++i) {
            const double a = 2.0 * M_PI * i / kConeSegments;
            const glm::dvec3 p = glm::dvec3(
                lightToWorld * glm::dvec4(radius * std::cos(a), radius * std::sin(a), -light.farPlane, 1.0));
            if (i > 0) addLine(lines, previous, p);
            previous = p;
        }
    } else {
        // The box's side edges, and the light's direction through its centre.
        for (int i = 0; i < 4; ++i) addLine(lines, c[i], c[4 + i]);
        addLine(lines, (c[0] + c[1] + c[2] + c[3]) * 0.25, farCenter);
    }
    return lines;
}

std::vector<glm::dvec3> cascadeSliceLines(const CascadeSlice& slice) {
    const std::array<glm::dvec3, 8> c = sliceCorners(slice.camera, slice.nearDepth, slice.farDepth);
    const int ring[4] = {0, 1, 3, 2};  // around a face (sliceCorners' order)
    std::vector<glm::dvec3> lines;
    for (int i = 0; i < 4; ++i) {
        const int a = ring[i], b = ring[(i + 1) % 4];
        addLine(lines, c[std::size_t(a)], c[std::size_t(b)]);          // near face
        addLine(lines, c[std::size_t(4 + a)], c[std::size_t(4 + b)]);  // far face
        addLine(lines, c[std::size_t(a)], c[std::size_t(4 + a)]);      // side edges
    }
    return lines;
}

std::vector<OverlayLines> lightOverlayLines(const FrameStats& stats, std::size_t light, const glm::vec4& color,
                                            bool slices) {
    std::vector<OverlayLines> out;
    for (const ShadowViewStats& view : stats.views) {
        if (!view.hasView || view.light != light) continue;
        if (view.kind != ShadowViewKind::Cascade) {
            out.push_back({lightVolumeLines(view.space), color});
            continue;
        }
        const glm::vec4 tint(cascadeTint(view.index), 1.0f);
        out.push_back({lightVolumeLines(view.space), tint});
        if (slices) out.push_back({cascadeSliceLines(view.slice), tint});
    }
    return out;
}

LightFrustumOverlay::LightFrustumOverlay()
    : program_(gl::buildProgram({{GL_VERTEX_SHADER, "overlay_lines.vert.glsl"},
                                 {GL_FRAGMENT_SHADER, "overlay_lines.frag.glsl"}},
                                {})),
      vertexArray_(gl::createVertexArray()),
      vertices_(gl::createBuffer()) {
    viewProjectionLocation_ = glGetUniformLocation(program_.id(), "uViewProjection");
    colorLocation_ = glGetUniformLocation(program_.id(), "uColor");
    glVertexArrayVertexBuffer(vertexArray_.id(), 0, vertices_.id(), 0, sizeof(glm::vec3));
    glEnableVertexArrayAttrib(vertexArray_.id(), 0);
    glVertexArrayAttribFormat(vertexArray_.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vertexArray_.id(), 0, 0);
}

std::string LightFrustumOverlay::draw(const FrameStats& stats, RenderTarget& target, const FrustumOverlayStyle& style) {
    return draw(stats, {stats.light}, target, style);
}

std::string LightFrustumOverlay::draw(const FrameStats& stats, const std::vector<LightSpace>& volumes,
                                      RenderTarget& target, const FrustumOverlayStyle& style) {
    std::vector<OverlayLines> lines;  // a matrix that is not finite gives points that are not: draw refuses them
    for (const LightSpace& volume : volumes) lines.push_back({lightVolumeLines(volume), style.color});
    return draw(stats, lines, target, style);
}

std::string LightFrustumOverlay::draw(const FrameStats& stats, const std::vector<OverlayLines>& lines,
                                      RenderTarget& target, const FrustumOverlayStyle& style) {
    if (!stats.ok) return "no light volume to draw: the frame was not rendered (" + stats.error + ")";
    if (!allFinite(stats.cameraViewProjection))
        return "no light volume to draw: the camera's matrices are not finite";
    std::vector<glm::vec3> points;
    std::vector<GLint> firsts;
    for (const OverlayLines& group : lines) {
        firsts.push_back(GLint(points.size()));
        for (const glm::dvec3& p : group.points) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                return "no light volume to draw: the light's matrices are not finite";
            points.emplace_back(p);
        }
    }
    if (target.width() < 1) return "no light volume to draw: the view has no size";
    if (points.empty()) return {};  // a light without shadow views has no volume
    firsts.push_back(GLint(points.size()));
    glNamedBufferData(vertices_.id(), GLsizeiptr(points.size() * sizeof(glm::vec3)), points.data(), GL_STREAM_DRAW);
    // Each group in its colour; `alpha` scales the colours' opacity.
    const auto drawGroups = [&](float alpha) {
        for (std::size_t g = 0; g < lines.size(); ++g) {
            const glm::vec4& c = lines[g].color;
            glUniform4f(colorLocation_, c.r, c.g, c.b, c.a * alpha);
            glDrawArrays(GL_LINES, firsts[g], firsts[g + 1] - firsts[g]);
        }
    };

    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer());
    glViewport(0, 0, target.width(), target.height());
    glUseProgram(program_.id());
    glBindVertexArray(vertexArray_.id());
    glUniformMatrix4fv(viewProjectionLocation_, 1, GL_FALSE, glm::value_ptr(glm::mat4(stats.cameraViewProjection)));

    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    // The volume usually reaches past the camera's far plane (it encloses the scene's bounding sphere): clamp
    // depth instead of clipping, so those parts are drawn (behind everything) rather than cut off.
    glEnable(GL_DEPTH_CLAMP);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    if (style.hiddenAlpha > 0.0f) {
        glDepthFunc(GL_GREATER);  // behind the scene's surfaces
        drawGroups(style.hiddenAlpha);
    }
    glDepthFunc(GL_LEQUAL);
    drawGroups(1.0f);

    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_CLAMP);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glBindVertexArray(0);
    glUseProgram(0);
    return {};
}

}  // namespace shadowlab
