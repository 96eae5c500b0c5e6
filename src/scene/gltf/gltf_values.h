// Loose glTF values, for materials and lights: the numbers of an extension object's fields (tinygltf::Value),
// with fallbacks for what is missing or of the wrong type. They become floats through util/finite.h.
#pragma once

#include "util/finite.h"  // finiteClamp, for the files that read these values

#include <vector>

namespace tinygltf {
class Value;
}

namespace shadelab {

// obj[key] as a number; `fallback` when obj is not an object, lacks key, or holds something else there.
double numberOr(const tinygltf::Value& obj, const char* key, double fallback);

// obj[key] as numbers (NaN for a non-number element); empty when it is not an array.
std::vector<double> numbersOf(const tinygltf::Value& obj, const char* key);

}  // namespace shadelab
