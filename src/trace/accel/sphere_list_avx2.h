// SphereList's flat pass in AVX2: eight spheres per step, the same operations as shading::intersectSphere in
// each lane (no fused multiply-adds: the file is built with -mavx2 and -ffp-contract=off), so the hits are the
// scalar function's bit for bit. Compiled alone with -mavx2 (sphere_list_avx2.cpp); call only where
// bvhIsaAvailable(BvhIsa::Avx2).
#pragma once

#include "trace/accel/sphere_group.h"
#include "trace/ray.h"

#include <cstddef>

namespace shadelab::trace {

// The nearest hit at tMin < t < tMax over `count` groups, into `best` (an exact tie goes to the lower index);
// false, with `best` left alone, when there is none.
bool closestSphereAvx2(const SphereGroup* groups, size_t count, const Ray& ray, float tMin, float tMax,
                       SphereHit& best);
// Whether some sphere is hit at tMin < t < tMax.
bool anySphereAvx2(const SphereGroup* groups, size_t count, const Ray& ray, float tMin, float tMax);

}  // namespace shadelab::trace
