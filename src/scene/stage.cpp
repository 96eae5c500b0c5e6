#include "scene/stage.h"

#include "scene/scene_load.h"

#include <algorithm>
#include <cmath>

namespace shadelab {

bool hasStage(const Scene& scene) {
    return std::any_of(scene.planes.begin(), scene.planes.end(),
                       [](const Plane& p) { return p.name == kStagePlaneName; });
}

void setStage(Scene& scene, bool on) {
    if (on == hasStage(scene)) return;
    if (!on) {
        scene.planes.erase(std::remove_if(scene.planes.begin(), scene.planes.end(),
                                          [](const Plane& p) { return p.name == kStagePlaneName; }),
                           scene.planes.end());
        scene.background = glm::vec3(0.0f);
        scene.terms.shadows = false;
        return;
    }
    const Bounds b = sceneBounds(scene);
    if (b.empty()) return;
    const glm::vec3 size = b.hi - b.lo;
    const float extent = std::max({size.x, size.y, size.z});
    Plane floor;
    floor.name = kStagePlaneName;
    floor.normal = glm::vec3(0.0f, 1.0f, 0.0f);
    floor.offset = b.lo.y - 1e-3f * extent;  // just under the model: no z-fighting with a flat base
    floor.material.ma = glm::vec3(0.55f);
    floor.material.md = glm::vec3(0.55f);
    floor.material.ms = glm::vec3(0.04f);
    floor.material.s = 8.0f;
    floor.material.baseColor = glm::vec3(0.55f);
    floor.material.roughness = 0.8f;
    // Tiles about a sixth of the model across: enough to read scale and depth, quiet enough not to compete.
    const float tile = std::pow(10.0f, std::round(std::log10(std::max(extent / 6.0f, 1e-6f)) * 2.0f) / 2.0f);
    floor.checker = Checker{glm::vec3(0.42f), tile};
    scene.planes.push_back(floor);
    scene.background = kStageBackground;
    scene.terms.shadows = true;
}

}  // namespace shadelab
