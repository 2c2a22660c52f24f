#pragma once
// One headless GL 4.5 context (EGL, Mesa llvmpipe in CI) for the whole gl_tests run, with KHR_debug output on:
// any GL error reported during a test fails it.
#include "context/headless_context.h"
#include "frame/renderer.h"
#include "gl/gl_errors.h"
#include "image/image_io.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace shadowlab::test {

HeadlessContext& sharedContext();

class GlTest : public ::testing::Test {
protected:
    void SetUp() override;
    void TearDown() override;
};

// A rendered view read back into memory, with the stats that produced it.
struct View {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // row 0 = bottom (GL order)
    FrameStats stats;

    // Red channel at a pixel given top-down (x right, y down) coordinates.
    int red(int x, int yDown) const;
    // The red channel (0..255) where a world point lands; -1 if it is off screen.
    int redAt(const glm::dvec3& world) const;
    // Whether pixel i (index into rgba / 4) shows the scene: the background's clear colour is not grey, every
    // shadow-factor pixel is.
    bool isGreyScene(std::size_t i) const {
        return rgba[i * 4] == rgba[i * 4 + 1] && rgba[i * 4 + 1] == rgba[i * 4 + 2];
    }
    // Scene pixels (shadow view) whose red value passes a predicate.
    template <typename Predicate>
    long countScenePixels(Predicate predicate) const {
        long n = 0;
        for (std::size_t i = 0; i * 4 < rgba.size(); ++i) n += isGreyScene(i) && predicate(int(rgba[i * 4]));
        return n;
    }
    // Mean red over a (2r+1)^2 window around a world point's pixel; -1 if off screen.
    double meanRedAround(const glm::dvec3& world, int r) const;
};

// Renders `scene` with `settings` into a fresh target of the given size using `renderer`.
View renderView(Renderer& renderer, const Scene& scene, const Settings& settings, int width = 320, int height = 240);

// Writes a PNG of a view under the test output folder (look at it!) and returns the path.
std::string saveView(const View& view, const std::string& name);

Scene loadBuiltin(const std::string& name);
// Looking straight down from y=30 at the origin, showing the shadow factor: every floor point outside a caster's
// footprint is visible, so shadows can be checked at hand-computed floor positions.
Settings topDownShadowView(Settings settings);
Settings loadShippedPreset(const std::string& name);
// `settings` with the first light's depth, slope-scaled and normal-offset bias at 0 (acne where the light grazes).
Settings zeroBias(Settings settings);

}  // namespace shadowlab::test
