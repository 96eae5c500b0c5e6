// Watertight ray–triangle intersection (Woop, Benthin & Wald 2013, "Watertight Ray/Triangle
// Intersection", JCGT 2(1)): a ray through an edge or vertex shared by triangles never falls through.
// Two-sided (no back-face culling). Only the test itself; the BVH that calls it is in mesh_bvh.h.
#pragma once

#include "trace/ray.h"

#include <cmath>
#include <optional>
#include <utility>

namespace shadelab::trace {

// Per-ray constants of the test: the axis permutation and the shear that maps dir onto +z.
struct WatertightRay {
    float org[3];
    int kx, ky, kz;
    float Sx, Sy, Sz;
};

inline WatertightRay makeWatertightRay(const Ray& ray) {
    const float d[3] = {ray.dir.x, ray.dir.y, ray.dir.z};
    WatertightRay w{};
    w.org[0] = ray.origin.x;
    w.org[1] = ray.origin.y;
    w.org[2] = ray.origin.z;
    // Woop et al. §4: z is the axis where |dir| is largest; x and y swap when dir_z < 0 to keep the winding.
    const float ax = std::fabs(d[0]), ay = std::fabs(d[1]), az = std::fabs(d[2]);
    w.kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    w.kx = w.kz == 2 ? 0 : w.kz + 1;
    w.ky = w.kx == 2 ? 0 : w.kx + 1;
    if (d[w.kz] < 0.0f) std::swap(w.kx, w.ky);
    w.Sx = d[w.kx] / d[w.kz];
    w.Sy = d[w.ky] / d[w.kz];
    w.Sz = 1.0f / d[w.kz];
    return w;
}

struct TriangleHit {
    float t;        // ray parameter, > 0
    float b0, b1, b2;  // barycentric weights of v0, v1, v2 (sum 1 up to rounding)
};

// The triangle (v0, v1, v2), each a float[3], hit at 0 < t <= tMax; std::nullopt otherwise.
inline std::optional<TriangleHit> intersectTriangle(const WatertightRay& r, const float* v0, const float* v1,
                                                    const float* v2, float tMax) {
    // Vertices relative to the ray origin.
    const float A[3] = {v0[0] - r.org[0], v0[1] - r.org[1], v0[2] - r.org[2]};
    const float B[3] = {v1[0] - r.org[0], v1[1] - r.org[1], v1[2] - r.org[2]};
    const float C[3] = {v2[0] - r.org[0], v2[1] - r.org[1], v2[2] - r.org[2]};

    // Woop et al. Fig. 5: shear and scale so the ray runs along +z through (0, 0).
    const float Ax = A[r.kx] - r.Sx * A[r.kz], Ay = A[r.ky] - r.Sy * A[r.kz];
    const float Bx = B[r.kx] - r.Sx * B[r.kz], By = B[r.ky] - r.Sy * B[r.kz];
    const float Cx = C[r.kx] - r.Sx * C[r.kz], Cy = C[r.ky] - r.Sy * C[r.kz];

    // Scaled barycentrics: 2D edge functions of the sheared triangle at the origin.
    float U = Cx * By - Cy * Bx;
    float V = Ax * Cy - Ay * Cx;
    float W = Bx * Ay - By * Ax;
    // An edge function that rounds to exactly 0 is recomputed in double, where the float products are
    // exact, so both triangles sharing the edge agree on its sign (Woop et al. §4.2).
    if (U == 0.0f || V == 0.0f || W == 0.0f) {
        U = float(double(Cx) * double(By) - double(Cy) * double(Bx));
        V = float(double(Ax) * double(Cy) - double(Ay) * double(Cx));
        W = float(double(Bx) * double(Ay) - double(By) * double(Ax));
    }
    if ((U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f)) return std::nullopt;
    const float det = U + V + W;
    if (det == 0.0f) return std::nullopt;   // the ray lies in the triangle's plane

    // Scaled hit distance from the sheared z coordinates.
    const float Az = r.Sz * A[r.kz], Bz = r.Sz * B[r.kz], Cz = r.Sz * C[r.kz];
    const float T = U * Az + V * Bz + W * Cz;
    const float rcpDet = 1.0f / det;
    const float t = T * rcpDet;
    if (!(t > 0.0f && t <= tMax)) return std::nullopt;  // also rejects NaN
    return TriangleHit{t, U * rcpDet, V * rcpDet, W * rcpDet};
}

}  // namespace shadelab::trace
