// Loose glTF values, for materials and lights: a number clamped to a range when finite, and the numbers of
// an extension object's fields (tinygltf::Value), with fallbacks for what is missing or of the wrong type.
#pragma once

#include <vector>

namespace tinygltf {
class Value;
}

namespace shadelab {

// x clamped to [lo, hi]; `fallback` when x is NaN or infinite.
float finiteClamp(double x, float lo, float hi, float fallback);

// obj[key] as a number; `fallback` when obj is not an object, lacks key, or holds something else there.
double numberOr(const tinygltf::Value& obj, const char* key, double fallback);

// obj[key] as numbers (NaN for a non-number element); empty when it is not an array.
std::vector<double> numbersOf(const tinygltf::Value& obj, const char* key);

}  // namespace shadelab
