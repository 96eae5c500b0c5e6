// C++ view of shaders/ibl.glsl: the same lookup text compiled as members of IblLookup, whose texel hooks
// read the arrays of environment_map.h where the shaders use texelFetch. The tracer and the tests call it;
// the rasterizer runs the GLSL. No GL and no scene types.
#pragma once

#include "shading/environment_map.h"
#include "shading/lighting.h"

#include <array>
#include <glm/common.hpp>
#include <glm/vec2.hpp>

namespace shadelab::shading {

using glm::clamp;

struct IblLookup {
    const PrefilteredEnvironment* env = nullptr;  // may be null when only iblDFG is used
    const DfgLut* dfg = nullptr;

    vec3 iblTexel(int x, int y) const {
        const float* t = &env->atlas[(size_t(y) * size_t(env->atlasWidth) + size_t(x)) * 3];
        return vec3(t[0], t[1], t[2]);
    }
    vec2 dfgTexel(int x, int y) const {
        const float* t = &dfg->ab[(size_t(y) * size_t(dfg->size) + size_t(x)) * 2];
        return vec2(t[0], t[1]);
    }

#define SL_FN
#include "shaders/cube_face.glsl"
#include "shaders/ibl.glsl"
#undef SL_FN

    // Conveniences over the GLSL-shaped functions.
    vec3 irradiance(vec3 n) const {
        std::array<vec3, 9> sh = env->sh;  // iblIrradianceSH takes the array as GLSL does, by value
        return IblLookup(*this).iblIrradianceSH(sh.data(), n);
    }
    vec3 prefiltered(vec3 R, float roughness) const {
        return IblLookup(*this).iblPrefiltered(env->size, env->levels, R, roughness);
    }
    vec2 dfgAt(float NoV, float roughness) const { return IblLookup(*this).iblDFG(dfg->size, NoV, roughness); }
};

}  // namespace shadelab::shading
