// The stage (docs/viewer.md, "Opening files and the stage"): what a bare glTF model gets in the viewer so it looks
// placed rather than floating in black: a soft checker floor just under its bounds, a soft grey background, and
// shadows. A plain function of the scene, so the viewer's switch, the tests and a saved scene all see the same thing;
// the floor is the plane named "stage".
#pragma once

#include "scene/scene.h"

namespace shadelab {

inline constexpr const char* kStagePlaneName = "stage";
inline constexpr glm::vec3 kStageBackground{0.30f, 0.32f, 0.36f};

bool hasStage(const Scene& scene);
// On: adds the floor under the bounds of the spheres and meshes (none when nothing is bounded), the
// background and the shadows term. Off: removes the floor and restores a black background and no shadows,
// as a bare model opens in `shadelab render`. Does nothing when already in that state.
void setStage(Scene& scene, bool on);

}  // namespace shadelab
