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
// The top-left caption: "Blinn-Phong · ambient + diffuse + specular · raster", then "denoised" when the Global
// modes show the path tracer's denoised preview (`denoised`), then the display when it is not Standard
// ("· filmic, +1 stops"), except in Difference, which shows the raw values.
std::string imageCaption(const ViewerState& state, bool denoised = false);
// Split: the labels left and right of the wipe.
inline const char* splitLeftCaption() { return "raster"; }
inline const char* splitRightCaption() { return "reference (Whitted ray tracer)"; }

}  // namespace shadelab::app
