// Zoom and pan of the shadow-map picture (pure maths): the whole map fits at zoom 1 with square texels, zooming keeps
// the texel under the cursor in place, panning moves the map with the mouse, and view positions map to texels.
#include "overlay/map_zoom_pan.h"

#include <gtest/gtest.h>

using namespace shadowlab;

TEST(MapZoomPan, ZoomOneFitsTheWholeMapWithSquareTexels) {
    MapZoomPan zp;
    const UvRect square = zp.visibleRect(400, 400);
    EXPECT_DOUBLE_EQ(square.min.x, 0.0);
    EXPECT_DOUBLE_EQ(square.max.y, 1.0);
    const UvRect wide = zp.visibleRect(800, 400);  // extra width shows beside the map, texels stay square
    EXPECT_DOUBLE_EQ(wide.max.x - wide.min.x, 2.0);
    EXPECT_DOUBLE_EQ(wide.max.y - wide.min.y, 1.0);
    EXPECT_DOUBLE_EQ(texelPixels(wide, 800, 2048), 400.0 / 2048.0);
}

TEST(MapZoomPan, ZoomKeepsTheTexelUnderTheCursorAndIsClamped) {
    MapZoomPan zp;
    const int w = 640, h = 480, res = 1024;
    const glm::dvec2 before = viewToUv(zp.visibleRect(w, h), 100.0, 50.0, w, h);
    zp.zoomAt(100.0, 50.0, 1.25, w, h, res);
    zp.zoomAt(100.0, 50.0, 1.25, w, h, res);
    EXPECT_NEAR(zp.zoom(), 1.5625, 1e-12);
    const glm::dvec2 after = viewToUv(zp.visibleRect(w, h), 100.0, 50.0, w, h);
    EXPECT_NEAR(after.x, before.x, 1e-12);
    EXPECT_NEAR(after.y, before.y, 1e-12);

    zp.zoomAt(320.0, 240.0, 1e9, w, h, res);  // up to kMaxTexelPixels per texel
    EXPECT_NEAR(texelPixels(zp.visibleRect(w, h), w, res), MapZoomPan::kMaxTexelPixels, 1e-9);
    zp.zoomAt(320.0, 240.0, 1e-9, w, h, res);
    EXPECT_EQ(zp.zoom(), MapZoomPan::kMinZoom);
    zp.reset();
    EXPECT_EQ(zp.zoom(), 1.0);
}

TEST(MapZoomPan, PanMovesTheMapWithTheMouse) {
    MapZoomPan zp;
    const int w = 400, h = 400;
    zp.zoomAt(200.0, 200.0, 4.0, w, h, 2048);
    const glm::dvec2 grabbed = viewToUv(zp.visibleRect(w, h), 150.0, 220.0, w, h);
    zp.pan(30.0, -12.0, w, h);
    const glm::dvec2 now = viewToUv(zp.visibleRect(w, h), 180.0, 208.0, w, h);
    EXPECT_NEAR(now.x, grabbed.x, 1e-12);
    EXPECT_NEAR(now.y, grabbed.y, 1e-12);
    zp.pan(1e6, 1e6, w, h);  // the centre stays on the map
    EXPECT_GE(zp.center().x, 0.0);
    EXPECT_LE(zp.center().y, 1.0);
}

TEST(MapZoomPan, ViewPositionsMapToTexelsWithRowZeroAtTheBottom) {
    const UvRect whole;  // the map exactly fills a 512x512 view of a 256² map: 2x2 pixels per texel
    EXPECT_EQ(texelAtView(whole, 0.5, 511.5, 512, 512, 256), glm::ivec2(0, 0));      // bottom-left
    EXPECT_EQ(texelAtView(whole, 511.5, 0.5, 512, 512, 256), glm::ivec2(255, 255));  // top-right
    EXPECT_EQ(texelAtView(whole, 5.0, 501.0, 512, 512, 256), glm::ivec2(2, 5));
    MapZoomPan zp;
    const UvRect wide = zp.visibleRect(800, 400);
    EXPECT_FALSE(texelAtView(wide, 10.0, 200.0, 800, 400, 256).has_value());  // beside the map
    EXPECT_TRUE(texelAtView(wide, 400.0, 200.0, 800, 400, 256).has_value());
}
