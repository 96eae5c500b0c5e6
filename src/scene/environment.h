// Environment: what surrounds the scene, as plain data (docs/scene-format.md "environment"). Absent, rays
// that leave the scene see `background` and nothing lights surfaces but the lights and Ia·ma. Present, it
// is the radiance every escaping ray sees (uniform `background`, or an equirectangular .hdr map) and it
// lights pbr surfaces by split-sum image-based lighting (docs/lighting.md). loadEnvironment fills `map`.
#pragma once

#include "shading/environment_map.h"

#include <memory>
#include <string>

namespace shadelab {

struct Environment {
    std::string hdr;         // equirectangular Radiance .hdr, as written (relative to the scene file); "" = uniform
    float intensity = 1.0f;  // radiance scale, >= 0
    float rotation = 0.0f;   // degrees about +y, turning the map (not the scene)
    // The prefiltered map of `hdr` (loadEnvironment, scene/environment_load.h), shared by both renderers and
    // every copy of the scene; null for a uniform environment, which needs no data.
    std::shared_ptr<const shading::PrefilteredEnvironment> map;
};

}  // namespace shadelab
