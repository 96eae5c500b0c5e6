// Python values ↔ JSON. To documents: scene documents built from dicts (Scene.from_dict, attribute edits). Only
// what a scene file can hold converts: dicts with string keys, lists and tuples, str, bool, int, float and None,
// plus anything with __index__ or __float__ (numpy scalars); numpy arrays arrive as lists (the package calls
// tolist()). Anything else is an InputError naming its JSON path.
#pragma once

#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>
#include <string>

namespace shadelab::python {

nlohmann::json toJson(pybind11::handle value, const std::string& path = "");

// JSON text (a scene file, a report) as Python values, keys in the text's order: what json.loads would give,
// without the package importing json.
pybind11::object jsonTextToPython(const std::string& text);

}  // namespace shadelab::python
