// The shadow-map picture from a real shadow map (textbook scene): auto contrast stretches over the written depths and
// is measured only when the map changed, "no caster" texels are blue, the texel grid appears only when zoomed in,
// hover (view position -> texel -> stored depth) agrees with the map read back, spot depth can be linearized.
#include "gl_fixture.h"

#include "overlay/shadow_map_view.h"

#include "image/depth_visualization.h"

namespace shadowlab::test {
namespace {

struct Rgb {
    int r, g, b;
};

class ShadowMapViewTest : public GlTest {
protected:
    void render(const Settings& settings) {
        if (!renderer_) renderer_ = std::make_unique<Renderer>();
        if (target_.width() == 0) ASSERT_EQ(target_.resize(160, 120), "");
        stats_ = renderer_->render(scene_, settings, cameraFor(settings.camera, scene_, double(target_.width()) / target_.height()), target_);
        ASSERT_TRUE(stats_.ok) << stats_.error;
        depth_ = map().readDepth();
    }
    const ShadowMap& map() const { return renderer_->shadowMap(); }
    float storedDepth(glm::ivec2 texel) const { return depth_[std::size_t(texel.y) * map().resolution() + texel.x]; }

    // Pixel of the view's picture at (x right, y down).
    static Rgb at(const ShadowMapView& view, int x, int yDown) {
        const std::vector<std::uint8_t> px = view.readPixels();
        const std::size_t i = (std::size_t(view.height() - 1 - yDown) * view.width() + x) * 4;
        return {px[i], px[i + 1], px[i + 2]};
    }
    static std::string save(const ShadowMapView& view, const std::string& name) {
        View picture{view.width(), view.height(), view.readPixels(), {}};
        return saveView(picture, name);
    }
    // Pixels with the grid's orange (red well above blue, green between).
    static long gridPixels(const ShadowMapView& view) {
        const std::vector<std::uint8_t> px = view.readPixels();
        long n = 0;
        for (std::size_t i = 0; i < px.size(); i += 4) n += px[i] > px[i + 2] + 80 && px[i + 1] > px[i + 2] + 20;
        return n;
    }

