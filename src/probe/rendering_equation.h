// The rendering equation at a probed pixel (teaching): L_out(ω_out) = L_e + ∫ f(ω_in, ω_out) L_in(ω_in)
// cos θ_in dω_in, shown as three small images of the hemisphere over the hit (the incoming radiance, the
// BRDF times the cosine, their product) and the integral's value beside the pixel's. Both are computed by
// the tracer: the surface, BRDF and lights of the path tracer (PathBsdf: the lecture's local model read as a
// BRDF, f·cos θ = shadeLight(Il = 1)/π), and, under global illumination, its paths for L_in.
//
// Point, spot and directional lights are deltas: they are no area of the hemisphere, so their part of the
// integral is a sum, Σ_l π f(ω_l) Il cos θ_l vis_l, marked where they fall. Under the local models that sum
// plus the constant Ia·ma is the whole pixel, and L_in shows the ambient as a constant sky; under the path
// tracer L_in is the whole scene seen from the point, and the images' integral is the indirect and
// area-emitter light the ambient stands in for. No GL.
#pragma once

#include "trace/trace_scene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace shadelab {

struct HemisphereLight {
    int light = 0;         // index into the scene's lights
    glm::vec2 at{0.0f};    // where its direction falls in the images, [0, 1]², (0, 0) the top left
    glm::vec3 term{0.0f};  // π f(ω_l) Il cos θ_l vis_l: its part of the pixel
    bool visible = true;   // vis_l (the shadow ray); false: blocked
    bool above = true;     // the light is above the surface (else its term is 0 and it is not drawn)
};

struct RenderingEquation {
    bool hit = false;
    bool global = false;  // L_in from the path tracer (else the local model's ambient sky)
    int size = 0;         // each image is size x size, the hemisphere mapped equal-area (every texel 2π/size² sr)
    std::vector<glm::vec3> incoming;  // L_in(ω), row 0 at the top (ω toward +b), column 0 at −t
    std::vector<glm::vec3> brdfCos;   // f(ω, ω_out) cos θ (non-delta lobes)
    std::vector<glm::vec3> product;   // their product
    std::vector<HemisphereLight> lights;
    glm::vec3 imageIntegral{0.0f};  // Σ product · 2π/size²: the part of the integral the images hold
    glm::vec3 imageError{0.0f};     // its standard error (global; 0 for the local sky, which has no noise)
    glm::vec3 lightSum{0.0f};       // Σ of the lights' terms
    glm::vec3 ambient{0.0f};        // Ia·ma (local models), else 0
    glm::vec3 emission{0.0f};       // L_e of the surface itself
    glm::vec3 total{0.0f};          // L_out: global: emission + lightSum + imageIntegral; local: ambient +
                                    // lightSum (+ emission); the pixel's value
    bool deltaLobes = false;        // the surface also mirrors or refracts (kr, kt): those rays are not drawn
};

// The rendering equation at the surface under pixel (x, y)'s centre of a width x height image of the scene's
// camera. `global`: L_in by `samplesPerTexel` paths per texel (stratified within it), at the scene's depth
// less one; else the local model. Deterministic for given arguments.
// 16 paths per texel of 64²: about 0.1 s on one core for the Cornell box, a standard error of ~1 % there.
inline constexpr int kDefaultPathsPerTexel = 16;
RenderingEquation renderingEquationAt(const trace::TraceScene& scene, int width, int height, int x, int y, bool global,
                                      int size = 64, int samplesPerTexel = kDefaultPathsPerTexel);

// The equal-area map of the images: a point of [0, 1]² (image coordinates) to a unit direction in the
// normal's frame (z along the normal), and its inverse for a direction with z >= 0. Shirley & Chiu's
// concentric square-to-disc map (1997), then Lambert's azimuthal projection of the disc onto the hemisphere.
glm::vec3 hemisphereDirection(glm::vec2 uv);
glm::vec2 hemisphereTexel(const glm::vec3& local);

}  // namespace shadelab
