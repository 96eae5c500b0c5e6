// MeshBvhCache: one slot, replaced when the geometry changes.
#include "trace/accel/mesh_bvh_cache.h"

namespace shadelab::trace {

std::shared_ptr<const MeshBvh> MeshBvhCache::get(const Scene& scene) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!bvh_ || !bvh_->matches(scene)) {
        bvh_.reset();  // free the old tree before building the new one
        bvh_ = std::make_shared<const MeshBvh>(scene);
    }
    return bvh_;
}

}  // namespace shadelab::trace