    Scene scene_ = loadBuiltin("textbook");
    std::unique_ptr<Renderer> renderer_;
    RenderTarget target_;
    FrameStats stats_;
    std::vector<float> depth_;
};

TEST_F(ShadowMapViewTest, AutoContrastStretchesOverTheWrittenDepthsAndShowsNoCasterInBlue) {
    render(loadShippedPreset("default"));
    ShadowMapView view;
    ShadowMapViewOptions options;  // auto, whole map
    ASSERT_EQ(view.render(map(), stats_.light, true, options, 512, 512), "");
    save(view, "shadow_map_view_auto");

    const DepthRange expected = writtenDepthRange(depth_);  // the CPU's answer
    EXPECT_TRUE(view.shownRange().anyCaster);
    EXPECT_EQ(view.shownRange().min, expected.min);
    EXPECT_EQ(view.shownRange().max, expected.max);
    EXPECT_FALSE(view.gridShown());

    // Every sampled pixel: blue where no caster wrote, else the grey its depth stretches to.
    const int res = map().resolution();
    int blue = 0, grey = 0;
    for (int y = 4; y < 512; y += 16)
        for (int x = 4; x < 512; x += 16) {
            const std::optional<glm::ivec2> texel = texelAtView(options.visible, x + 0.5, y + 0.5, 512, 512, res);
            ASSERT_TRUE(texel.has_value());
            const float d = storedDepth(*texel);
            const Rgb c = at(view, x, y);
            if (d >= 1.0f) {
                EXPECT_TRUE(c.b > c.r + 60 && c.b > c.g + 40) << x << "," << y;
                ++blue;
            } else {
                const double g = 255.0 * (d - expected.min) / (expected.max - expected.min);
                EXPECT_NEAR(c.r, g, 2.0) << x << "," << y;
                EXPECT_TRUE(c.r == c.g && c.g == c.b);
                ++grey;
            }
        }
    EXPECT_GT(blue, 50);
    EXPECT_GT(grey, 300);
}

TEST_F(ShadowMapViewTest, AutoRangeIsMeasuredOnlyWhenTheMapChanged) {
    Settings settings = loadShippedPreset("default");
    render(settings);
    ShadowMapView view;
    ASSERT_EQ(view.render(map(), stats_.light, true, {}, 256, 256), "");
    const ShownDepthRange first = view.shownRange();

    settings.lights[0].direction = {0.5f, -1.0f, 0.1f};  // a different map
    render(settings);
    ASSERT_TRUE(stats_.shadowPass.ran);
    ASSERT_EQ(view.render(map(), stats_.light, /*mapRedrawn=*/false, {}, 256, 256), "");
    EXPECT_EQ(view.shownRange().min, first.min);  // not told: the old measurement stays
    ASSERT_EQ(view.render(map(), stats_.light, /*mapRedrawn=*/true, {}, 256, 256), "");
    const DepthRange expected = writtenDepthRange(depth_);
    EXPECT_NE(view.shownRange().min, first.min);
    EXPECT_EQ(view.shownRange().min, expected.min);
    EXPECT_EQ(view.shownRange().max, expected.max);

    // A reallocated map is re-measured even if the caller forgets to say so.
    settings.lights[0].shadow.resolution = 512;
    render(settings);
    ASSERT_EQ(view.render(map(), stats_.light, false, {}, 256, 256), "");
    EXPECT_EQ(view.shownRange().min, writtenDepthRange(depth_).min);
}

TEST_F(ShadowMapViewTest, AnUnchangedPictureIsNotRedrawn) {
    Settings settings = loadShippedPreset("default");
    render(settings);
    ShadowMapView view;
    ShadowMapViewOptions options;
    ASSERT_EQ(view.render(map(), stats_.light, true, options, 200, 200), "");
    EXPECT_TRUE(view.redrawn());
    ASSERT_EQ(view.render(map(), stats_.light, false, options, 200, 200), "");
    EXPECT_FALSE(view.redrawn());  // an idle editor frame costs nothing
    options.texelGrid = false;
    ASSERT_EQ(view.render(map(), stats_.light, false, options, 200, 200), "");
    EXPECT_TRUE(view.redrawn());
    ASSERT_EQ(view.render(map(), stats_.light, false, options, 201, 200), "");
    EXPECT_TRUE(view.redrawn());
    ASSERT_EQ(view.render(map(), stats_.light, true, options, 201, 200), "");  // the shadow pass ran
    EXPECT_TRUE(view.redrawn());
    settings.lights[0].shadow.resolution = 1024;  // a new map
    render(settings);
    ASSERT_EQ(view.render(map(), stats_.light, false, options, 201, 200), "");
    EXPECT_TRUE(view.redrawn());
}

TEST_F(ShadowMapViewTest, FullAndManualContrastAndRefusedManualRange) {
    render(loadShippedPreset("default"));
    ShadowMapView view;
    ShadowMapViewOptions options;
    options.contrast = DepthContrast::Full;
    ASSERT_EQ(view.render(map(), stats_.light, true, options, 128, 128), "");
    EXPECT_EQ(view.shownRange().min, 0.0f);
    EXPECT_EQ(view.shownRange().max, 1.0f);

    options.contrast = DepthContrast::Manual;
    options.manualMin = 0.4f;
    options.manualMax = 0.6f;
    ASSERT_EQ(view.render(map(), stats_.light, false, options, 128, 128), "");
    EXPECT_EQ(view.shownRange().min, 0.4f);
    const std::vector<std::uint8_t> kept = view.readPixels();

    options.manualMin = 0.7f;  // above max: refused, the picture stays
    const std::string error = view.render(map(), stats_.light, false, options, 128, 128);
    EXPECT_NE(error.find("min"), std::string::npos) << error;
    EXPECT_EQ(view.readPixels(), kept);
    EXPECT_EQ(view.shownRange().min, 0.4f);
}

TEST_F(ShadowMapViewTest, TexelGridAppearsOnlyWhenZoomedIn) {
    render(loadShippedPreset("default"));
    ShadowMapView view;
    ShadowMapViewOptions options;
    MapZoomPan zoomPan;
    const int w = 400, h = 300, res = map().resolution();
    options.visible = zoomPan.visibleRect(w, h);
    ASSERT_EQ(view.render(map(), stats_.light, true, options, w, h), "");
    EXPECT_FALSE(view.gridShown());
    EXPECT_EQ(gridPixels(view), 0);

    // Zoom on the middle cube's left edge (at zoom 1 the map spans x 50..350) until a texel covers >= 8 pixels.
    while (texelPixels(zoomPan.visibleRect(w, h), w, res) < kGridMinTexelPixels)
        zoomPan.zoomAt(50.0 + 0.465 * h, 0.5 * h, 1.5, w, h, res);
    options.visible = zoomPan.visibleRect(w, h);
    ASSERT_EQ(view.render(map(), stats_.light, false, options, w, h), "");
    save(view, "shadow_map_view_zoomed_grid");
    EXPECT_TRUE(view.gridShown());
    // About two lines per texel column and row: a texel of p pixels has ~2p grid pixels of its p^2.
    const double p = texelPixels(options.visible, w, res);
    EXPECT_GT(gridPixels(view), long(0.5 * w * h * (2.0 / p)));
    EXPECT_LT(gridPixels(view), long(1.5 * w * h * (2.0 / p)));

    options.texelGrid = false;
    ASSERT_EQ(view.render(map(), stats_.light, false, options, w, h), "");
    EXPECT_EQ(gridPixels(view), 0);
}

TEST_F(ShadowMapViewTest, HoverGivesTheTexelAndItsStoredDepth) {
    render(loadShippedPreset("default"));
    ShadowMapView view;
    ShadowMapViewOptions options;
    MapZoomPan zoomPan;
    const int w = 300, h = 200, res = map().resolution();
    zoomPan.zoomAt(180.0, 70.0, 3.0, w, h, res);
    zoomPan.pan(-25.0, 10.0, w, h);
    options.visible = zoomPan.visibleRect(w, h);
    options.texelGrid = false;
    ASSERT_EQ(view.render(map(), stats_.light, true, options, w, h), "");
    const ShownDepthRange range = view.shownRange();
    int checked = 0;
    for (const glm::dvec2 mouse : {glm::dvec2(10.5, 10.5), glm::dvec2(150.5, 100.5), glm::dvec2(290.5, 190.5),
                                   glm::dvec2(77.5, 160.5), glm::dvec2(220.5, 30.5)}) {
        const std::optional<glm::ivec2> texel = texelAtView(options.visible, mouse.x, mouse.y, w, h, res);
        if (!texel) continue;
        const std::optional<float> depth = view.depthAt(map(), texel->x, texel->y);
        ASSERT_TRUE(depth.has_value());
        EXPECT_EQ(*depth, storedDepth(*texel));
        // And it is the texel the picture shows under the mouse.
        const Rgb c = at(view, int(mouse.x), int(mouse.y));
        if (*depth < 1.0f) EXPECT_NEAR(c.r, 255.0 * std::clamp((*depth - range.min) / (range.max - range.min), 0.0f, 1.0f), 2.0);
        ++checked;
    }
    EXPECT_GE(checked, 4);
    EXPECT_FALSE(view.depthAt(map(), -1, 0).has_value());
    EXPECT_FALSE(view.depthAt(map(), res, 0).has_value());
}

TEST_F(ShadowMapViewTest, SpotDepthLinearizedBetweenNearAndFar) {
    Settings settings = loadShippedPreset("default");
    settings.lights[0].type = LightType::Spot;
    settings.lights[0].position = {3.0f, 8.0f, 2.0f};
    settings.lights[0].direction = {-0.3f, -1.0f, -0.2f};
    render(settings);
    ASSERT_TRUE(stats_.light.perspective);
    EXPECT_NEAR(linearLightDepth(stats_.light, 0.0), 0.0, 1e-9);
    EXPECT_NEAR(linearLightDepth(stats_.light, 1.0), 1.0, 1e-9);

    ShadowMapView view;
    ShadowMapViewOptions options;
    options.linearize = true;
    ASSERT_EQ(view.render(map(), stats_.light, true, options, 256, 256), "");
    save(view, "shadow_map_view_spot_linear");
    const DepthRange stored = writtenDepthRange(depth_);
    EXPECT_NEAR(view.shownRange().min, linearLightDepth(stats_.light, stored.min), 1e-6);
    EXPECT_NEAR(view.shownRange().max, linearLightDepth(stats_.light, stored.max), 1e-6);
    // Perspective depth crowds toward 1; linear depth spreads the scene over a wider range.
    EXPECT_GT(view.shownRange().max - view.shownRange().min, stored.max - stored.min);
    const std::optional<glm::ivec2> texel = texelAtView(options.visible, 128.5, 128.5, 256, 256, map().resolution());
    ASSERT_TRUE(texel.has_value());
    const float d = storedDepth(*texel);
    ASSERT_LT(d, 1.0f);
    const double expected = 255.0 * (linearLightDepth(stats_.light, d) - view.shownRange().min) /
                            (view.shownRange().max - view.shownRange().min);
    EXPECT_NEAR(at(view, 128, 128).r, expected, 2.0);
}

TEST_F(ShadowMapViewTest, NoMapYetSaysSo) {
    ShadowMap empty;
    ShadowMapView view;
    const std::string error = view.render(empty, LightSpace{}, true, {}, 64, 64);
    EXPECT_NE(error.find("no shadow map"), std::string::npos) << error;
    EXPECT_FALSE(view.depthAt(empty, 0, 0).has_value());
}

}  // namespace
}  // namespace shadowlab::test
