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
    float ox, oy, oz;  // org[kx], org[ky], org[kz]: the test reads only the permuted components it needs
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
    w.ox = w.org[w.kx];
    w.oy = w.org[w.ky];
    w.oz = w.org[w.kz];
    return w;
}

struct TriangleHit {
    float t;           // ray parameter, > 0
    float b0, b1, b2;  // barycentric weights of v0, v1, v2 (sum 1 up to rounding)
};

// The test itself: true with `out` set when the triangle (v0, v1, v2), each a float[3], is hit at 0 < t <= tMax.
// A template on a tag type only so that bvh_traverse_avx2.cpp can instantiate its own copy (with a tag of its
// own) for AVX2 without the linker ever taking it for the baseline one; plain IEEE float and double operations
// with no library calls, so every copy rounds alike.
template <typename Tag>
inline bool intersectTriangleT(const WatertightRay& r, const float* v0, const float* v1, const float* v2, float tMax,
                               TriangleHit& out) {
    // Vertices relative to the ray origin, read straight in the permuted order (x, y, z = kx, ky, kz).
    const int kx = r.kx, ky = r.ky, kz = r.kz;
    const float Akx = v0[kx] - r.ox, Aky = v0[ky] - r.oy, Akz = v0[kz] - r.oz;
    const float Bkx = v1[kx] - r.ox, Bky = v1[ky] - r.oy, Bkz = v1[kz] - r.oz;
    const float Ckx = v2[kx] - r.ox, Cky = v2[ky] - r.oy, Ckz = v2[kz] - r.oz;

    // Woop et al. Fig. 5: shear and scale so the ray runs along +z through (0, 0).
    const float Ax = Akx - r.Sx * Akz, Ay = Aky - r.Sy * Akz;
    const float Bx = Bkx - r.Sx * Bkz, By = Bky - r.Sy * Bkz;
    const float Cx = Ckx - r.Sx * Ckz, Cy = Cky - r.Sy * Ckz;

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
    if ((U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f)) return false;
    const float det = U + V + W;
    if (det == 0.0f) return false;  // the ray lies in the triangle's plane

    // Scaled hit distance from the sheared z coordinates.
    const float Az = r.Sz * Akz, Bz = r.Sz * Bkz, Cz = r.Sz * Ckz;
    const float T = U * Az + V * Bz + W * Cz;
    const float rcpDet = 1.0f / det;
    const float t = T * rcpDet;
    if (!(t > 0.0f && t <= tMax)) return false;  // also rejects NaN
    out = TriangleHit{t, U * rcpDet, V * rcpDet, W * rcpDet};
    return true;
}

namespace watertight_detail {
struct BaselineTag {};
}  // namespace watertight_detail

// The triangle (v0, v1, v2), each a float[3], hit at 0 < t <= tMax; std::nullopt otherwise.
inline std::optional<TriangleHit> intersectTriangle(const WatertightRay& r, const float* v0, const float* v1,
                                                    const float* v2, float tMax) {
    TriangleHit h;
    if (!intersectTriangleT<watertight_detail::BaselineTag>(r, v0, v1, v2, tMax, h)) return std::nullopt;
    return h;
}

}  // namespace shadelab::trace
