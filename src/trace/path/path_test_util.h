// Shared helpers of the path tracer's tests: a render and its image mean with the mean's standard error, small
// settings, the area-light scene (a floor, a glossy and a diffuse sphere, an emissive sphere and triangle), and
// byte equality of two float images. Test-only; not part of the library.
#pragma once

#include "trace/path/path_render.h"
#include "trace/trace_test_util.h"

#include <cmath>
#include <cstring>
#include <memory>

namespace shadelab::trace::test {

struct PathRun {
    std::unique_ptr<PathRender> render;
    glm::dvec3 mean{0.0};  // over all pixels
    glm::dvec3 se{0.0};    // standard error of that mean
};

inline PathRun pathRun(const Scene& scene, PathSettings s) {
    PathRun r;
    r.render = std::make_unique<PathRender>(std::make_shared<const TraceScene>(scene), s);
    r.render->addSamples(s.spp);
    const double n = double(s.width) * s.height;
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const glm::vec3 m = r.render->mean(x, y), e = r.render->standardError(x, y);
            r.mean += glm::dvec3(m) / n;
            r.se += glm::dvec3(e) * glm::dvec3(e);
        }
    r.se = glm::sqrt(r.se) / n;
    return r;
}

inline PathSettings small(int w, int h, int spp, int maxDepth) {
    PathSettings s;
    s.width = w;
    s.height = h;
    s.spp = spp;
    s.maxDepth = maxDepth;
    s.threads = 2;
    return s;
}

// An area-light scene: a floor, a glossy and a diffuse sphere, and an emissive sphere and emissive triangle.
inline Scene areaLightScene() {
    Scene scene;
    scene.camera.position = glm::vec3(0.0f, 1.5f, 5.0f);
    scene.camera.target = glm::vec3(0.0f, 0.5f, 0.0f);
    scene.camera.fovY = 40.0f;
    scene.model = ShadingModel::BlinnPhong;
    Plane floor;
    floor.material = test::plainMaterial(glm::vec3(0.0f), glm::vec3(0.6f), glm::vec3(0.2f), 30.0f);
    scene.planes.push_back(floor);
    Sphere glossy;
    glossy.center = glm::vec3(-0.8f, 0.6f, 0.0f);
    glossy.radius = 0.6f;
    glossy.material = test::plainMaterial(glm::vec3(0.0f), glm::vec3(0.2f, 0.3f, 0.6f), glm::vec3(0.5f), 60.0f);
    scene.spheres.push_back(glossy);
    Sphere matte = glossy;
    matte.center = glm::vec3(0.8f, 0.5f, 0.3f);
    matte.radius = 0.5f;
    matte.material = test::plainMaterial(glm::vec3(0.0f), glm::vec3(0.7f, 0.4f, 0.2f));
    scene.spheres.push_back(matte);
    Sphere lamp;
    lamp.center = glm::vec3(0.3f, 2.4f, 0.8f);
    lamp.radius = 0.35f;
    lamp.material = test::plainMaterial(glm::vec3(0.0f));
    lamp.material.emission = glm::vec3(6.0f, 5.0f, 4.0f);
    scene.spheres.push_back(lamp);
    Mesh panel;
    panel.parts.push_back(test::makePart({{-2.5f, 0.2f, -1.5f}, {-1.5f, 0.2f, -1.5f}, {-2.0f, 1.6f, -1.0f}}, {0, 1, 2},
                                         glm::vec3(-2.0f, 0.6f, -3.0f)));
    panel.parts[0].material = test::plainMaterial(glm::vec3(0.0f));
    panel.parts[0].material.emission = glm::vec3(1.0f, 3.0f, 2.0f);
    scene.meshes.push_back(panel);
    return scene;
}

inline bool sameBytes(const ImageF& a, const ImageF& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)) == 0;
}

}  // namespace shadelab::trace::test
