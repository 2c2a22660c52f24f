// The light's volume drawn over the main view: lines land where the volume's corners project, parts behind the
// scene are fainter than parts in front, nothing else of the picture changes, and a failed frame draws nothing.
#include "gl_fixture.h"

#include "overlay/light_frustum_overlay.h"

namespace shadowlab::test {
namespace {

constexpr int kWidth = 480, kHeight = 360;
const glm::vec4 kMagenta{1.0f, 0.0f, 1.0f, 1.0f};

struct Projected {
    glm::dvec2 pixel;  // x right, y down
    double depth;      // window depth, clamped to [0,1] as the overlay's depth clamp does
};

Projected project(const FrameStats& stats, const glm::dvec3& originRelative) {
    const glm::dvec4 clip = stats.cameraViewProjection * glm::dvec4(originRelative, 1.0);
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    return {{(ndc.x * 0.5 + 0.5) * kWidth, (0.5 - ndc.y * 0.5) * kHeight}, std::clamp(ndc.z * 0.5 + 0.5, 0.0, 1.0)};
}

struct Rgb {
    int r, g, b;
};

Rgb pixel(const std::vector<std::uint8_t>& rgba, int x, int yDown) {
    const std::size_t i = (std::size_t(kHeight - 1 - yDown) * kWidth + x) * 4;
    return {rgba[i], rgba[i + 1], rgba[i + 2]};
}

// How far a pixel moved from `before` toward magenta: 0 = unchanged, 1 = pure magenta (by the green channel, which
// magenta takes to 0, and red/blue, which it takes to 255).
double magentaShare(Rgb before, Rgb after) {
    const double room = (255 - before.r) + before.g + (255 - before.b);
    if (room < 30) return 0.0;  // already close to magenta: cannot tell
    return ((after.r - before.r) + (before.g - after.g) + (after.b - before.b)) / room;
}

class LightFrustumOverlayTest : public GlTest {
protected:
    void render(const Settings& settings) {
        renderer_ = std::make_unique<Renderer>();
        ASSERT_EQ(target_.resize(kWidth, kHeight), "");
        stats_ = renderer_->render(scene_, settings, cameraFor(settings.camera, scene_, double(target_.width()) / target_.height()), target_);
        ASSERT_TRUE(stats_.ok) << stats_.error;
        before_ = target_.readColor();
        depth_.resize(std::size_t(kWidth) * kHeight);
        glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer());
        glReadPixels(0, 0, kWidth, kHeight, GL_DEPTH_COMPONENT, GL_FLOAT, depth_.data());
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    float sceneDepth(int x, int yDown) const { return depth_[std::size_t(kHeight - 1 - yDown) * kWidth + x]; }

