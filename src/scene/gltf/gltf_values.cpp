// Loose glTF values: fields of extension objects (gltf_values.h).
#include "scene/gltf/gltf_values.h"

#include <tiny_gltf.h>

#include <cmath>

namespace shadelab {

double numberOr(const tinygltf::Value& obj, const char* key, double fallback) {
    if (!obj.IsObject() || !obj.Has(key)) return fallback;
    const tinygltf::Value& v = obj.Get(key);
    return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

std::vector<double> numbersOf(const tinygltf::Value& obj, const char* key) {
    std::vector<double> out;
    if (!obj.IsObject() || !obj.Has(key) || !obj.Get(key).IsArray()) return out;
    const tinygltf::Value& a = obj.Get(key);
    for (size_t i = 0; i < a.ArrayLen(); ++i) {
        const tinygltf::Value& x = a.Get(int(i));
        out.push_back(x.IsNumber() ? x.GetNumberAsDouble() : std::nan(""));
    }
    return out;
}

}  // namespace shadelab
