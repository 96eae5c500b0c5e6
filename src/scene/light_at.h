// A scene light evaluated at a point through shaders/lighting.glsl's functions: the vector toward it and the
// intensity arriving there. The tracers, the path tracer's next-event estimation and the probe read lights
// through lightAt; the rasterizer uploads the same lightCone() (raster/frame_block.cpp), so every renderer
// evaluates one formula.
#pragma once

#include "scene/light.h"
#include "shading/lighting.h"

namespace shadelab {

// lightIntensityAt's `cone`: a spot's spotConeScaleOffset() and flag, and a positional light's range.
inline glm::vec4 lightCone(const Light& l) {
    const bool spot = l.type == LightType::Spot;
    const glm::vec2 c = spot ? shading::spotConeScaleOffset(l.innerConeAngle, l.outerConeAngle) : glm::vec2(0.0f);
    return glm::vec4(c.x, c.y, l.positional() ? l.range : 0.0f, spot ? 1.0f : 0.0f);
}

// lightVector's posOrDir: the position of a point or spot light, a directional light's direction of travel.
inline glm::vec3 lightPosOrDir(const Light& l) { return l.positional() ? l.position : l.direction; }

struct LightAt {
    glm::vec3 L;   // from the point toward the light, unnormalised (lightVector)
    glm::vec3 Il;  // intensity arriving at the point: attenuation, range and cone applied
};

inline LightAt lightAt(const Light& l, const glm::vec3& P) {
    const bool positional = l.positional();
    const glm::vec3 L = shading::lightVector(lightPosOrDir(l), positional, P);
    return {L, shading::lightIntensityAt(l.color, positional, l.attenuation, L, l.direction, lightCone(l))};
}

}  // namespace shadelab
