// The viewer's probe, no window: what it reports at a pixel equals the shared C++ shading
// and the integrator's local terms under every model, it finds planes, meshes and the background, and its
// shadow-ray visibility is the tracer's.
#include "app/viewer_state.h"
#include "app_test_util.h"
#include "probe/probe.h"
#include "scene/scene_load.h"
#include "scene/view.h"
#include "shading/lighting.h"
#include "shading/local_illumination.h"
#include "test_output.h"
#include "trace/integrator.h"
#include "trace/tile_renderer.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

using namespace shadelab;
using namespace shadelab::app;
using namespace shadelab::test;

// ---- Probe ---------------------------------------------------------------------------------------------

TEST(AppState, ProbeOnSphereEqualsSharedShading) {
    ViewerState s = defaultState();
    const int w = 640, h = 360;
    const uint32_t green = idOf(s, "matte green");
    const Sphere& sphere = s.scene.spheres[green - 1];
    const glm::ivec2 px = pixelOf(s.scene, w, h, sphere.center + glm::vec3(0.3f, 0.3f, 0.0f));
    const ProbeResult p = probePixel(trace::TraceScene(s.scene), w, h, px.x, px.y);
    ASSERT_TRUE(p.hit);
    EXPECT_EQ(p.objectId, green);
    EXPECT_EQ(p.kind, ObjectKind::Sphere);

    // Independently: the same ray, hit and vectors from the shared functions.
    const ViewSetup v = makeViewSetup(s.scene, w, h);
    const glm::vec3 dir = shading::cameraRayDirection(v.forward, v.right, v.up, v.tanHalfFovY, float(w), float(h),
                                                      px.x + 0.5f, px.y + 0.5f);
    const float t = shading::intersectSphere(v.eye, dir, sphere.center, sphere.radius, 0.0f);
    const glm::vec3 P = v.eye + t * dir;
    const glm::vec3 N = glm::normalize(shading::faceForward((P - sphere.center) / sphere.radius, -dir));
    ASSERT_EQ(p.lights.size(), s.scene.lights.size());
    glm::vec3 sum = shading::shadeAmbient(s.scene.ambient, sphere.material.ma, true);
    for (size_t i = 0; i < s.scene.lights.size(); ++i) {
        const glm::vec3 L = glm::normalize(s.scene.lights[i].position - P);
        EXPECT_NEAR(p.lights[i].NoL, glm::dot(N, L), 1e-6f) << i;
        EXPECT_NEAR(p.lights[i].RoV, glm::dot(shading::reflectLight(N, L), -dir), 1e-5f) << i;
        sum += shading::shadeLight(N, L, -dir, s.scene.lights[i].color, sphere.material.md, sphere.material.ms,
                                   sphere.material.s, shading::SL_MODEL_PHONG, true, true);
        // The per-light terms add up to the light's contribution.
        const glm::vec3 parts = p.lights[i].diffuse + p.lights[i].specularPhong;
        EXPECT_NEAR(glm::length(parts - shading::shadeLight(N, L, -dir, s.scene.lights[i].color, sphere.material.md,
                                                            sphere.material.ms, sphere.material.s, 0, true, true)),
                    0.0f, 1e-6f);
    }
    EXPECT_NEAR(glm::length(p.totalPhong - sum), 0.0f, 1e-5f);
    // Negative control: a pixel 40 to the left sees a different normal.
    const ProbeResult q = probePixel(trace::TraceScene(s.scene), w, h, px.x - 40, px.y);
    EXPECT_GT(std::fabs(q.lights[0].NoL - p.lights[0].NoL), 1e-3f);
    // The report carries the numbers.
    const nlohmann::json j = nlohmann::json::parse(probeReportJson(p, s.scene, green));
    EXPECT_EQ(j["object"]["id"], green);
    EXPECT_NEAR(j["lights"][0]["NoL"].get<float>(), p.lights[0].NoL, 1e-7f);
}

