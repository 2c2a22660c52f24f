// Issue 21, "optional mips": with filter.momentMips a distant receiver reads the moments at the level of its pixel's
// footprint in the map, so its shadow factor is the mean over the texels the pixel covers instead of one point of
// them: the picture aliases less (8 slats whose shadows show as 5 stripes without mips, a grey band with them).
// Measured against the same view rendered at 8x8 the pixels and box-filtered down
// (the area mean each pixel should show).
#include "gl_fixture.h"

#include <cmath>
#include <cstdio>

namespace shadowlab::test {
namespace {

class MomentMips : public GlTest {};

constexpr int kWidth = 160, kHeight = 90, kSuper = 8;

// Mean |S - the 8x8 supersampled S| over the scene pixels of a kWidth x kHeight shadow-factor view, and how many of
// them are off by more than a quarter (aliased edges).
struct Aliasing {
    double meanError = 0.0;
    long aliased = 0, pixels = 0;
};

Aliasing aliasingOf(const View& view, const View& super) {
    Aliasing a;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = std::size_t(y) * kWidth + std::size_t(x);
            if (!view.isGreyScene(i)) continue;
            double sum = 0.0;
            int n = 0;
            for (int sy = 0; sy < kSuper; ++sy)
                for (int sx = 0; sx < kSuper; ++sx) {
                    const std::size_t j = std::size_t(y * kSuper + sy) * kWidth * kSuper + std::size_t(x * kSuper + sx);
                    if (!super.isGreyScene(j)) continue;
                    sum += super.rgba[j * 4];
                    ++n;
                }
            if (n < kSuper * kSuper) continue;  // a silhouette: the background shares the pixel
            const double error = std::abs(view.rgba[i * 4] - sum / n) / 255.0;
            a.meanError += error;
            a.aliased += error > 0.25;
            ++a.pixels;
        }
    if (a.pixels > 0) a.meanError /= double(a.pixels);
    return a;
}

TEST_F(MomentMips, ADistantGrazingFloorAliasesLessWithMips) {
    // builtin:fence's slats under a low light from +z: their shadows, stripes a unit apart (half a unit wide) running
    // 5 units back from the fence, seen from 60 units above: a pixel covers 0.24 units of floor, the stripes' edges
    // are 2 pixels apart, and a 2048^2 map's texel is about 0.01 units (level 4-5 of the mips).
    const Scene scene = loadBuiltin("fence");
    Settings s = loadShippedPreset("default");
    s.filter.kind = FilterKind::Vsm;
    s.lights[0].shadow.resolution = 2048;
    s.lights[0].direction = glm::vec3(0.0f, -0.6f, -1.0f);
    s.camera.autoFrame = false;
    s.camera.position = glm::dvec3(0.0, 150.0, -2.5);
    s.camera.target = glm::dvec3(0.0, 0.0, -2.5);
    s.camera.fovYDeg = 20.0f;
    s.view = ViewMode::Shadow;
    Renderer renderer;
    const View super = renderView(renderer, scene, s, kWidth * kSuper, kHeight * kSuper);
    ASSERT_TRUE(super.stats.ok) << super.stats.error;
    const View plain = renderView(renderer, scene, s, kWidth, kHeight);
    s.filter.momentMips = true;
    const View mipped = renderView(renderer, scene, s, kWidth, kHeight);
    ASSERT_TRUE(mipped.stats.ok) << mipped.stats.error;
    saveView(plain, "moment-mips-off");
    saveView(mipped, "moment-mips-on");
    const Aliasing off = aliasingOf(plain, super), on = aliasingOf(mipped, super);
    std::printf("fence shadow from 150 units above, VSM, 2048^2, %dx%d against %dx supersampling: mean |S - S_area| %.4f without mips, "
                "%.4f with; pixels off by > 0.25: %ld and %ld of %ld\n",
                kWidth, kHeight, kSuper, off.meanError, on.meanError, off.aliased, on.aliased, on.pixels);
    ASSERT_GT(on.pixels, 1000);
    EXPECT_GT(off.aliased, 50) << "without mips the slats' shadows alias";
    EXPECT_LT(on.meanError, 0.8 * off.meanError);  // llvmpipe: 0.0264 -> 0.0177
    EXPECT_LT(on.aliased, 0.6 * double(off.aliased));  // llvmpipe: 58 -> 26
}

}  // namespace
}  // namespace shadowlab::test
