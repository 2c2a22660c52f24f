// The shipped presets for the built-ins with their own lights (presets/room.json, presets/courtyard.json) render
// their scenes headless with every light they list: no error, and a picture with lit and shadowed surfaces.
#include "gl_fixture.h"

#include <algorithm>

namespace shadowlab::test {
namespace {

class LitBuiltinPresets : public GlTest {};

TEST_F(LitBuiltinPresets, RoomAndCourtyardRenderWithEveryLight) {
    Renderer renderer;
    for (const auto& [name, lightCount] : {std::pair<std::string, std::size_t>{"room", 1}, {"courtyard", 4}}) {
        SCOPED_TRACE(name);
        const Scene scene = loadBuiltin(name);
        Settings settings = loadShippedPreset(name);
        settings.camera.autoFrame = true;  // from outside: the view's corners show the background
        ASSERT_EQ(settings.lights.size(), lightCount);
        const View view = renderView(renderer, scene, settings, 160, 100);
        saveView(view, "lit-builtin-" + name);
        ASSERT_TRUE(view.stats.ok) << view.stats.error;
        EXPECT_NE(view.stats.lightSource.find("the settings' " + std::to_string(lightCount) + " light"),
                  std::string::npos)
            << view.stats.lightSource;
        // Scene pixels (not the background's clear colour, which the view's corner shows): the brightest is lit,
        // and some are much darker (in shadow, or outside a light's reach).
        auto isBackground = [&](std::size_t i) {
            return std::equal(&view.rgba[i * 4], &view.rgba[i * 4 + 3], &view.rgba[0]);
        };
        auto luma = [&](std::size_t i) { return (view.rgba[i * 4] + view.rgba[i * 4 + 1] + view.rgba[i * 4 + 2]) / 3; };
        int brightest = 0;
        long dark = 0, scenePixels = 0;
        const std::size_t pixels = view.rgba.size() / 4;
        for (std::size_t i = 0; i < pixels; ++i)
            if (!isBackground(i)) ++scenePixels, brightest = std::max(brightest, luma(i));
        for (std::size_t i = 0; i < pixels; ++i) dark += !isBackground(i) && luma(i) < brightest / 2;
        EXPECT_GT(scenePixels, 160 * 100 / 4) << "the scene fills the view";
        EXPECT_GT(brightest, 120);
        EXPECT_GT(dark, 50);
    }
}

}  // namespace
}  // namespace shadowlab::test
