#include "raster/shader_variant.h"

#include "raster/frame_block.h"
#include "raster/shadow_block.h"
#include "shading/dfg_lut.h"
#include "shading/lighting.h"
#include "shading/sheen_lut.h"

#include <algorithm>

namespace shadelab::raster {

std::string ShaderVariant::defines() const {
    const auto define = [](const char* name, const std::string& value) {
        return std::string("#define ") + name + " " + value + "\n";
    };
    std::string s;
    s += define("SL_SHADOWS", shadows ? "1" : "0");
    s += define("SL_MAX_LIGHTS", std::to_string(kMaxLights));
    s += define("SL_MAX_SHADOWED", std::to_string(kMaxShadowedLights));
    s += define("SL_MAX_SHADOW_LAYERS", std::to_string(kMaxShadowLayers));
    s += define("SL_MAX_SHADOW_PLANES", std::to_string(kMaxShadowPlanes));
    s += define("SL_MODEL", std::to_string(model));
    s += define("SL_AMBIENT", terms & kTermAmbient ? "true" : "false");
    s += define("SL_DIFFUSE", terms & kTermDiffuse ? "true" : "false");
    s += define("SL_SPECULAR", terms & kTermSpecular ? "true" : "false");
    s += define("SL_LIGHTS", std::to_string(lights));
    s += define("SL_MORE_LIGHTS", moreLights ? "1" : "0");
    // An X-macro over the specialised lights, unrolled here: Mesa does not unroll the loop itself, and only
    // literal arguments let it fold each light's branches and load its matrices as uniform (an index read
    // from a uniform block makes llvmpipe gather per fragment).
    // F(index, isPoint, isAttenuated, shadow kind, plane mask, first layer).
    std::string each;
    for (int i = 0; i < lights; ++i) {
        const size_t k = size_t(i);
        each += " F(" + std::to_string(i) + ", " + (point[k] ? "true" : "false") + ", " +
                (attenuated[k] ? "true" : "false") + ", " + std::to_string(shadowKind[k]) + ", " +
                std::to_string(planeMask[k]) + ", " + std::to_string(firstLayer[k]) + ")";
    }
    s += define("SL_FOR_EACH_LIGHT(F)", each);
    s += define("SL_SHADOW_PLANES", std::to_string(planes));
    s += define("SL_PCF", pcf ? "1" : "0");
    s += define("SL_IBL", std::to_string(ibl));
    s += define("SL_DFG_SIZE", std::to_string(shading::kDfgLutSize));
    s += define("SL_SHEEN_SIZE", std::to_string(shading::kSheenLutSize));
    s += define("SL_ENERGY_COMPENSATION", energyCompensation ? "1" : "0");
    s += define("SL_ENVIRONMENT", "0");  // RasterRenderer redefines it to 1 for its environment programs
    return s;
}

std::string colorProgramDefines(const std::string& variantDefines, int materialMaps, bool environment) {
    std::string s = variantDefines;
    // Bit 64 is the clear coat, bit 256 glTF's specular layer and bit 512 its sheen (ColorProgramCache::kCoatBit,
    // kSpecularLayerBit, kSheenBit), the others mesh.frag's maps.
    const int maps = materialMaps & ~(64 | 256 | 512);
    if (maps) s += "#define SL_MATERIAL_MAPS " + std::to_string(maps) + "\n";
    if (materialMaps & 64) s += "#define SL_CLEARCOAT 1\n";
    if (materialMaps & 256) s += "#define SL_SPECULAR_LAYER 1\n";
    if (materialMaps & 512) s += "#define SL_SHEEN 1\n";
    if (environment) s += "#undef SL_ENVIRONMENT\n#define SL_ENVIRONMENT 1\n";
    return s;
}

// surface.glsl's shadeOneLight picks disney's function by `#if SL_MODEL == 3`.
static_assert(shading::SL_MODEL_DISNEY == 3 && shading::SL_MODEL_PBR == 2);

ShaderVariant makeShaderVariant(const FrameBlock& frame, const ShadowBlock* shadows, int model) {
    ShaderVariant v;
    v.model = model >= 0 ? model : frame.flags.x;
    v.terms = frame.flags.y;
    const int count = std::clamp(frame.flags.z, 0, kMaxLights);
    v.lights = std::min(count, kMaxShadowedLights);
    v.moreLights = count > kMaxShadowedLights;
    for (int i = 0; i < v.lights; ++i) {
        v.point[size_t(i)] = frame.lightPos[i].w != 0.0f;
        v.attenuated[size_t(i)] =
            v.point[size_t(i)] && (glm::vec3(frame.lightAtten[i]) != glm::vec3(1.0f, 0.0f, 0.0f) ||
                                   frame.lightCone[i].z != 0.0f || frame.lightCone[i].w != 0.0f);
    }
    const bool pbr = shading::physicallyBased(v.model);  // pbr, disney
    v.ibl = pbr && (v.terms & kTermAmbient) ? frame.iblInfo.x : 0;
    v.energyCompensation = pbr && frame.iblInfo.w != 0;
    if (shadows && (frame.flags.w & kPassShadows)) {
        v.shadows = true;
        v.planes = std::clamp(shadows->info.x, 0, kMaxShadowPlanes);
        v.pcf = shadows->info.y != 0;
        for (int i = 0; i < v.lights; ++i) {
            v.shadowKind[size_t(i)] = shadows->light[i].x;
            v.planeMask[size_t(i)] = shadows->light[i].z;
            v.firstLayer[size_t(i)] = shadows->light[i].y;
        }
    }
    return v;
}

}  // namespace shadelab::raster
