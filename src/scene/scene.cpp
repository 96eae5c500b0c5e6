// Scene helpers: the shading model's names as used in scene files, flags and the viewer.
#include "scene/scene.h"

#include <stdexcept>

namespace shadelab {

const char* toString(ShadingModel m) {
    switch (m) {
        case ShadingModel::Phong: return "phong";
        case ShadingModel::BlinnPhong: return "blinn-phong";
    }
    return "phong";
}

ShadingModel parseShadingModel(const std::string& name) {
    if (name == "phong") return ShadingModel::Phong;
    if (name == "blinn-phong") return ShadingModel::BlinnPhong;
    throw std::invalid_argument("unknown shading model '" + name + "'; expected phong or blinn-phong");
}

}  // namespace shadelab
