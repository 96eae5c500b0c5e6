// The words drawn on the image itself (docs/viewer.md, "Captions"), so a class sees what it shows with the panel
// hidden: the model, the terms (the lecture's progression step), and the view mode; in Split, which side is which.
// Plain functions of the state, so tests read the same words the window draws.
#pragma once

#include "app/viewer_state.h"

#include <string>

namespace shadelab::app {

// "Phong", "normalised Blinn-Phong", "PBR (GGX)".
std::string modelCaption(const Scene& scene);
// "ambient + diffuse + specular"; "nothing" when every term is off. Transmission rides with reflections.
std::string termsCaption(const Terms& terms);
// What the Global modes' caption says of the path tracer: how far it has got and what is shown.
struct GlobalCaption {
    int samples = 0;        // per pixel so far (0: the first pass is under way)
    double noise8 = 0.0;    // the raw estimate's mean standard error, 8-bit sRGB units
    bool denoised = false;  // the image shown is the denoised preview
};
// The top-left caption: "Blinn-Phong · ambient + diffuse + specular · raster"; in the Global modes then the
// samples and the noise ("· 16 samples, noise 2.1/255", "noise -" until two samples measure it) and
// "denoised" for the preview; then the display when it is not Standard ("· filmic, +1 stops"), except in
// Difference, which shows the raw values.
std::string imageCaption(const ViewerState& state, const GlobalCaption& global = {});
// The labels left and right of the wipe of Split ("raster" | "reference (Whitted ray tracer)") and of
// Local | Global ("local (raster)" | "global (path traced)"); empty in the other modes.
struct WipeCaptions {
    const char* left = "";
    const char* right = "";
};
WipeCaptions wipeCaptions(ViewMode mode);

// Where the two wipe labels go, in window pixels: each kept to its own side of the wipe within the visible
// image, so that they never meet and never leave it. The left one ends `gap` before the wipe, the right one
// starts `gap` after it; a label its side has no room for is not drawn (the wipe dragged to an edge, or under
// the panel).
struct WipeLabelPlacement {
    bool leftShown = false, rightShown = false;
    float leftX = 0.0f, rightX = 0.0f;  // each label's left edge
};
WipeLabelPlacement placeWipeLabels(float visibleLeft, float visibleRight, float wipe, float gap, float leftWidth,
                                   float rightWidth);

}  // namespace shadelab::app
