// layOutViewer: the viewer's panel and image placement.
#include "app/viewer_layout.h"

#include <algorithm>
#include <cmath>

namespace shadelab::app {

ViewerLayout layOutViewer(const LayoutInput& in) {
    ViewerLayout l;
    const int winW = std::max(1, in.windowWidth);
    l.fbScale = float(in.fbWidth) / float(winW);
    l.panelWidth = in.showPanel ? std::min(kViewerPanelWidth * in.uiScale, 0.5f * float(winW)) : 0.0f;
    const bool overlay = in.overlayPanel || (in.uiScale >= 1.5f && l.panelWidth > 0.34f * float(winW));
    l.panelOverlays = overlay && in.showPanel;
    const int areaX = overlay ? 0 : int(std::lround(l.panelWidth * l.fbScale));
    const int areaW = std::max(1, in.fbWidth - areaX), areaH = std::max(1, in.fbHeight);
    if (in.fixedWidth > 0) {
        l.renderWidth = in.fixedWidth;
        l.renderHeight = in.fixedHeight;
    } else {
        l.renderWidth = areaW;
        l.renderHeight = areaH;
    }
    const float scale = std::min({1.0f, float(areaW) / float(l.renderWidth), float(areaH) / float(l.renderHeight)});
    l.fbRect.width = std::max(1, int(std::lround(float(l.renderWidth) * scale)));
    l.fbRect.height = std::max(1, int(std::lround(float(l.renderHeight) * scale)));
    l.fbRect.x = areaX + (areaW - l.fbRect.width) / 2;
    l.fbRect.y = (areaH - l.fbRect.height) / 2;
    l.imageX = float(l.fbRect.x) / l.fbScale;
    l.imageY = float(in.fbHeight - l.fbRect.y - l.fbRect.height) / l.fbScale;
    l.imageW = float(l.fbRect.width) / l.fbScale;
    l.imageH = float(l.fbRect.height) / l.fbScale;
    return l;
}

}  // namespace shadelab::app
