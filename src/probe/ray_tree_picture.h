// The ray view drawn into an 8-bit image (`render --ray-tree X,Y`, for slides): the recorded tree's
// segments projected by the scene's camera as antialiased lines with a dark outline, in the colours the
// viewer gives them, and a ring at the probed pixel, where the primary ray meets the image plane.
#pragma once

#include "image/image.h"
#include "probe/ray_tree_view.h"
#include "scene/scene.h"

namespace shadelab {

// Draws onto `image`, which shows `scene` through its camera at image.width x image.height.
void drawRayTreePicture(Image8& image, const Scene& scene, const RayTreeView& tree);

}  // namespace shadelab
