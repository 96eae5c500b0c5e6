// whiteFurnaceScene: every material white, lights off, a uniform environment of radiance 1.
#include "scene/white_furnace.h"

#include <algorithm>

namespace shadelab {
namespace {

void whiten(Material& m) {
    const float ms = std::clamp((m.ms.x + m.ms.y + m.ms.z) / 3.0f, 0.0f, 1.0f);
    m.ma = glm::vec3(1.0f);
    m.ms = glm::vec3(ms);
    m.md = glm::vec3(1.0f - ms);
    m.baseColor = glm::vec3(1.0f);
    m.kr = glm::vec3(0.0f);
    m.kt = glm::vec3(0.0f);
}

}  // namespace

Scene whiteFurnaceScene(const Scene& scene, const WhiteFurnaceSettings& settings) {
    Scene f = scene;
    const glm::vec3 radiance(std::max(settings.radiance, 0.0f));
    f.background = radiance;
    // A uniform environment of that radiance: under pbr it lights the surfaces through image-based lighting
    // (it replaces Ia·ma there), so GGX's energy loss shows as rings and energyCompensation removes them.
    // Phong and Blinn-Phong keep the lecture's Ia·ma as the stand-in for it.
    f.environment = Environment{};
    f.ambient = settings.ambient ? radiance : glm::vec3(0.0f);
    f.lights.clear();
    f.terms.ambient = settings.ambient;
    f.terms.diffuse = f.terms.specular = true;
    f.terms.shadows = f.terms.reflections = false;
    for (Sphere& s : f.spheres) whiten(s.material);
    for (Plane& p : f.planes) {
        whiten(p.material);
        if (p.checker) p.checker->md2 = p.material.md;
    }
    for (Mesh& mesh : f.meshes) {
        // One white for every part, from the first part's ms (the viewer edits a mesh as one material), written
        // into the override too, so a saved furnace scene loads as one.
        Material white = mesh.parts.empty() ? Material{} : mesh.parts.front().material;
        whiten(white);
        MaterialOverride& o = mesh.material;
        o.ma = white.ma, o.md = white.md, o.ms = white.ms, o.kr = white.kr, o.kt = white.kt;
        o.baseColor = white.baseColor;
        for (MeshPart& part : mesh.parts) o.applyTo(part.material);
    }
    return f;
}

Scene leaveWhiteFurnace(const Scene& saved, const Scene& furnace) {
    Scene s = saved;
    s.camera = furnace.camera;
    s.model = furnace.model;
    s.normalized = furnace.normalized;
    return s;
}

}  // namespace shadelab