    Scene scene_ = loadBuiltin("textbook");
    std::unique_ptr<Renderer> renderer_;
    RenderTarget target_;
    FrameStats stats_;
    std::vector<std::uint8_t> before_;
    std::vector<float> depth_;
};

// Far enough back that the whole box is in view; the light's direction line runs under the floor for a stretch.
Settings farView() {
    Settings settings = loadShippedPreset("default");
    settings.camera.autoFrame = false;
    settings.camera.position = {44.0f, 30.0f, 58.0f};
    settings.camera.target = {0.0f, 0.0f, 0.0f};
    return settings;
}

// Points along every drawn line, classified by the view's depth buffer over the 3x3 pixels around them (a margin of
// 1e-6: this far-away camera packs the scene into depths 0.99996..0.99999), with the strongest overlay colour there.
struct LineSamples {
    std::vector<double> inFront, hidden;  // magentaShare per sample
};

class LineSampler {
public:
    LineSampler(const FrameStats& stats, const std::vector<float>& depth) : stats_(stats), depth_(depth) {}
    LineSamples sample(const std::vector<std::uint8_t>& before, const std::vector<std::uint8_t>& after) const {
        LineSamples out;
        const std::vector<glm::dvec3> lines = lightVolumeLines(stats_.light);
        for (std::size_t i = 0; i + 1 < lines.size(); i += 2) {
            for (int k = 1; k < 100; ++k) {
                const Projected p = project(stats_, glm::mix(lines[i], lines[i + 1], k / 100.0));
                const int x = int(p.pixel.x), y = int(p.pixel.y);
                if (x < 1 || y < 1 || x >= kWidth - 1 || y >= kHeight - 1) continue;
                bool allFront = true, allHidden = true;
                double best = 0.0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const float scene = depth_[std::size_t(kHeight - 1 - (y + dy)) * kWidth + (x + dx)];
                        allFront = allFront && (p.depth <= scene - 1e-6 || scene >= 1.0f);  // 1: background
                        allHidden = allHidden && p.depth > scene + 1e-6;
                        best = std::max(best, magentaShare(pixel(before, x + dx, y + dy), pixel(after, x + dx, y + dy)));
                    }
                if (allFront) out.inFront.push_back(best);
                if (allHidden) out.hidden.push_back(best);
            }
        }
        return out;
    }

private:
    const FrameStats& stats_;
    const std::vector<float>& depth_;
};

double shareWithin(const std::vector<double>& values, double lo, double hi) {
    if (values.empty()) return 0.0;
    return double(std::count_if(values.begin(), values.end(), [&](double v) { return v >= lo && v <= hi; })) /
           double(values.size());
}

TEST_F(LightFrustumOverlayTest, DirectionalBoxLinesAppearWhereTheyProjectFainterWhenHidden) {
    render(farView());
    LightFrustumOverlay overlay;
    ASSERT_EQ(overlay.draw(stats_, target_, {kMagenta, 0.3f}), "");
    const std::vector<std::uint8_t> after = target_.readColor();
    saveView(View{kWidth, kHeight, after, stats_}, "light_frustum_overlay_directional");

    // All eight corners of the box are in this view, each with a line through it.
    for (const glm::dvec3& corner : lightVolumeCorners(stats_.light)) {
        const Projected p = project(stats_, corner);
        const int x = int(p.pixel.x), y = int(p.pixel.y);
        ASSERT_TRUE(x >= 1 && y >= 1 && x < kWidth - 1 && y < kHeight - 1) << x << "," << y;
        double best = 0.0;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                best = std::max(best, magentaShare(pixel(before_, x + dx, y + dy), pixel(after, x + dx, y + dy)));
        EXPECT_GT(best, 0.95) << "corner at " << x << "," << y;
    }
    const LineSamples samples = LineSampler(stats_, depth_).sample(before_, after);
    ASSERT_GE(samples.inFront.size(), 500u);
    ASSERT_GE(samples.hidden.size(), 10u);  // the direction line under the floor
    EXPECT_GE(shareWithin(samples.inFront, 0.95, 1.01), 0.97);
    EXPECT_GE(shareWithin(samples.hidden, 0.2, 0.45), 0.9);  // drawn at the hidden parts' opacity

    // Only thin lines: most of the picture is untouched.
    long changed = 0;
    for (std::size_t i = 0; i < after.size(); i += 4) changed += after[i + 1] != before_[i + 1];
    EXPECT_GT(changed, 500);
    EXPECT_LT(changed, long(kWidth) * kHeight / 20);
}

TEST_F(LightFrustumOverlayTest, HiddenAlphaZeroDrawsOnlyTheVisibleParts) {
    render(farView());
    LightFrustumOverlay overlay;
    ASSERT_EQ(overlay.draw(stats_, target_, {kMagenta, 0.0f}), "");
    const LineSamples samples = LineSampler(stats_, depth_).sample(before_, target_.readColor());
    ASSERT_GE(samples.hidden.size(), 10u);
    EXPECT_GE(shareWithin(samples.hidden, -0.01, 0.01), 0.9);  // (a few lie within a pixel of a visible line)
    EXPECT_GE(shareWithin(samples.inFront, 0.95, 1.01), 0.97);
}

TEST_F(LightFrustumOverlayTest, SpotPyramidStartsAtTheLight) {
    Settings settings = loadShippedPreset("default");
    settings.lights[0].type = LightType::Spot;
    settings.lights[0].position = {3.0f, 6.0f, 2.0f};
    settings.lights[0].direction = {-0.4f, -1.0f, -0.3f};
    render(settings);
    LightFrustumOverlay overlay;
    ASSERT_EQ(overlay.draw(stats_, target_, {kMagenta, 0.3f}), "");
    const std::vector<std::uint8_t> after = target_.readColor();
    saveView(View{kWidth, kHeight, after, stats_}, "light_frustum_overlay_spot");
    const Projected apex = project(stats_, glm::dvec3(settings.lights[0].position) - stats_.renderOrigin);
    const int x = int(apex.pixel.x), y = int(apex.pixel.y);
    ASSERT_TRUE(x >= 1 && y >= 1 && x < kWidth - 1 && y < kHeight - 1) << "light off screen";
    double best = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            best = std::max(best, magentaShare(pixel(before_, x + dx, y + dy), pixel(after, x + dx, y + dy)));
    EXPECT_GT(best, 0.95);
    // Five lines meet at the apex (four edges and the axis), the cone's circle adds 48 segments.
    EXPECT_EQ(lightVolumeLines(stats_.light).size(), std::size_t(2 * (8 + 5 + 48)));
}

TEST_F(LightFrustumOverlayTest, AFailedFrameDrawsNothingAndSaysWhy) {
    render(loadShippedPreset("default"));
    FrameStats failed;
    failed.error = "shadow.resolution: 0 is outside [16, 16384]";
    LightFrustumOverlay overlay;
    const std::string error = overlay.draw(failed, target_);
    EXPECT_NE(error.find("not rendered"), std::string::npos) << error;
    EXPECT_NE(error.find("shadow.resolution"), std::string::npos) << error;
    EXPECT_EQ(target_.readColor(), before_);
}

}  // namespace
}  // namespace shadowlab::test
