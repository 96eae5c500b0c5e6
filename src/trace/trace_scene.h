// TraceScene: a Scene made ready to trace. It holds a copy of the scene (O(objects): mesh geometry is
// shared), the mesh BVH (shared, geometry only), a BVH over the spheres, and the secondary-ray epsilon.
// Rebuild it when anything changes; reuse the mesh BVH while the mesh geometry is the same.
#pragma once

#include "scene/scene.h"
#include "trace/accel/mesh_bvh.h"
#include "trace/accel/sphere_set.h"
#include "trace/ray.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace shadelab::trace {

enum class HitKind : uint8_t { Sphere, Plane, Triangle };

// A ray's nearest hit. For triangles `index` is a MeshBvh slot and b0..b2 its barycentrics.
struct Hit {
    float t = 0.0f;  // ray parameter
    HitKind kind = HitKind::Sphere;
    uint32_t index = 0;  // sphere index, plane index, or MeshBvh slot
    float b0 = 0.0f, b1 = 0.0f, b2 = 0.0f;
};

class TraceScene {
public:
    // Builds everything, the mesh BVH included.
    explicit TraceScene(const Scene& scene);
    // Reuses `meshes`, which must have been built over this scene's very mesh geometry (MeshBvh::matches,
    // by identity): the cheap path when only materials, lights, camera, spheres or planes changed.
    TraceScene(const Scene& scene, std::shared_ptr<const MeshBvh> meshes);

    // The scene as given: everything shading reads.
    const Scene& scene() const { return scene_; }
    const std::shared_ptr<const MeshBvh>& meshBvh() const { return meshes_; }

    // Offset of secondary-ray origins along the normal, world units (scene/ray_epsilon.h).
    float epsilon() const { return epsilon_; }

    // Nearest hit with t > 0. An exact tie in t goes to spheres, then planes, then triangles, and within
    // each kind to the lower index in scene order: the answer does not depend on traversal order.
    std::optional<Hit> intersect(const Ray& ray) const;
    // Whether anything lies on the ray at 0 < t < tMax. Transmissive surfaces block too (hard shadows of
    // glass are black, a documented simplification of Whitted 1980's kt-weighted shadow rays).
    bool occluded(const Ray& ray, float tMax) const;
    // intersect(rays[k]) for up to eight rays at once (bit k of `valid`), into out[k]; the meshes take them as one
    // packet (MeshBvh::closestHit8), which pays for coherent rays: camera rays of neighbouring pixels.
    void intersect8(const Ray* rays, unsigned valid, std::optional<Hit>* out) const;
    // occluded(rays[k], tMax[k]) for up to eight rays at once: bit k set where ray k is occluded.
    unsigned occluded8(const Ray* rays, const float* tMax, unsigned valid) const;

    // Coverage id of the object hit (scene/coverage.h).
    uint32_t coverageId(const Hit& hit) const;
    const Material& material(const Hit& hit) const;
    // The mesh part a triangle hit lies on.
    const MeshPart& meshPart(const Hit& hit) const {
        const std::pair<uint32_t, uint32_t> ref = partRef_[meshes_->part(hit.index)];
        return scene_.meshes[ref.first].parts[ref.second];
    }
    // The triangle a hit lies on, as an index into its part's geometry (indices[3 t .. 3 t + 2]).
    uint32_t triangleInPart(const Hit& hit) const {
        return meshes_->sourceTriangle(hit.index) - partFirstTriangle_[meshes_->part(hit.index)];
    }

private:
    void prepare();
    // The nearest sphere or plane hit (t > 0) into `best` (best.t is INFINITY without one); false without one.
    bool nearestAnalytic(const Ray& ray, Hit& best) const;
    // Whether a plane or a sphere lies on the ray at 0 < t < tMax.
    bool occludedByAnalytic(const Ray& ray, float tMax) const;

    Scene scene_;
    std::shared_ptr<const MeshBvh> meshes_;
    std::optional<SphereSet> spheres_;
    std::vector<std::pair<uint32_t, uint32_t>> partRef_;  // (mesh, part) of each flattened mesh part
    std::vector<uint32_t> partFirstTriangle_;             // MeshBvh::sourceTriangle of each part's first
    float epsilon_ = 1e-4f;
};

}  // namespace shadelab::trace
