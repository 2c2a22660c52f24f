// The shipped presets for the built-ins with their own lights (presets/room.json, presets/courtyard.json) render
// their scenes headless with every light they list: no error, a picture with lit and shadowed surfaces, and EACH
// light casts: alone it shadows part of what it reaches, and in the full picture turning its shadow off brightens
// pixels (a dark patch from any one light would not show that the others cast).
#include "gl_fixture.h"
#include "light_alone.h"

#include <algorithm>
#include <cstdio>

namespace shadowlab::test {
namespace {

class LitBuiltinPresets : public GlTest {};

TEST_F(LitBuiltinPresets, RoomAndCourtyardRenderWithEveryLight) {
    Renderer renderer;
    constexpr int kWidth = 320, kHeight = 200;
    for (const auto& [name, lightCount] : {std::pair<std::string, std::size_t>{"room", 1}, {"courtyard", 4}}) {
        SCOPED_TRACE(name);
        const Scene scene = loadBuiltin(name);
        Settings settings = loadShippedPreset(name);
        settings.camera.autoFrame = true;  // from outside: the view's corners show the background
        ASSERT_EQ(settings.lights.size(), lightCount);
        const View view = renderView(renderer, scene, settings, kWidth, kHeight);
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
        EXPECT_GT(scenePixels, kWidth * kHeight / 4) << "the scene fills the view";
        EXPECT_GT(brightest, 120);
        EXPECT_GT(dark, 50);

        for (std::size_t light = 0; light < lightCount; ++light) {
            SCOPED_TRACE("light " + std::to_string(light));
            ASSERT_TRUE(settings.lights[light].enabled && settings.lights[light].castsShadows);
            const LightAlone alone = renderLightAlone(renderer, scene, settings, light, kWidth, kHeight);
            EXPECT_GT(alone.shadowed, 20) << "alone, it shadows none of the " << alone.reached << " pixels it reaches";
            Settings unshadowed = settings;
            unshadowed.lights[light].castsShadows = false;
            const View without = renderView(renderer, scene, unshadowed, kWidth, kHeight);
            ASSERT_TRUE(without.stats.ok) << without.stats.error;
            long brighter = 0;
            for (std::size_t i = 0; i < pixels; ++i)
                brighter += !isBackground(i) && luma(i) + 8 <= (without.rgba[i * 4] + without.rgba[i * 4 + 1] +
                                                                 without.rgba[i * 4 + 2]) / 3;
            std::printf("[ %s ] light %zu: alone shadows %ld of the %ld pixels it reaches; shadow off brightens %ld\n",
                        name.c_str(), light, alone.shadowed, alone.reached, brighter);
            EXPECT_GT(brighter, 20) << "in the full picture its shadow darkens nothing: with its castsShadows off "
                                    << "no pixel gets 8 levels brighter";
        }
    }
}

}  // namespace
}  // namespace shadowlab::test