TEST(AppState, ProbeFindsPlanesMeshesAndBackground) {
    ViewerState s = defaultState();
    const ProbeResult floor = probePixel(trace::TraceScene(s.scene), 640, 360, 320, 350);
    EXPECT_TRUE(floor.hit);
    EXPECT_EQ(floor.kind, ObjectKind::Plane);
    const ProbeResult sky = probePixel(trace::TraceScene(s.scene), 640, 360, 320, 2);
    EXPECT_FALSE(sky.hit);
    const std::string path = test::sourcePath("assets/scenes/torus.json");
    ViewerState t = makeViewerState(loadScene(path), path);
    const Mesh& torus = t.scene.meshes[0];
    const Bounds b = torus.parts[0].geometry->bounds;
    // The near side of the tube, above the torus' centre.
    const glm::vec3 c = 0.5f * (b.lo + b.hi);
    const glm::ivec2 px = pixelOf(t.scene, 640, 360, glm::vec3(c.x, b.hi.y, c.z));
    const ProbeResult m = probePixel(trace::TraceScene(t.scene), 640, 360, px.x, px.y + 2);
    ASSERT_TRUE(m.hit);
    EXPECT_EQ(m.kind, ObjectKind::Mesh);
    EXPECT_GT(glm::dot(m.N, m.V), 0.0f);  // faces the viewer
}

