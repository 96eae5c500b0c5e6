// A glTF node's camera and light (gltf_lights_cameras.h), read for the importer's node walk (gltf_import.cpp).
#include "scene/gltf/gltf_lights_cameras.h"

#include "scene/gltf/gltf_values.h"
#include "scene/scene_limits.h"
#include "util/input_error.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

namespace shadelab::gltf {
namespace {

std::string indexed(const char* array, size_t i) { return std::string(array) + "[" + std::to_string(i) + "]"; }

// KHR_lights_punctual's cone: 0 <= innerConeAngle < outerConeAngle <= π/2 (defaults 0 and π/4). A value
// outside [0, π/2] is clamped into it, and an inner angle past the outer one is lowered to it, with a warning.
void addCone(const tinygltf::SpotLight& spot, const std::string& lightPlace, Light& l, const Warn& warnOnce) {
    const auto angle = [&](double a, float fallback, const char* name) {
        if (std::isfinite(a) && a >= 0.0 && a <= double(kMaxConeAngle)) return float(a);
        const float clamped = std::isfinite(a) ? float(std::clamp(a, 0.0, double(kMaxConeAngle))) : fallback;
        warnOnce(lightPlace + ".spot." + name + ": " + std::to_string(a) + " outside [0, pi/2]; using " +
                 std::to_string(clamped));
        return clamped;
    };
    l.innerConeAngle = angle(spot.innerConeAngle, kDefaultInnerConeAngle, "innerConeAngle");
    l.outerConeAngle = angle(spot.outerConeAngle, kDefaultOuterConeAngle, "outerConeAngle");
    if (l.innerConeAngle > l.outerConeAngle) {
        warnOnce(lightPlace + ".spot.innerConeAngle: " + std::to_string(l.innerConeAngle) +
                 " exceeds outerConeAngle; using " + std::to_string(l.outerConeAngle));
        l.innerConeAngle = l.outerConeAngle;
    }
}

glm::vec3 direction(const glm::dvec3& d, const glm::vec3& fallback) {
    const double len = glm::length(d);
    return len > 1e-12 && std::isfinite(len) ? glm::vec3(d / len) : fallback;
}

}  // namespace

std::optional<Camera> importCamera(const tinygltf::Model& model_, const tinygltf::Node& node, const std::string& file_,
                                   const std::string& place, const glm::dmat4& world, const Warn& warnOnce) {
    if (size_t(node.camera) >= model_.cameras.size())
        throw InputError(file_, place,
                         "camera " + std::to_string(node.camera) + " out of range (" +
                             std::to_string(model_.cameras.size()) + " cameras)");
    const tinygltf::Camera& gc = model_.cameras[size_t(node.camera)];
    const std::string cameraPlace = indexed("cameras", size_t(node.camera));
    if (gc.type != "perspective") {
        warnOnce(cameraPlace + ": " + gc.type + " camera skipped (only perspective cameras are imported)");
        return std::nullopt;
    }
    // glTF cameras look down their node's -Z with +Y up (glTF 2.0 spec, "Cameras").
    Camera c;
    c.position = glm::vec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    const glm::dmat3 linear(world);
    c.target = c.position + direction(linear * glm::dvec3(0.0, 0.0, -1.0), glm::vec3(0.0f, 0.0f, -1.0f));
    c.up = direction(linear * glm::dvec3(0.0, 1.0, 0.0), glm::vec3(0.0f, 1.0f, 0.0f));
    const double yfov = gc.perspective.yfov;
    if (std::isfinite(yfov) && yfov > 0.0 && yfov < glm::pi<double>()) {
        c.fovY = float(glm::degrees(yfov));
    } else {
        c.fovY = 45.0f;
        warnOnce(cameraPlace + ": yfov " + std::to_string(yfov) + " out of (0, pi); using 45 degrees");
    }
    return c;
}

std::optional<ImportedLight> importLight(const tinygltf::Model& model_, const tinygltf::Node& node,
                                         const std::string& file_, const std::string& place, const glm::dmat4& world,
                                         const Warn& warnOnce) {
    const std::string extPlace = place + ".extensions.KHR_lights_punctual";
    const tinygltf::Value& ext = node.extensions.at("KHR_lights_punctual");
    const double index = numberOr(ext, "light", -1.0);
    if (!(index >= 0.0 && index < double(model_.lights.size())))
        throw InputError(
            file_, extPlace,
            "light " + std::to_string(index) + " out of range (" + std::to_string(model_.lights.size()) + " lights)");
    const tinygltf::Light& gl = model_.lights[size_t(index)];
    const std::string lightPlace = indexed("KHR_lights_punctual.lights", size_t(index));
    Light l;
    l.name = gl.name.empty() ? node.name : gl.name;
    const glm::dmat3 linear(world);
    if (gl.type == "directional") {
        l.type = LightType::Directional;
        l.direction = direction(linear * glm::dvec3(0.0, 0.0, -1.0), glm::vec3(0.0f, -1.0f, 0.0f));
    } else if (gl.type == "point" || gl.type == "spot") {
        l.type = gl.type == "spot" ? LightType::Spot : LightType::Point;
        l.position = glm::vec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
        // A spot shines along its node's −Z, as a directional light does; scale leaves the cone alone.
        if (l.type == LightType::Spot) {
            l.direction = direction(linear * glm::dvec3(0.0, 0.0, -1.0), glm::vec3(0.0f, -1.0f, 0.0f));
            addCone(gl.spot, lightPlace, l, warnOnce);
        }
        // range: > 0 where given (the spec's "Must be > 0"), absent is infinite; anything else is dropped.
        if (std::isfinite(gl.range) && gl.range > 0.0) {
            l.range = float(std::min(gl.range, double(kMaxCoordinate)));
        } else if (gl.range != 0.0) {
            warnOnce(lightPlace + ": range " + std::to_string(gl.range) + " is not > 0; the light has no range");
        }
    } else {
        warnOnce(lightPlace + ": unknown light type \"" + gl.type + "\" skipped");
        return std::nullopt;
    }
    l.color = gl.color.size() >= 3 ? glm::vec3(finiteClamp(gl.color[0], 0.0f, kMaxRadiance, 1.0f),
                                               finiteClamp(gl.color[1], 0.0f, kMaxRadiance, 1.0f),
                                               finiteClamp(gl.color[2], 0.0f, kMaxRadiance, 1.0f))
                                   : glm::vec3(1.0f);
    return ImportedLight{std::move(l), finiteClamp(gl.intensity, 0.0f, 1e30f, 1.0f)};
}

}  // namespace shadelab::gltf
