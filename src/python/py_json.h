// Python values → JSON documents, for scene documents built from dicts (Scene.from_dict, attribute edits). Only
// what a scene file can hold converts: dicts with string keys, lists and tuples, str, bool, int, float and None,
// plus anything with __index__ or __float__ (numpy scalars); numpy arrays arrive as lists (the package calls
// tolist()). Anything else is an InputError naming its JSON path.
#pragma once

#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>
#include <string>

namespace shadelab::python {

nlohmann::json toJson(pybind11::handle value, const std::string& path = "");

}  // namespace shadelab::python
