// glTF's layers on a pbr surface point: the fields of shading::SurfaceParams that the layered functions read
// (shadeLightPbrLayers, the environment's split sums), set in one place for the Whitted tracer, the path tracer
// and the probe, so that the probe's parts are those of the picture.
#pragma once

#include "shading/local_illumination.h"
#include "trace/surface.h"

#include <glm/vec3.hpp>

namespace shadelab::trace {

// Sets `p`'s layers for the surface `s` (its material, textured coat, base colour and metallic) seen along the
// unit direction `V`, whatever model `s` is shaded with (the probe shows pbr's under every model): the clear coat
// (coat, coatN); glTF's specular layer, ior and anisotropy (layered, specLayer, aniso, baseColor, metallic, and ms =
// its F0); the sheen (sheen, sheenTable, sheenEV); the transmission and volume (transmission, transmitColor,
// transmitTint, and md = what stays diffuse). A material without a layer leaves those fields as they are.
void setPbrLayers(shading::SurfaceParams& p, const Surface& s, const glm::vec3& V);

}  // namespace shadelab::trace
