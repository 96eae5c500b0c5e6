// The Embree 3 baseline of trace_bench (optional: built only with SHADELAB_HAVE_EMBREE, never used by shadelab
// itself): a scene's triangles as one Embree geometry with its BVH, and Embree's ray-hit record for a ray.
#pragma once

#include "scene/scene.h"
#include "trace/ray.h"

#include <embree3/rtcore.h>

#include <chrono>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

namespace shadelab::bench {

struct EmbreeScene {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    std::vector<glm::vec3> normals;  // geometric, per triangle, for the shadow-ray offset
    double commitSeconds = 0.0;      // rtcCommitScene alone: Embree's BVH build

    explicit EmbreeScene(const Scene& s) {
        device = rtcNewDevice(nullptr);
        scene = rtcNewScene(device);
        RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        size_t nv = 0, nt = 0;
        for (const Mesh& m : s.meshes)
            for (const MeshPart& p : m.parts) {
                nv += p.geometry->positions.size();
                nt += p.triangleCount();
            }
        auto* v = static_cast<float*>(
            rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), nv));
        auto* idx = static_cast<unsigned*>(
            rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), nt));
        size_t vb = 0, ti = 0;
        for (const Mesh& m : s.meshes)
            for (const MeshPart& part : m.parts) {
                const MeshGeometry& p = *part.geometry;
                for (size_t k = 0; k < p.positions.size(); ++k) {
                    v[3 * (vb + k) + 0] = p.positions[k].x;
                    v[3 * (vb + k) + 1] = p.positions[k].y;
                    v[3 * (vb + k) + 2] = p.positions[k].z;
                }
                for (size_t t = 0; t < p.triangleCount(); ++t, ++ti) {
                    for (int c = 0; c < 3; ++c) idx[3 * ti + size_t(c)] = unsigned(vb + p.indices[3 * t + size_t(c)]);
                    const glm::vec3 a = p.positions[p.indices[3 * t]], b = p.positions[p.indices[3 * t + 1]],
                                    c = p.positions[p.indices[3 * t + 2]];
                    normals.push_back(glm::cross(b - a, c - a));
                }
                vb += p.positions.size();
            }
        rtcCommitGeometry(geom);
        rtcAttachGeometry(scene, geom);
        rtcReleaseGeometry(geom);
        const auto t0 = std::chrono::steady_clock::now();
        rtcCommitScene(scene);
        commitSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    ~EmbreeScene() {
        rtcReleaseScene(scene);
        rtcReleaseDevice(device);
    }
};

// Embree's ray-hit record for `ray`, from t = 0 to infinity, with no hit yet.
inline RTCRayHit embreeRayHit(const trace::Ray& ray) {
    RTCRayHit rh{};
    rh.ray.org_x = ray.origin.x;
    rh.ray.org_y = ray.origin.y;
    rh.ray.org_z = ray.origin.z;
    rh.ray.dir_x = ray.dir.x;
    rh.ray.dir_y = ray.dir.y;
    rh.ray.dir_z = ray.dir.z;
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = INFINITY;
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

}  // namespace shadelab::bench
