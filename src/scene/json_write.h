// Writing numbers into scene files: floats as the shortest decimal that reads back exactly, and RGB/XYZ triples.
// Shared by the scene writer (scene_json.cpp) and the material writer (material_json.cpp).
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <system_error>

namespace shadelab::json_write {

// The shortest decimal that reads back as exactly `f`, as a double: 0.1f is written "0.1", not
// "0.10000000149011612". The loader reads a double and rounds it to float, so check that path. Where the
// standard library has no floating-point to_chars (the web build's libc++), the shortest of %.1g .. %.9g that
// reads back as `f` (9 significant digits always do) is the same number.
inline double exact(float f) {
    char buf[64];
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
    auto r = std::to_chars(buf, buf + sizeof buf, f);
    double d = 0.0;
    if (r.ec != std::errc() || std::from_chars(buf, r.ptr, d).ec != std::errc() || static_cast<float>(d) != f)
        return static_cast<double>(f);
    return d;
#else
    if (!std::isfinite(f)) return static_cast<double>(f);
    for (int digits = 1; digits <= 9; ++digits) {
        std::snprintf(buf, sizeof buf, "%.*g", digits, static_cast<double>(f));
        const double d = std::strtod(buf, nullptr);
        if (static_cast<float>(d) == f) return d;
    }
    return static_cast<double>(f);
#endif
}

inline nlohmann::ordered_json vec(const glm::vec3& v) {
    return nlohmann::ordered_json::array({exact(v.x), exact(v.y), exact(v.z)});
}

}  // namespace shadelab::json_write
