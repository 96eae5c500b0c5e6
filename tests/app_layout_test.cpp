// layOutViewer (app/viewer_layout.h): the viewer's panel and image placement at UI scales 1, 1.5 and 2, on a
// laptop window, a projector's and a HiDPI framebuffer.
#include "app/viewer_layout.h"

#include <gtest/gtest.h>

using namespace shadelab::app;

namespace {

LayoutInput window(int w, int h, float uiScale, int fbScale = 1) {
    LayoutInput in;
    in.windowWidth = w;
    in.windowHeight = h;
    in.fbWidth = w * fbScale;
    in.fbHeight = h * fbScale;
    in.uiScale = uiScale;
    return in;
}

}  // namespace

TEST(ViewerLayout, AtScaleOneThePanelSitsBesideAnImageThatFillsTheRest) {
    const ViewerLayout l = layOutViewer(window(1600, 900, 1.0f));
    EXPECT_FLOAT_EQ(l.panelWidth, 440.0f);
    EXPECT_FALSE(l.panelOverlays);
    EXPECT_EQ(l.renderWidth, 1160);
    EXPECT_EQ(l.renderHeight, 900);
    EXPECT_FLOAT_EQ(l.imageX, 440.0f);
    EXPECT_FLOAT_EQ(l.imageY, 0.0f);
    EXPECT_FLOAT_EQ(l.imageW, 1160.0f);
    EXPECT_EQ(l.fbRect.x, 440);
    EXPECT_EQ(l.fbRect.y, 0);

    LayoutInput hidden = window(1600, 900, 1.0f);
    hidden.showPanel = false;
    const ViewerLayout h = layOutViewer(hidden);
    EXPECT_FLOAT_EQ(h.panelWidth, 0.0f);
    EXPECT_EQ(h.renderWidth, 1600);  // control: without the panel the image takes the window
}

TEST(ViewerLayout, AtScaleOneAndAHalfAWidePanelLiesOverTheImage) {
    // 660 units of panel on a 1280-unit window would leave a portrait image: it overlays instead.
    const ViewerLayout narrow = layOutViewer(window(1280, 720, 1.5f));
    EXPECT_FLOAT_EQ(narrow.panelWidth, 640.0f);  // at most half the window
    EXPECT_TRUE(narrow.panelOverlays);
    EXPECT_EQ(narrow.renderWidth, 1280);
    EXPECT_FLOAT_EQ(narrow.imageX, 0.0f);
    // On a window wide enough for both, it sits beside (control).
    const ViewerLayout wide = layOutViewer(window(2400, 1000, 1.5f));
    EXPECT_FLOAT_EQ(wide.panelWidth, 660.0f);
    EXPECT_FALSE(wide.panelOverlays);
    EXPECT_EQ(wide.renderWidth, 2400 - 660);
}

TEST(ViewerLayout, AtScaleTwoOnAHiDpiFramebufferTheImageIsInFramebufferPixels) {
    const ViewerLayout l = layOutViewer(window(1920, 1080, 2.0f, 2));
    EXPECT_FLOAT_EQ(l.fbScale, 2.0f);
    EXPECT_FLOAT_EQ(l.panelWidth, 880.0f);
    EXPECT_TRUE(l.panelOverlays);  // 880 > 0.34 × 1920
    EXPECT_EQ(l.renderWidth, 3840);
    EXPECT_EQ(l.renderHeight, 2160);
    EXPECT_FLOAT_EQ(l.imageW, 1920.0f);  // window units
    EXPECT_EQ(l.fbRect.width, 3840);

    LayoutInput projector = window(3000, 1200, 2.0f);
    projector.overlayPanel = true;  // F11, even where it would fit beside
    EXPECT_TRUE(layOutViewer(projector).panelOverlays);
    projector.overlayPanel = false;
    EXPECT_FALSE(layOutViewer(projector).panelOverlays);  // control
}

TEST(ViewerLayout, AFixedSizeShowsOneToOneWhenItFitsElseScaledDownAndCentred) {
    LayoutInput in = window(1600, 900, 1.0f);
    in.fixedWidth = 640;
    in.fixedHeight = 360;
    const ViewerLayout fits = layOutViewer(in);
    EXPECT_EQ(fits.renderWidth, 640);
    EXPECT_EQ(fits.fbRect.width, 640);
    EXPECT_EQ(fits.fbRect.x, 440 + (1160 - 640) / 2);
    EXPECT_EQ(fits.fbRect.y, (900 - 360) / 2);
    in.fixedWidth = 2320;
    in.fixedHeight = 900;
    const ViewerLayout big = layOutViewer(in);
    EXPECT_EQ(big.renderWidth, 2320);   // rendered at its size...
    EXPECT_EQ(big.fbRect.width, 1160);  // ... shown at half
    EXPECT_EQ(big.fbRect.height, 450);
    EXPECT_FLOAT_EQ(big.imageY, float(900 - 225 - 450));
}
