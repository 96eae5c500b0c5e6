// The white furnace: the scene with every material white and lit by nothing but a uniform
// environment of radiance 1, so a model that loses or gains energy shows up as dark or bright rings on an
// object that should vanish into the background. Pure functions on Scene; the viewer's button and the
// `whiteFurnace` script action use them. What each model shows: docs/lighting.md, "The white furnace".
#pragma once

#include "scene/scene.h"

namespace shadelab {

struct WhiteFurnaceSettings {
    float radiance = 1.0f;  // the uniform environment: background (and Ia), linear
    bool ambient = true;    // Ia = radiance with the ambient term on: the lecture's stand-in for the environment.
                            // Off where the environment itself lights the surfaces (image-based lighting, a
                            // path tracer), so the ambient term does not count that light twice.
};

// The furnace version of `scene`. It sets scene fields only, nothing a renderer must know about:
// - background = radiance (grey) and a uniform environment of it (image-based lighting under pbr), Ia =
//   radiance with the ambient term on (or Ia = 0 and off), no lights;
// - every material white: ma = baseColor = 1; the lecture's md + ms = 1 (ms = the mean of ms, clamped to
//   [0, 1], md = 1 − ms), so a lobe that conserves energy reflects all of it; s, metallic and roughness kept;
//   kr = kt = 0 (no mirror or glass paths: the surface's own BRDF is on trial); a checker's md2 = md;
// - terms: diffuse and specular on, ambient as settings.ambient; shadows and reflections off (no lights, no kr).
// Camera, model, `normalized`, raster settings, geometry and names are unchanged.
Scene whiteFurnaceScene(const Scene& scene, const WhiteFurnaceSettings& settings = {});

// Leaving the furnace: `saved` (the scene before whiteFurnaceScene) with what the class may have changed
// meanwhile that the furnace never sets: the camera, the model and `normalized`. With no change in between,
// exactly `saved`.
Scene leaveWhiteFurnace(const Scene& saved, const Scene& furnace);

}  // namespace shadelab
