// ShadingModel and its one name table: the words scene files, `--model` and viewer scripts accept.
// "blinn" is an alias of blinn-phong on input; files and messages always use the canonical names.
#pragma once

#include "util/name_table.h"

namespace shadelab {

// The values are shading::SL_MODEL_* (shaders/lighting.glsl); modelIndex() hands them to the renderers.
enum class ShadingModel { Phong = 0, BlinnPhong = 1, Pbr = 2, Disney = 3 };

inline constexpr EnumName<ShadingModel> kShadingModelNames[] = {
    {ShadingModel::Phong, "phong"},
    {ShadingModel::BlinnPhong, "blinn-phong"},
    {ShadingModel::BlinnPhong, "blinn", true},
    {ShadingModel::Pbr, "pbr"},
    {ShadingModel::Disney, "disney"},
};

inline int modelIndex(ShadingModel m) { return int(m); }

// The microfacet models, pbr and disney: they read the metallic-roughness fields (baseColor, metallic,
// roughness), take image-based light in place of the constant ambient, and show the base colour unlit.
inline bool isPhysicallyBased(ShadingModel m) { return m == ShadingModel::Pbr || m == ShadingModel::Disney; }

inline const char* toString(ShadingModel m) { return nameOf(kShadingModelNames, m); }
inline std::optional<ShadingModel> parseShadingModel(std::string_view name) {
    return lookupName(kShadingModelNames, name);
}

}  // namespace shadelab
