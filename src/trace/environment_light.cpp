// EnvironmentLight: the rotation and intensity applied as the rasterizer's shaders apply them
// (shaders/surface.glsl, SL_IBL), around the shared lookups of shaders/ibl.glsl.
#include "trace/environment_light.h"

#include "scene/scene_models.h"
#include "shading/dfg_lut.h"
#include "shading/prefilter.h"

#include <algorithm>

#include <cmath>
#include <glm/trigonometric.hpp>

namespace shadelab::trace {

EnvironmentLight::EnvironmentLight(const Scene& scene) : uniform_(scene.background) {
    // The DFG table costs tens of milliseconds the first time: only pbr scenes that read it compute it.
    const bool pbr = usesPhysicallyBased(scene);  // the scene's model, or any material's own
    if (pbr && (scene.environment || scene.energyCompensation || usesTransmission(scene)))
        lookup_.dfg = &shading::dfgLut();
    if (!scene.environment) return;
    const Environment& e = *scene.environment;
    lightsPbr_ = pbr;
    intensity_ = e.intensity;
    uniform_ = scene.background * e.intensity;
    cosRot_ = std::cos(glm::radians(e.rotation));
    sinRot_ = std::sin(glm::radians(e.rotation));
    lookup_.env = e.map.get();
}

glm::vec3 EnvironmentLight::escaping(glm::vec3 dir) const { return prefiltered(dir, 0.0f); }

glm::vec3 EnvironmentLight::prefiltered(glm::vec3 R, float roughness) const {
    if (!lookup_.env) return uniform_;
    shading::IblLookup l = lookup_;
    return intensity_ *
           l.iblPrefiltered(lookup_.env->size, lookup_.env->levels, l.iblRotate(R, cosRot_, sinRot_), roughness);
}

float EnvironmentLight::mirrorWeight(float roughness) const {
    const int levels = lookup_.env ? lookup_.env->levels : shading::prefilterLevels(256);
    return std::max(0.0f, 1.0f - std::clamp(roughness, 0.0f, 1.0f) * float(levels - 1));
}

glm::vec3 EnvironmentLight::prefilteredWithMirror(glm::vec3 R, float roughness, glm::vec3 mirror) const {
    const float w = mirrorWeight(roughness);
    if (w <= 0.0f) return prefiltered(R, roughness);
    // Level 1 alone: lod = 1 reads it with weight 1 (ibl.glsl's trilinear filter).
    const int levels = lookup_.env ? lookup_.env->levels : shading::prefilterLevels(256);
    return glm::mix(prefiltered(R, 1.0f / float(levels - 1)), mirror, w);
}

glm::vec3 EnvironmentLight::irradiance(glm::vec3 N) const {
    if (!lookup_.env) return uniform_;
    shading::IblLookup l = lookup_;
    return intensity_ * lookup_.irradiance(l.iblRotate(glm::normalize(N), cosRot_, sinRot_));
}

glm::vec2 EnvironmentLight::dfg(float NoV, float roughness) const { return lookup_.dfgAt(NoV, roughness); }

}  // namespace shadelab::trace
