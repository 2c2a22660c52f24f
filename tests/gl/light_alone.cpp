#include "light_alone.h"

namespace shadowlab::test {

LightAlone renderLightAlone(Renderer& renderer, const Scene& scene, const Settings& settings, std::size_t light,
                            int width, int height) {
    Settings alone = settings;
    alone.view = ViewMode::Shadow;
    alone.lights = {settings.lights.at(light)};
    const View shadowed = renderView(renderer, scene, alone, width, height);
    EXPECT_TRUE(shadowed.stats.ok) << shadowed.stats.error;
    alone.lights[0].castsShadows = false;
    const View reach = renderView(renderer, scene, alone, width, height);
    EXPECT_TRUE(reach.stats.ok) << reach.stats.error;
    LightAlone a;
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    a.shadowFactor.assign(pixels, 0.0);
    a.reach.assign(pixels, 0.0);
    if (!shadowed.stats.ok || !reach.stats.ok) return a;
    for (std::size_t i = 0; i < pixels; ++i) {
        if (!reach.isGreyScene(i)) continue;  // the background
        a.reach[i] = reach.rgba[i * 4] / 255.0;
        a.shadowFactor[i] = shadowed.rgba[i * 4] / 255.0;
        const bool reached = a.reach[i] > 0.5;
        a.reached += reached;
        a.shadowed += reached && shadowed.rgba[i * 4] < 64;
    }
    return a;
}

}  // namespace shadowlab::test
