// The viewer's layout: where the side panel and the image go in the window, and the size the image is rendered
// at, as a pure function of the window, the UI scale and the options, so that it is tested without a window
// (app_layout_test.cpp). Window (logical) units unless named fb*; the framebuffer may be denser (HiDPI).
#pragma once

#include "app/image_rect.h"

namespace shadelab::app {

inline constexpr float kViewerPanelWidth = 440.0f;  // side panel, window units at UI scale 1

struct LayoutInput {
    int windowWidth = 0, windowHeight = 0;  // window units
    int fbWidth = 0, fbHeight = 0;          // framebuffer pixels
    float uiScale = 1.0f;
    bool showPanel = true;
    bool overlayPanel = false;            // projector mode (key F11): the panel lies over a full-window image
    int fixedWidth = 0, fixedHeight = 0;  // --size: the image is rendered at this size (0: the area's)
};

struct ViewerLayout {
    float fbScale = 1.0f;                   // framebuffer pixels per window unit
    float panelWidth = 0.0f;                // 0 when the panel is hidden
    bool panelOverlays = false;             // the panel lies over the image (projector mode, or too wide to sit beside)
    float imageX = 0, imageY = 0;           // the image's top-left corner
    float imageW = 0, imageH = 0;           // its size as shown
    ImageRect fbRect;                       // the same in framebuffer pixels (GL)
    int renderWidth = 0, renderHeight = 0;  // the size the image is rendered at
};

// The panel is kViewerPanelWidth × uiScale wide, at most half the window. At a UI scale of 1.5 or more a panel
// wider than a third of the window would squeeze the image into a portrait, so it lies over the image instead.
// The image fills the rest (or the whole window under an overlaid panel); a fixed size shows 1:1 when it fits,
// else scaled down to fit, centred.
ViewerLayout layOutViewer(const LayoutInput& in);

}  // namespace shadelab::app
