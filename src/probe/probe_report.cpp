// probeReportJson: the probe as JSON for scripts and tests (field names follow design.md's vocabulary).
#include "probe/probe.h"

#include "probe/ray_tree_view.h"

#include <cmath>

#include <nlohmann/json.hpp>

namespace shadelab {
namespace {

nlohmann::json vec(const glm::vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

const char* kindName(ObjectKind k) {
    switch (k) {
        case ObjectKind::Sphere: return "sphere";
        case ObjectKind::Plane: return "plane";
        case ObjectKind::Mesh: return "mesh";
        case ObjectKind::None: break;
    }
    return "background";
}

}  // namespace

std::string probeReportJson(const ProbeResult& p, const Scene& scene, uint32_t coverageId, const RayTreeView* rayTree) {
    nlohmann::json j;
    j["pixel"] = {p.x, p.y};
    j["size"] = {p.width, p.height};
    j["hit"] = p.hit;
    j["coverage_id"] = coverageId;  // what the rasterizer's coverage buffer holds at the pixel
    j["model"] = toString(scene.model);
    if (!p.hit) return j.dump(2) + "\n";
    j["shaded_with"] = toString(modelOf(p.material, scene.model));  // the material's own model, else the scene's
    j["object"] = {{"id", p.objectId}, {"kind", kindName(p.kind)}, {"label", p.label}};
    j["t"] = p.t;
    j["P"] = vec(p.P);
    j["N"] = vec(p.N);
    j["V"] = vec(p.V);
    const Material& m = p.material;
    j["material"] = {{"ma", vec(m.ma)},
                     {"md", vec(m.md)},
                     {"ms", vec(m.ms)},
                     {"s", m.s},
                     {"baseColor", vec(m.baseColor)},
                     {"metallic", m.metallic},
                     {"roughness", m.roughness},
                     {"pbr_diffuse_color", vec(p.pbrDiffuseColor)},
                     {"pbr_f0", vec(p.pbrF0)},
                     {"disney_f0", vec(p.disneyF0)}};
    nlohmann::json derived = nlohmann::json::array();  // fields derived from the other model's (scene-format.md)
    for (const auto& entry : kMaterialFieldNames)
        if (m.derived & entry.value) derived.push_back(entry.name);
    j["material"]["derived"] = std::move(derived);
    j["ambient"] = vec(p.ambient);
    nlohmann::json lights = nlohmann::json::array();
    for (const ProbeLight& l : p.lights)
        lights.push_back({{"name", l.name},
                          {"L", vec(l.L)},
                          {"R", vec(l.R)},
                          {"H", vec(l.H)},
                          {"NoL", l.NoL},
                          {"RoV", l.RoV},
                          {"NoH", l.NoH},
                          {"Il", vec(l.Il)},
                          {"visibility", l.visibility},
                          {"spec_phong", l.specPhong},
                          {"spec_blinn", l.specBlinn},
                          {"diffuse", vec(l.diffuse)},
                          {"specular_phong", vec(l.specularPhong)},
                          {"specular_blinn", vec(l.specularBlinn)},
                          {"D", l.D},
                          {"Vis", l.Vis},
                          {"F", vec(l.F)},
                          {"diffuse_pbr", vec(l.diffusePbr)},
                          {"specular_pbr", vec(l.specularPbr)},
                          {"sheen_pbr", vec(l.sheenPbr)},
                          {"transmission_pbr", vec(l.transmissionPbr)},
                          {"clearcoat_pbr", vec(l.clearcoatPbr)},
                          {"diffuse_disney", vec(l.diffuseDisney)},
                          {"sheen_disney", vec(l.sheenDisney)},
                          {"specular_disney", vec(l.specularDisney)},
                          {"clearcoat_disney", vec(l.clearcoatDisney)}});
    j["lights"] = lights;
    j["total"] = {{"phong", vec(p.totalPhong)},
                  {"blinn_phong", vec(p.totalBlinn)},
                  {"pbr", vec(p.totalPbr)},
                  {"disney", vec(p.totalDisney)}};
    j["unlit"] = p.unlit;
    if (rayTree) {
        nlohmann::json rays = nlohmann::json::array();
        for (size_t k = 0; k < rayTree->record.rays.size(); ++k) {
            const trace::TreeRay& r = rayTree->record.rays[k];
            nlohmann::json ray = {{"line", rayTreeRayLine(scene, rayTree->record, k)},
                                  {"kind", trace::treeRayKindName(r.kind)},
                                  {"parent", r.parent},
                                  {"depth", r.depth},
                                  {"origin", vec(r.ray.origin)},
                                  {"dir", vec(r.ray.dir)},
                                  {"object", r.hitId}};
            if (r.hit) ray["t"] = r.hit->t;
            if (r.kind == trace::TreeRayKind::Shadow) {
                ray["light"] = r.light;
                ray["blocked"] = r.blocked;
                if (std::isfinite(r.tMax)) ray["tMax"] = r.tMax;
            }
            rays.push_back(ray);
        }
        j["ray_tree"] = {
            {"pixel", {rayTree->x, rayTree->y}}, {"size", {rayTree->width, rayTree->height}}, {"rays", rays}};
    }
    return j.dump(2) + "\n";
}

}  // namespace shadelab
