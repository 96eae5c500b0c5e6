// The reference depth of a raster-against-reference comparison.
#include "compare/comparison.h"

#include <algorithm>

namespace shadelab {

int comparisonDepth(const Scene& scene, std::optional<int> requested) {
    return requested.value_or(std::min(scene.maxDepth, 1));
}

}  // namespace shadelab
