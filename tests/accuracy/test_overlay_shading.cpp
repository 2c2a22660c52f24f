// The accuracy overlay keeps the surface's shading under its colours, and every colour stays apart from the others'
// shades (the legend still names each pixel).
#include "accuracy/accuracy_overlay.h"

#include <gtest/gtest.h>

namespace shadowlab {

TEST(OverlayShading, ColoursFollowLambertAndStayApartFromEachOther) {
    std::vector<LegendEntry> all = errorLegend();
    for (const LegendEntry& e : causeLegend()) all.push_back(e);
    for (const LegendEntry& e : all) {
        const OverlayRgb lit = shadedColour(e, 1.0f), grazing = shadedColour(e, 0.0f), half = shadedColour(e, 0.5f);
        EXPECT_EQ(lit.red, e.red) << e.name;
        EXPECT_LT(grazing.red + grazing.green + grazing.blue, lit.red + lit.green + lit.blue) << e.name;
        for (const OverlayRgb c : {lit, grazing, half}) {
            const std::uint8_t rgb[3] = {c.red, c.green, c.blue};
            EXPECT_TRUE(isShadeOf(e, rgb)) << e.name;
            for (const LegendEntry& other : all) {
                const bool same = other.red == e.red && other.green == e.green && other.blue == e.blue;
                if (!same) EXPECT_FALSE(isShadeOf(other, rgb)) << e.name << " reads as " << other.name;
            }
        }
    }
    const std::uint8_t grey[3] = {120, 120, 120};
    EXPECT_FALSE(isShadeOf(errorLegend()[0], grey));
}

}  // namespace shadowlab
