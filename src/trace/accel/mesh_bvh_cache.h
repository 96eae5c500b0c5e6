// MeshBvhCache: the last MeshBvh built, handed to every thread that asks for the same mesh geometry (the
// viewer's reference workers and its probe), so a scene's triangles are sorted into a BVH once.
#pragma once

#include "scene/scene.h"
#include "trace/accel/mesh_bvh.h"

#include <memory>
#include <mutex>

namespace shadelab::trace {

class MeshBvhCache {
public:
    // The cached BVH when it matches `scene` (MeshBvh::matches, by geometry identity); otherwise builds
    // one, caches it and returns it. Thread-safe; a build holds the lock, so two callers never build twice.
    std::shared_ptr<const MeshBvh> get(const Scene& scene);

private:
    std::mutex mutex_;
    std::shared_ptr<const MeshBvh> bvh_;
};

}  // namespace shadelab::trace
