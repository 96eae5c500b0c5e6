// The lighting probe (teaching): for one pixel, what the primary ray hits and every quantity of the
// lighting model there (N, V, and per light L, R, H, the dot products and each term), for Phong,
// Blinn-Phong and pbr side by side. Pure C++ over the tracer's scene and the shared shading code; no GL. The
// viewer's probe panel and diagram, its probe report and Python's shadelab.probe all read it.
#pragma once

#include "scene/object_ref.h"
#include "scene/scene.h"
#include "trace/trace_scene.h"

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace shadelab {

// The surface point a probe is anchored to, so that it stays on the point while the camera moves.
struct ProbeAnchor {
    uint32_t objectId = 0;  // coverage id of the object probed; 0 = not anchored yet
    glm::vec3 point{0.0f};  // the hit point, world units (objects do not move in the viewer)
};

struct ProbeLight {
    std::string name;
    glm::vec3 L{0.0f}, R{0.0f}, H{0.0f};  // unit; L toward the light, R = 2N(N·L) − L, H = normalize(L + V)
    float NoL = 0.0f, RoV = 0.0f, NoH = 0.0f;
    glm::vec3 Il{0.0f};             // intensity arriving at P (attenuation applied), linear RGB
    float visibility = 1.0f;        // vis_l: the tracer's shadow ray, 1 lit, 0 blocked; 1 with shadows off
    float specPhong = 0.0f;         // max(R·V, 0)^s, 0 on the unlit side
    float specBlinn = 0.0f;         // max(N·H, 0)^s, 0 on the unlit side
    glm::vec3 diffuse{0.0f};        // vis_l · Il ⊙ md · max(N·L, 0)
    glm::vec3 specularPhong{0.0f};  // vis_l · Il ⊙ ms · specPhong
    glm::vec3 specularBlinn{0.0f};  // vis_l · Il ⊙ ms · specBlinn
    // pbr (glTF metallic-roughness, lighting.glsl): the BRDF's factors and this light's two parts.
    float D = 0.0f;              // D_GGX(N·H, α)
    float Vis = 0.0f;            // V_SmithGGXCorrelated(N·V, N·L, α) = G2 / (4 N·L N·V)
    glm::vec3 F{0.0f};           // F_Schlick(F0, V·H)
    glm::vec3 diffusePbr{0.0f};  // vis_l · Il ⊙ (1 − F) ⊙ c_diff · N·L (plain c_diff · N·L with specular off)
    glm::vec3 specularPbr{0.0f};  // vis_l · Il ⊙ π · D · Vis · F · N·L
    // Under glTF's transmission, a light behind the surface through it: Il ⊙ c_diff·t·tint · π·D·V(L′, V)·|N·L|.
    glm::vec3 transmissionPbr{0.0f};
    // Under glTF's sheen the three above keep sheenScaling and this is the sheen's lobe, c·π·f_sheen·Il·N·L.
    glm::vec3 sheenPbr{0.0f};
    // Under glTF's clear coat the parts above keep (1 − c·Fc) and this is the coat's lobe, c·π·f_coat·Il·Nc·L.
    glm::vec3 clearcoatPbr{0.0f};
    // disney (shadeLightDisney): this light's part through each lobe, vis_l included; they sum to its term.
    glm::vec3 diffuseDisney{0.0f};    // the diffuse with its retro-reflection and subsurface blend
    glm::vec3 sheenDisney{0.0f};      // the sheen
    glm::vec3 specularDisney{0.0f};   // the anisotropic GGX lobe
    glm::vec3 clearcoatDisney{0.0f};  // the clearcoat's GTR1 lobe
};

struct ProbeResult {
    int x = 0, y = 0;           // pixel, row 0 at the top
    int width = 0, height = 0;  // image size the pixel belongs to
    bool hit = false;
    uint32_t objectId = 0;  // coverage id (scene/coverage.h); 0 = background
    ObjectKind kind = ObjectKind::None;
    std::string label;                    // objectLabel()
    float t = 0.0f;                       // ray parameter of the hit, world units
    glm::vec3 P{0.0f}, N{0.0f}, V{0.0f};  // hit point; unit normal facing the viewer; unit vector to the eye
    Material material;                    // the object's, with the checker tile's md at P
    glm::vec3 ambient{0.0f};              // Ia ⊙ ma
    std::vector<ProbeLight> lights;
    bool unlit = false;                            // no light term on: the totals are the unlit colour (step 0)
    glm::vec3 totalPhong{0.0f};                    // shadeLocal with the scene's term switches, Phong
    glm::vec3 totalBlinn{0.0f};                    // the same, Blinn-Phong
    glm::vec3 totalPbr{0.0f};                      // the same, pbr
    glm::vec3 totalDisney{0.0f};                   // the same, disney
    glm::vec3 pbrDiffuseColor{0.0f}, pbrF0{0.0f};  // c_diff (of the checker tile at P) and F0 (shading::surfaceParams)
    glm::vec3 disneyF0{0.0f};                      // disney's own F0 there (disneySpecularF0: specular, specularTint)
};

// Asks the tracer about pixel (x, y) of a width x height image: its primary ray through the pixel centre
// (trace::sampleRay), its nearest hit (TraceScene::intersect, the reference's BVH), its surface
// (WhittedIntegrator::surfaceAt: normal flipped to the viewer, checker applied) and, with the shadows
// term on, each light's vis_l from its shadow ray (WhittedIntegrator::visibility, the same origin
// offset): the exact answer the rasterizer's shadow maps approximate. Then evaluates every local term
// with shading::shadeLight / shadeLocal, for Phong, Blinn-Phong, pbr and disney side by side.
ProbeResult probePixel(const trace::TraceScene& scene, int width, int height, int x, int y);

// The probe at an anchored point seen from the scene's current camera: a ray from the eye's direction
// that starts just short of the point, so the point is probed even when something now hides it. `x`, `y`
// are the pixel it projects to. No hit when the object there is not the anchored one any more.
ProbeResult probeAnchor(const trace::TraceScene& scene, int width, int height, const ProbeAnchor& anchor);

struct RayTreeView;

// The JSON written by the script's "probeReport" action and --probe-report (docs/viewer.md); with the ray
// tree when it is shown (its rays as rayTreeRayLine writes them, and each ray's fields).
std::string probeReportJson(const ProbeResult& probe, const Scene& scene, uint32_t coverageId,
                            const RayTreeView* rayTree = nullptr);

}  // namespace shadelab
