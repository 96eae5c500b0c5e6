// toJson: a Python value as the JSON document a scene file would hold. NaN and infinities stay numbers, so that
// the scene reader rejects them at their path ("must be finite").
#include "python/py_json.h"

#include "util/input_error.h"

#include <cctype>

namespace py = pybind11;

namespace shadelab::python {
namespace {

constexpr int kMaxDepth = 64;  // nesting; a scene document is a few levels deep

// The path of `key` inside `path`, written as the scene reader writes it (json_reader.cpp).
std::string childPath(const std::string& path, const std::string& key) {
    bool identifier = !key.empty() && !std::isdigit(static_cast<unsigned char>(key[0]));
    for (char c : key)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') identifier = false;
    if (!identifier) return path + "[" + nlohmann::json(key).dump() + "]";
    return path.empty() ? key : path + "." + key;
}

nlohmann::json convert(py::handle v, const std::string& path, int depth) {
    if (depth > kMaxDepth) throw InputError("", path, "nested too deeply");
    if (v.is_none()) return nullptr;
    if (py::isinstance<py::bool_>(v)) return v.cast<bool>();
    if (py::isinstance<py::str>(v)) return v.cast<std::string>();
    if (py::isinstance<py::int_>(v) || (!py::isinstance<py::float_>(v) && py::hasattr(v, "__index__"))) {
        py::int_ i = py::reinterpret_steal<py::int_>(PyNumber_Index(v.ptr()));
        if (!i) throw py::error_already_set();
        // Beyond int64: as a float (the reader checks ranges; such values fail there with their path).
        long long ll = PyLong_AsLongLong(i.ptr());
        if (ll == -1 && PyErr_Occurred()) {
            PyErr_Clear();
            return PyLong_AsDouble(i.ptr());
        }
        return static_cast<int64_t>(ll);
    }
    if (py::isinstance<py::float_>(v) || py::hasattr(v, "__float__")) return v.cast<double>();
    if (py::isinstance<py::dict>(v)) {
        nlohmann::json obj = nlohmann::json::object();
        for (auto item : py::reinterpret_borrow<py::dict>(v)) {
            if (!py::isinstance<py::str>(item.first))
                throw InputError("", path, "keys must be strings, got " + std::string(py::str(item.first)));
            const std::string key = item.first.cast<std::string>();
            obj[key] = convert(item.second, childPath(path, key), depth + 1);
        }
        return obj;
    }
    if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
        nlohmann::json arr = nlohmann::json::array();
        size_t i = 0;
        for (py::handle e : v) arr.push_back(convert(e, path + "[" + std::to_string(i++) + "]", depth + 1));
        return arr;
    }
    throw InputError("", path,
                     "cannot be written in a scene: " + std::string(py::str(py::type::handle_of(v).attr("__name__"))));
}

}  // namespace

nlohmann::json toJson(py::handle value, const std::string& path) { return convert(value, path, 0); }

namespace {

py::object toPython(const nlohmann::ordered_json& j) {
    switch (j.type()) {
        case nlohmann::ordered_json::value_t::null: return py::none();
        case nlohmann::ordered_json::value_t::boolean: return py::bool_(j.get<bool>());
        case nlohmann::ordered_json::value_t::number_integer: return py::int_(j.get<int64_t>());
        case nlohmann::ordered_json::value_t::number_unsigned: return py::int_(j.get<uint64_t>());
        case nlohmann::ordered_json::value_t::number_float: return py::float_(j.get<double>());
        case nlohmann::ordered_json::value_t::string: return py::str(j.get_ref<const std::string&>());
        case nlohmann::ordered_json::value_t::array: {
            py::list list;
            for (const auto& e : j) list.append(toPython(e));
            return std::move(list);
        }
        case nlohmann::ordered_json::value_t::object: {
            py::dict dict;
            for (auto it = j.begin(); it != j.end(); ++it) dict[py::str(it.key())] = toPython(it.value());
            return std::move(dict);
        }
        default: break;
    }
    return py::none();
}

}  // namespace

py::object jsonTextToPython(const std::string& text) { return toPython(nlohmann::ordered_json::parse(text)); }

}  // namespace shadelab::python