// A floor point in a sphere's shadow: the probe's vis_l is the shadow ray's, and the totals hold only the
// ambient term; with shadows off (the negative control) the same pixel is lit.
TEST(AppState, ProbeReportsShadowRayVisibility) {
    Scene scene;
    scene.camera.position = {0.0f, 2.0f, 6.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.ambient = glm::vec3(0.1f);
    scene.planes.push_back(Plane{});
    scene.spheres.push_back({"blocker", {0.0f, 1.0f, 0.0f}, 0.5f, Material{}});
    Light above;
    above.position = {0.0f, 5.0f, 0.0f};
    scene.lights.push_back(above);
    const int w = 320, h = 180;
    const glm::ivec2 under = pixelOf(scene, w, h, glm::vec3(0.0f, 0.0f, 0.0f));
    const ProbeResult shadowed = probePixel(trace::TraceScene(scene), w, h, under.x, under.y);
    ASSERT_TRUE(shadowed.hit);
    ASSERT_EQ(shadowed.kind, ObjectKind::Plane);
    EXPECT_EQ(shadowed.lights[0].visibility, 0.0f);
    EXPECT_EQ(shadowed.lights[0].diffuse, glm::vec3(0.0f));
    EXPECT_NEAR(glm::length(shadowed.totalPhong - shadowed.ambient), 0.0f, 1e-7f);
    const glm::ivec2 aside = pixelOf(scene, w, h, glm::vec3(2.0f, 0.0f, 0.0f));
    EXPECT_EQ(probePixel(trace::TraceScene(scene), w, h, aside.x, aside.y).lights[0].visibility, 1.0f);
    scene.terms.shadows = false;
    const ProbeResult lit = probePixel(trace::TraceScene(scene), w, h, under.x, under.y);
    EXPECT_EQ(lit.lights[0].visibility, 1.0f);
    EXPECT_GT(lit.totalPhong.r, shadowed.totalPhong.r + 0.1f);
    const nlohmann::json j = nlohmann::json::parse(probeReportJson(shadowed, scene, shadowed.objectId));
    EXPECT_EQ(j["lights"][0]["visibility"].get<float>(), 0.0f);
}

// disney: each light's four lobe parts sum to its term, and with the ambient to the shared shadeLocal's total;
// its F0 is disney's own (specular 1, tinted), not pbr's; the report carries both. Control: disney is not pbr.
TEST(AppState, ProbeDisneyLobesSumToTheSharedShading) {
    ViewerState s = defaultState();
    setModel(s, ShadingModel::Disney);
    const int w = 640, h = 360;
    const uint32_t green = idOf(s, "matte green");
    Sphere& sphere = s.scene.spheres[green - 1];
    sphere.material.roughness = 0.4f;
    sphere.material.disney = {0.5f, 1.0f, 0.6f, 0.7f, 1.0f, 0.5f, 1.0f, 0.5f};
    const glm::ivec2 px = pixelOf(s.scene, w, h, sphere.center + glm::vec3(0.3f, 0.3f, 0.0f));
    const ProbeResult p = probePixel(trace::TraceScene(s.scene), w, h, px.x, px.y);
    ASSERT_TRUE(p.hit);
    const Material& m = sphere.material;
    EXPECT_EQ(p.disneyF0, shading::disneySpecularF0(m.baseColor, m.metallic, 1.0f, 0.6f));
    EXPECT_GT(glm::length(p.disneyF0 - p.pbrF0), 1e-3f);
    glm::vec3 sum = p.ambient;
    for (size_t i = 0; i < p.lights.size(); ++i) {
        const ProbeLight& l = p.lights[i];
        const glm::vec3 one =
            shading::shadeLightDisney(p.N, l.L, p.V, l.Il, m.baseColor, m.metallic, m.roughness, m.disney.lobes0(),
                                      m.disney.lobes1(), true, true, glm::vec3(1.0f));
        const glm::vec3 parts = l.diffuseDisney + l.sheenDisney + l.specularDisney + l.clearcoatDisney;
        EXPECT_NEAR(glm::length(parts - l.visibility * one), 0.0f, 1e-5f) << i;
        sum += parts;
    }
    EXPECT_NEAR(glm::length(p.totalDisney - sum), 0.0f, 1e-5f);
    EXPECT_GT(glm::length(p.totalDisney - p.totalPbr), 1e-3f) << "control: disney is not pbr here";
    const nlohmann::json j = nlohmann::json::parse(probeReportJson(p, s.scene, green));
    EXPECT_NEAR(j["total"]["disney"][0].get<float>(), p.totalDisney.x, 1e-6f);
    EXPECT_NEAR(j["material"]["disney_f0"][1].get<float>(), p.disneyF0.y, 1e-6f);
    EXPECT_NEAR(j["lights"][0]["clearcoat_disney"][0].get<float>(), p.lights[0].clearcoatDisney.x, 1e-6f);
}

// glTF's clear coat under pbr: the base's two parts and the coat's lobe sum to each light's coated term and, with
// the ambient, to the total the tracer shades; the report carries the coat's part. Control: without the coat the
// total differs.
TEST(AppState, ProbePbrClearcoatPartsSumToTheCoatedShading) {
    ViewerState s = defaultState();
    setModel(s, ShadingModel::Pbr);
    const int w = 640, h = 360;
    const uint32_t green = idOf(s, "matte green");
    Sphere& sphere = s.scene.spheres[green - 1];
    sphere.material.roughness = 0.6f;
    sphere.material.clearcoat = Clearcoat{1.0f, 0.1f};
    const glm::ivec2 px = pixelOf(s.scene, w, h, sphere.center + glm::vec3(0.3f, 0.3f, 0.0f));
    const ProbeResult p = probePixel(trace::TraceScene(s.scene), w, h, px.x, px.y);
    ASSERT_TRUE(p.hit);
    const Material& m = sphere.material;
    glm::vec3 sum = p.ambient;
    for (size_t i = 0; i < p.lights.size(); ++i) {
        const ProbeLight& l = p.lights[i];
        const glm::vec3 base = shading::shadeLight(p.N, l.L, p.V, l.Il, p.pbrDiffuseColor, p.pbrF0, m.roughness,
                                                   shading::SL_MODEL_PBR, true, true);
        const glm::vec3 one = shading::clearcoatLight(base, p.N, l.L, p.V, l.Il, m.clearcoat.packed(), true);
        const glm::vec3 parts = l.diffusePbr + l.specularPbr + l.clearcoatPbr;
        EXPECT_NEAR(glm::length(parts - l.visibility * one), 0.0f, 1e-5f) << i;
        sum += parts;
    }
    EXPECT_NEAR(glm::length(p.totalPbr - sum), 0.0f, 1e-5f);
    const nlohmann::json j = nlohmann::json::parse(probeReportJson(p, s.scene, green));
    EXPECT_NEAR(j["lights"][0]["clearcoat_pbr"][1].get<float>(), p.lights[0].clearcoatPbr.y, 1e-6f);
    sphere.material.clearcoat.factor = 0.0f;
    const ProbeResult bare = probePixel(trace::TraceScene(s.scene), w, h, px.x, px.y);
    EXPECT_GT(glm::length(p.totalPbr - bare.totalPbr), 1e-3f) << "control: the coat changes the total";
}

// glTF's sheen (under a coat): the base's two parts, the sheen's and the coat's sum to the layered shading, light by
// light, as the tracer's shadeLightPbrLayers gives it; the report carries the sheen's part; control: the sheen
// changes the total.
TEST(AppState, ProbePbrSheenPartsSumToTheLayeredShading) {
    ViewerState s = defaultState();
    setModel(s, ShadingModel::Pbr);
    const int w = 640, h = 360;
    const uint32_t green = idOf(s, "matte green");
    Sphere& sphere = s.scene.spheres[green - 1];
    sphere.material.roughness = 0.6f;
    sphere.material.sheen = Sheen{{1.0f, 0.8f, 0.6f}, 0.4f};
    sphere.material.clearcoat = Clearcoat{0.5f, 0.1f};
    // Near the rim, where the sheen shows.
    const glm::ivec2 px = pixelOf(s.scene, w, h, sphere.center + glm::vec3(0.85f * sphere.radius, 0.3f, 0.0f));
    const ProbeResult p = probePixel(trace::TraceScene(s.scene), w, h, px.x, px.y);
    ASSERT_TRUE(p.hit);
    const Material& m = sphere.material;
    shading::SurfaceParams params =
        shading::surfaceParams(shading::SL_MODEL_PBR, m.ma, m.md, m.ms, m.s, m.baseColor, m.metallic, m.roughness);
    params.md = p.pbrDiffuseColor;
    params.coat = m.clearcoat.packed();
    params.coatN = p.N;
    params.sheen = m.sheen.packed();
    params.sheenTable = &shading::sheenLut();
    params.sheenEV = shading::sheenAlbedoAt(glm::dot(glm::normalize(p.N), glm::normalize(p.V)), m.sheen.roughness);
    glm::vec3 sum = p.ambient, sheens(0.0f);
    for (size_t i = 0; i < p.lights.size(); ++i) {
        const ProbeLight& l = p.lights[i];
        const glm::vec3 one = shading::shadeLightPbrLayers(p.N, {l.L, l.Il}, p.V, params, true, true);
        const glm::vec3 parts = l.diffusePbr + l.specularPbr + l.sheenPbr + l.clearcoatPbr;
        EXPECT_NEAR(glm::length(parts - l.visibility * one), 0.0f, 1e-5f) << i;
        sum += parts;
        sheens += l.sheenPbr;
    }
    EXPECT_GT(sheens.x, 1e-3f) << "the sheen's part is there";
    EXPECT_NEAR(glm::length(p.totalPbr - sum), 0.0f, 1e-5f);
    const nlohmann::json j = nlohmann::json::parse(probeReportJson(p, s.scene, green));
    EXPECT_NEAR(j["lights"][0]["sheen_pbr"][0].get<float>(), p.lights[0].sheenPbr.x, 1e-6f);
    sphere.material.sheen = Sheen{};
    const ProbeResult bare = probePixel(trace::TraceScene(s.scene), w, h, px.x, px.y);
    EXPECT_GT(glm::length(p.totalPbr - bare.totalPbr), 1e-3f) << "control: the sheen changes the total";
}

// glTF's transmission in the probe: a light behind a transmitting sphere shines through it, listed as its own part;
// the parts still sum to the pbr total, the report carries it, and without the transmission the total changes
// (control).
TEST(AppState, ProbePbrTransmissionIsTheLightThrough) {
    ViewerState s = defaultState();
    setModel(s, ShadingModel::Pbr);
    s.scene.terms.shadows = false;  // the sphere itself would hide the light behind it
    const int w = 640, h = 360;
    const uint32_t green = idOf(s, "matte green");
    Sphere& sphere = s.scene.spheres[green - 1];
    sphere.material.roughness = 0.5f;
    sphere.material.transmission = Transmission{0.8f};
    Light back;
    back.name = "behind";
    back.position = sphere.center - 4.0f * glm::normalize(s.scene.camera.position - sphere.center);
    back.color = glm::vec3(1.0f);
    s.scene.lights.push_back(back);
    const glm::ivec2 px = pixelOf(s.scene, w, h, sphere.center);
    const ProbeResult p = probePixel(trace::TraceScene(s.scene), w, h, px.x, px.y);
    ASSERT_TRUE(p.hit);
    glm::vec3 sum = p.ambient;
    for (const ProbeLight& l : p.lights)
        sum += l.diffusePbr + l.specularPbr + l.transmissionPbr + l.sheenPbr + l.clearcoatPbr;
    EXPECT_NEAR(glm::length(p.totalPbr - sum), 0.0f, 1e-5f);
    const ProbeLight& behind = p.lights.back();
    EXPECT_LT(behind.NoL, 0.0f);
    EXPECT_GT(behind.transmissionPbr.y, 1e-3f) << "the light behind shines through";
    EXPECT_EQ(behind.diffusePbr, glm::vec3(0.0f));
    const nlohmann::json j = nlohmann::json::parse(probeReportJson(p, s.scene, green));
    EXPECT_NEAR(j["lights"][p.lights.size() - 1]["transmission_pbr"][1].get<float>(), behind.transmissionPbr.y, 1e-6f);
    sphere.material.transmission = Transmission{};
    const ProbeResult bare = probePixel(trace::TraceScene(s.scene), w, h, px.x, px.y);
    EXPECT_GT(glm::length(p.totalPbr - bare.totalPbr), 1e-3f) << "control: the transmission changes the total";
}

TEST(AppState, ProbePbrColumnEqualsSharedShading) {
    ViewerState s = defaultState();
    setModel(s, ShadingModel::Pbr);
    const int w = 640, h = 360;
    const uint32_t green = idOf(s, "matte green");
    Sphere& sphere = s.scene.spheres[green - 1];
    sphere.material.metallic = 0.3f;
    sphere.material.roughness = 0.35f;
    const glm::ivec2 px = pixelOf(s.scene, w, h, sphere.center + glm::vec3(0.3f, 0.3f, 0.0f));
    const ProbeResult p = probePixel(trace::TraceScene(s.scene), w, h, px.x, px.y);
    ASSERT_TRUE(p.hit);
    const Material& m = sphere.material;
    const shading::SurfaceParams sp =
        shading::surfaceParams(shading::SL_MODEL_PBR, m.ma, m.md, m.ms, m.s, m.baseColor, m.metallic, m.roughness);
    EXPECT_EQ(p.pbrDiffuseColor, sp.md);
    EXPECT_EQ(p.pbrF0, sp.ms);
    glm::vec3 sum = p.ambient;
    for (size_t i = 0; i < p.lights.size(); ++i) {
        const ProbeLight& l = p.lights[i];
        const glm::vec3 one =
            shading::shadeLight(p.N, l.L, p.V, l.Il, sp.md, sp.ms, sp.s, shading::SL_MODEL_PBR, true, true);
        EXPECT_NEAR(glm::length(l.diffusePbr + l.specularPbr - l.visibility * one), 0.0f, 1e-5f) << i;
        // D·Vis·F is the specular BRDF: π · f · N·L · Il is the specular part.
        const glm::vec3 spec = shading::SL_PI * l.D * l.Vis * l.F * std::max(l.NoL, 0.0f) * l.Il * l.visibility;
        EXPECT_NEAR(glm::length(spec - l.specularPbr), 0.0f, 1e-4f * std::max(1.0f, glm::length(spec))) << i;
        sum += l.diffusePbr + l.specularPbr;
    }
    EXPECT_NEAR(glm::length(p.totalPbr - sum), 0.0f, 1e-5f);
    EXPECT_GT(glm::length(p.totalPbr - p.totalPhong), 1e-3f) << "control: pbr is not Phong here";
    const nlohmann::json j = nlohmann::json::parse(probeReportJson(p, s.scene, green));
    EXPECT_NEAR(j["total"]["pbr"][0].get<float>(), p.totalPbr.x, 1e-6f);
    EXPECT_NEAR(j["lights"][0]["D"].get<float>(), p.lights[0].D, 1e-6f);
    EXPECT_EQ(j["model"], "pbr");

    // On the checker floor the tile's colour is pbr's base colour, as in the integrator (F0 stays the plane's).
    const Plane& floor = s.scene.planes[0];
    ASSERT_TRUE(floor.checker.has_value());
    int seen[2] = {0, 0};
    for (int x = 0; x < w && (!seen[0] || !seen[1]); x += 7) {
        const ProbeResult f = probePixel(trace::TraceScene(s.scene), w, h, x, h - 5);
        if (!f.hit || f.kind != ObjectKind::Plane) continue;
        const int parity = shading::checkerParity(f.P, floor.normal, floor.checker->size);
        const glm::vec3 base = parity == 1 ? floor.checker->md2 : floor.material.baseColor;
        EXPECT_EQ(f.pbrDiffuseColor, shading::pbrDiffuseColor(base, floor.material.metallic)) << x;
        EXPECT_EQ(f.pbrF0, shading::pbrF0(floor.material.baseColor, floor.material.metallic)) << x;
        ++seen[parity];
    }
    EXPECT_TRUE(seen[0] && seen[1]) << "both kinds of tile";
    EXPECT_NE(floor.checker->md2, floor.material.baseColor) << "control: the tiles differ";
}

TEST(AppState, ProbeTotalsEqualTheIntegratorsLocalTermsUnderEveryModel) {
    // The probe explains the reference's pixel: its total for the scene's model is the integrator's own local
    // term (reflections are not in the probe's numbers), on spheres and on both kinds of checker tile.
    ViewerState s = defaultState();
    s.scene.spheres[0].material.metallic = 0.6f;
    s.scene.spheres[0].material.roughness = 0.3f;
    const int w = 96, h = 54;
    for (const ShadingModel model : {ShadingModel::Phong, ShadingModel::BlinnPhong, ShadingModel::Pbr}) {
        for (const bool normalized : {false, true}) {
            SCOPED_TRACE(std::string(toString(model)) + (normalized ? " normalized" : ""));
            Scene scene = s.scene;
            scene.model = model;
            scene.normalized = normalized;
            const trace::TraceScene ts(scene);
            const trace::WhittedIntegrator integrator(ts, 0);
            const ViewSetup view = makeViewSetup(scene, w, h);
            int checked = 0, otherDiffers = 0;
            for (int y = 1; y < h; y += 4)
                for (int x = 1; x < w; x += 4) {
                    const trace::Ray ray = trace::sampleRay(view, 1, x, y, 0, 0);
                    const std::optional<trace::Hit> hit = ts.intersect(ray);
                    if (!hit) continue;
                    const glm::vec3 expected = integrator.local(ray, integrator.surfaceAt(ray, *hit));
                    const ProbeResult p = probePixel(ts, w, h, x, y);
                    const glm::vec3 total = model == ShadingModel::Phong        ? p.totalPhong
                                            : model == ShadingModel::BlinnPhong ? p.totalBlinn
                                                                                : p.totalPbr;
                    const glm::vec3 other = model == ShadingModel::Pbr ? p.totalPhong : p.totalPbr;
                    EXPECT_NEAR(glm::length(total - expected), 0.0f, 1e-5f * std::max(1.0f, glm::length(expected)))
                        << x << "," << y;
                    otherDiffers += glm::length(other - expected) > 1e-3f;
                    ++checked;
                }
            EXPECT_GT(checked, 150);
            EXPECT_GT(otherDiffers, checked / 4) << "control: another model's column is not the image";
        }
    }
}
