// The lecture's intersection algebra for one traced ray, with the tracer's own numbers: the ray
// r(t) = o + t·d solved against the object it hit (or the one it was aimed at), written as the lecture
// writes it. The sphere and plane solutions repeat lighting.glsl's intersectSphere / intersectPlane
// expression by expression, so their t is the tracer's t bit for bit; the triangle's is Möller–Trumbore
// (1997) in double precision beside the tracer's watertight test, and agrees with it to rounding.
#pragma once

#include "trace/ray.h"
#include "trace/trace_scene.h"

#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace shadelab::trace {

// ‖o + t·d − c‖² − r² = 0, i.e. a·t² + b·t + c = 0 with a = d·d (1: d is unit), b = 2 d·(o − c),
// c = ‖o − c‖² − r². The tracer works with the half-b form b' = d·(o − c) and Δ/4 = r² − ‖(o − c) − b'd‖²
// (the same discriminant, computed without cancellation), and takes the second root from Vieta's c/q.
struct SphereAlgebra {
    glm::vec3 center{0.0f};
    float radius = 0.0f;
    float a = 0.0f, b = 0.0f, c = 0.0f;  // the lecture's coefficients
    float discriminant = 0.0f;           // b² − 4ac (4 × the tracer's Δ/4)
    bool real = false;                   // discriminant >= 0: the line meets the sphere
    float tNear = 0.0f, tFar = 0.0f;     // the two roots, tNear <= tFar (when real)
    int taken = 0;                       // 0 none, 1 tNear, 2 tFar
    float t = -1.0f;                     // the root taken, -1 none: exactly intersectSphere's answer
};

// nᵀ(o + t·d) − δ = 0, so t = (δ − nᵀo) / (nᵀd); nᵀd = 0 (to 1e-12) means the ray runs parallel to the plane.
struct PlaneAlgebra {
    glm::vec3 normal{0.0f};
    float offset = 0.0f;  // δ
    float nDotO = 0.0f, nDotD = 0.0f;
    bool parallel = false;
    float t = -1.0f;  // the tracer's t, -1 when parallel or behind the origin
};

// o + t·d = (1 − u − v)·A + u·B + v·C: t and the barycentrics (b0, b1, b2) = (1 − u − v, u, v).
struct TriangleAlgebra {
    glm::vec3 A{0.0f}, B{0.0f}, C{0.0f};
    double t = -1.0, b0 = 0.0, b1 = 0.0, b2 = 0.0;
    bool parallel = false;  // the ray lies in the triangle's plane
};

SphereAlgebra sphereAlgebra(const Ray& ray, const glm::vec3& center, float radius, float tMin = 0.0f);
PlaneAlgebra planeAlgebra(const Ray& ray, const glm::vec3& normal, float offset, float tMin = 0.0f);
TriangleAlgebra triangleAlgebra(const Ray& ray, const glm::vec3& A, const glm::vec3& B, const glm::vec3& C);

// The algebra of `ray` against the object of `hit`, in the lecture's words with its numbers, one line
// per step ("o = (…)", "a·t² + b·t + c = 0 with a = …", "Δ = b² − 4ac = …", "roots …", "t = …, taken
// because …"). The ray's hit t is the number it ends with.
std::vector<std::string> rayAlgebraLines(const TraceScene& scene, const Ray& ray, const Hit& hit);

}  // namespace shadelab::trace
