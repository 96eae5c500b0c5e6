// Shared helpers of the scene JSON tests: a field-by-field, bit-exact comparison of two scenes (the list of
// differing fields, empty when equal), parsing with the warnings kept, and the save-reload round trip.
// Test-only; not part of the library.
#pragma once

#include "scene/scene_json.h"

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace shadelab::test {

// ---- Field-by-field, bit-exact comparison: the list of differing fields, empty when equal ---------------

struct Diff {
    std::vector<std::string> fields;
    void f(const std::string& name, float a, float b) {
        if (std::memcmp(&a, &b, sizeof a) != 0) fields.push_back(name + " " + str(a) + " vs " + str(b));
    }
    void v(const std::string& name, const glm::vec3& a, const glm::vec3& b) {
        for (int i = 0; i < 3; ++i) f(name + "[" + std::to_string(i) + "]", a[i], b[i]);
    }
    template <class T>
    void eq(const std::string& name, const T& a, const T& b) {
        if (!(a == b)) fields.push_back(name);
    }
    template <class T, class Fn>
    void opt(const std::string& name, const std::optional<T>& a, const std::optional<T>& b, Fn cmp) {
        if (a.has_value() != b.has_value())
            fields.push_back(name + " presence");
        else if (a)
            cmp(name, *a, *b);
    }
    static std::string str(float x) {
        std::ostringstream s;
        s.precision(9);
        s << x;
        return s.str();
    }
    void material(const std::string& p, const Material& a, const Material& b) {
        v(p + ".ma", a.ma, b.ma), v(p + ".md", a.md, b.md), v(p + ".ms", a.ms, b.ms), f(p + ".s", a.s, b.s);
        v(p + ".kr", a.kr, b.kr), v(p + ".kt", a.kt, b.kt), f(p + ".ior", a.ior, b.ior);
        v(p + ".baseColor", a.baseColor, b.baseColor), f(p + ".metallic", a.metallic, b.metallic);
        f(p + ".roughness", a.roughness, b.roughness);
        for (const DisneyField& d : kDisneyFields) f(p + ".disney." + d.name, a.disney.*d.member, b.disney.*d.member);
        for (const auto& c : kClearcoatFields)
            f(p + ".clearcoat." + c.name, a.clearcoat.*c.member, b.clearcoat.*c.member);
        f(p + ".specular.factor", a.specular.factor, b.specular.factor);
        v(p + ".specular.color", a.specular.color, b.specular.color);
        v(p + ".sheen.color", a.sheen.color, b.sheen.color),
            f(p + ".sheen.roughness", a.sheen.roughness, b.sheen.roughness);
        f(p + ".anisotropy.strength", a.anisotropy.strength, b.anisotropy.strength);
        f(p + ".anisotropy.rotation", a.anisotropy.rotation, b.anisotropy.rotation);
        f(p + ".transmission.factor", a.transmission.factor, b.transmission.factor);
        f(p + ".volume.thickness", a.volume.thickness, b.volume.thickness);
        f(p + ".volume.attenuationDistance", a.volume.attenuationDistance, b.volume.attenuationDistance);
        v(p + ".volume.attenuationColor", a.volume.attenuationColor, b.volume.attenuationColor);
        eq(p + ".model", a.model, b.model);
    }
    void materialOverride(const std::string& p, const MaterialOverride& a, const MaterialOverride& b) {
        auto vv = [this](const std::string& n, const glm::vec3& x, const glm::vec3& y) { v(n, x, y); };
        auto ff = [this](const std::string& n, float x, float y) { f(n, x, y); };
        opt(p + ".ma", a.ma, b.ma, vv), opt(p + ".md", a.md, b.md, vv), opt(p + ".ms", a.ms, b.ms, vv);
        opt(p + ".s", a.s, b.s, ff), opt(p + ".kr", a.kr, b.kr, vv), opt(p + ".kt", a.kt, b.kt, vv);
        opt(p + ".ior", a.ior, b.ior, ff), opt(p + ".baseColor", a.baseColor, b.baseColor, vv);
        opt(p + ".metallic", a.metallic, b.metallic, ff), opt(p + ".roughness", a.roughness, b.roughness, ff);
        for (int i = 0; i < kDisneyFieldCount; ++i)
            opt(p + ".disney." + kDisneyFields[i].name, a.disney.value[i], b.disney.value[i], ff);
        for (int i = 0; i < ClearcoatOverride::kCount; ++i)
            opt(p + ".clearcoat." + kClearcoatFields[i].name, a.clearcoat.value[i], b.clearcoat.value[i], ff);
        opt(p + ".specular.factor", a.specular.factor, b.specular.factor, ff);
        opt(p + ".specular.color", a.specular.color, b.specular.color, vv);
        opt(p + ".sheen.color", a.sheen.color, b.sheen.color, vv);
        opt(p + ".sheen.roughness", a.sheen.roughness, b.sheen.roughness, ff);
        opt(p + ".anisotropy.strength", a.anisotropy.strength, b.anisotropy.strength, ff);
        opt(p + ".anisotropy.rotation", a.anisotropy.rotation, b.anisotropy.rotation, ff);
        opt(p + ".transmission.factor", a.transmission.factor, b.transmission.factor, ff);
        opt(p + ".volume.thickness", a.volume.thickness, b.volume.thickness, ff);
        opt(p + ".volume.attenuationDistance", a.volume.attenuationDistance, b.volume.attenuationDistance, ff);
        opt(p + ".volume.attenuationColor", a.volume.attenuationColor, b.volume.attenuationColor, vv);
    }
};

inline std::vector<std::string> diffScenes(const Scene& a, const Scene& b) {
    Diff d;
    d.eq("title", a.title, b.title), d.eq("notes", a.notes, b.notes);
    d.v("camera.position", a.camera.position, b.camera.position);
    d.v("camera.target", a.camera.target, b.camera.target);
    d.v("camera.up", a.camera.up, b.camera.up), d.f("camera.fovY", a.camera.fovY, b.camera.fovY);
    d.eq("model", a.model, b.model);
    d.eq("normalized", a.normalized, b.normalized);
    d.eq("terms.ambient", a.terms.ambient, b.terms.ambient), d.eq("terms.diffuse", a.terms.diffuse, b.terms.diffuse);
    d.eq("terms.specular", a.terms.specular, b.terms.specular);
    d.eq("terms.shadows", a.terms.shadows, b.terms.shadows);
    d.eq("terms.reflections", a.terms.reflections, b.terms.reflections);
    d.v("ambient", a.ambient, b.ambient), d.v("background", a.background, b.background);
    d.eq("environment", a.environment.has_value(), b.environment.has_value());
    if (a.environment && b.environment) {
        d.eq("environment.hdr", a.environment->hdr, b.environment->hdr);
        d.f("environment.intensity", a.environment->intensity, b.environment->intensity);
        d.f("environment.rotation", a.environment->rotation, b.environment->rotation);
    }
    d.eq("energyCompensation", a.energyCompensation, b.energyCompensation);
    d.eq("maxDepth", a.maxDepth, b.maxDepth);
    d.eq("display.exposure", a.display.exposure, b.display.exposure);
    d.eq("display.viewTransform", int(a.display.transform), int(b.display.transform));
    d.eq("raster.shadowMapSize", a.raster.shadowMapSize, b.raster.shadowMapSize);
    d.f("raster.depthBias", a.raster.depthBias, b.raster.depthBias);
    d.f("raster.normalBias", a.raster.normalBias, b.raster.normalBias);
    d.eq("raster.pcf", a.raster.pcf, b.raster.pcf);
    d.eq("raster.reflectionCubeSize", a.raster.reflectionCubeSize, b.raster.reflectionCubeSize);
    d.eq("raster.movingPreview", a.raster.movingPreview, b.raster.movingPreview);
    d.eq("lights.size", a.lights.size(), b.lights.size());
    for (size_t i = 0; i < std::min(a.lights.size(), b.lights.size()); ++i) {
        const Light &x = a.lights[i], &y = b.lights[i];
        std::string p = "lights[" + std::to_string(i) + "]";
        d.eq(p + ".type", x.type, y.type), d.eq(p + ".name", x.name, y.name);
        d.v(p + ".position", x.position, y.position), d.v(p + ".direction", x.direction, y.direction);
        d.v(p + ".color", x.color, y.color), d.v(p + ".attenuation", x.attenuation, y.attenuation);
        d.f(p + ".innerConeAngle", x.innerConeAngle, y.innerConeAngle);
        d.f(p + ".outerConeAngle", x.outerConeAngle, y.outerConeAngle), d.f(p + ".range", x.range, y.range);
    }
    d.eq("spheres.size", a.spheres.size(), b.spheres.size());
    for (size_t i = 0; i < std::min(a.spheres.size(), b.spheres.size()); ++i) {
        const Sphere &x = a.spheres[i], &y = b.spheres[i];
        std::string p = "spheres[" + std::to_string(i) + "]";
        d.eq(p + ".name", x.name, y.name), d.v(p + ".center", x.center, y.center);
        d.f(p + ".radius", x.radius, y.radius), d.material(p + ".material", x.material, y.material);
    }
    d.eq("planes.size", a.planes.size(), b.planes.size());
    for (size_t i = 0; i < std::min(a.planes.size(), b.planes.size()); ++i) {
        const Plane &x = a.planes[i], &y = b.planes[i];
        std::string p = "planes[" + std::to_string(i) + "]";
        d.eq(p + ".name", x.name, y.name), d.v(p + ".normal", x.normal, y.normal);
        d.f(p + ".offset", x.offset, y.offset), d.material(p + ".material", x.material, y.material);
        d.opt(p + ".checker", x.checker, y.checker, [&d](const std::string& n, const Checker& c, const Checker& e) {
            d.v(n + ".md2", c.md2, e.md2), d.f(n + ".size", c.size, e.size);
        });
    }
    d.eq("meshes.size", a.meshes.size(), b.meshes.size());
    for (size_t i = 0; i < std::min(a.meshes.size(), b.meshes.size()); ++i) {
        const Mesh &x = a.meshes[i], &y = b.meshes[i];
        std::string p = "meshes[" + std::to_string(i) + "]";
        d.eq(p + ".name", x.name, y.name), d.eq(p + ".source", x.source, y.source);
        for (int k = 0; k < 16; ++k)
            d.f(p + ".transform[" + std::to_string(k) + "]", x.transform[k / 4][k % 4], y.transform[k / 4][k % 4]);
        d.materialOverride(p + ".material", x.material, y.material);
    }
    return d.fields;
}

inline std::string joined(const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& x : v) s += x + "\n";
    return s;
}

inline std::vector<std::string> gWarnings;
inline void collectWarning(const std::string& line) { gWarnings.push_back(line); }

inline Scene parse(const std::string& text) {
    gWarnings.clear();
    return parseSceneJson(text, "a.json", collectWarning);
}

// Saves, reloads and checks that nothing changed, and that saving again gives the same text.
inline void expectRoundTrip(const Scene& scene) {
    std::string text = sceneToJson(scene);
    Scene back = parse(text);
    EXPECT_EQ(joined(diffScenes(scene, back)), "") << text;
    EXPECT_EQ(sceneToJson(back), text);
    EXPECT_TRUE(gWarnings.empty()) << joined(gWarnings);
}

}  // namespace shadelab::test
