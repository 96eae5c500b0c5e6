// Analytic pixels: a headless raster render of a sphere under a directional light, checked
// pixel by pixel against the C++ equations evaluated for each pixel's own ray and hit point.
#include "gl_fixture.h"
#include "image/encode.h"
#include "image/png.h"
#include "raster/raster_renderer.h"
#include "scene/coverage.h"
#include "scene/view.h"
#include "shading/local_illumination.h"
#include "test_output.h"

#include <cmath>
#include <glm/geometric.hpp>

using namespace shadelab;

namespace {

Scene sphereScene(ShadingModel model, float s) {
    Scene scene;
    scene.camera.position = {0.0f, 0.0f, 4.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.fovY = 40.0f;
    scene.model = model;
    scene.ambient = glm::vec3(0.1f, 0.12f, 0.15f);
    scene.background = glm::vec3(0.05f, 0.0f, 0.1f);
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(-1.0f, -1.0f, -1.5f));
    sun.color = glm::vec3(1.0f, 0.9f, 0.8f);
    scene.lights.push_back(sun);
    Sphere sphere;
    sphere.center = {0.0f, 0.0f, 0.0f};
    sphere.radius = 1.0f;
    sphere.material.ma = glm::vec3(0.9f, 0.3f, 0.3f);
    sphere.material.md = glm::vec3(0.7f, 0.2f, 0.2f);
    sphere.material.ms = glm::vec3(0.5f);
    sphere.material.s = s;
    scene.spheres.push_back(sphere);
    return scene;
}

// The expected colour of pixel (x, y): the tracer's recipe written out with the shared C++ functions.
glm::vec3 expectedPixel(const Scene& scene, const ViewSetup& v, int x, int y, bool* hit) {
    glm::vec3 dir = shading::cameraRayDirection(v.forward, v.right, v.up, v.tanHalfFovY, float(v.width),
                                                float(v.height), float(x) + 0.5f, float(y) + 0.5f);
    const Sphere& s = scene.spheres[0];
    float t = shading::intersectSphere(v.eye, dir, s.center, s.radius, 0.0f);
    *hit = t > 0.0f;
    if (!*hit) return scene.background;
    glm::vec3 P = v.eye + t * dir, V = -dir;
    glm::vec3 N = shading::faceForward((P - s.center) / s.radius, V);
    const Light& l = scene.lights[0];
    shading::LightSample sample{shading::lightVector(l.direction, false, P), l.color};
    shading::SurfaceParams m{s.material.ma, s.material.md, s.material.ms, s.material.s};
    int model = scene.model == ShadingModel::Phong ? shading::SL_MODEL_PHONG : shading::SL_MODEL_BLINN_PHONG;
    return shading::shadeLocal(N, V, &sample, 1, m, scene.ambient, model, shading::TermFlags{});
}

struct PixelCheck {
    int checked = 0, hits = 0, failures = 0;
    float worst = 0.0f;
};

PixelCheck compareAll(const Scene& scene, const raster::RasterOutput& out, float tol) {
    ViewSetup v = makeViewSetup(scene, out.color.width, out.color.height);
    PixelCheck c;
    for (int y = 0; y < v.height; ++y)
        for (int x = 0; x < v.width; ++x) {
            bool hit = false;
            glm::vec3 e = expectedPixel(scene, v, x, y, &hit);
            uint32_t id = out.coverage[size_t(y) * size_t(v.width) + size_t(x)];
            // Pixels whose centre ray grazes the silhouette may go either way in float; skip the rim.
            if ((id != kBackgroundId) != hit) continue;
            const float* p = out.color.pixel(x, y);
            float err = std::max({std::abs(p[0] - e.x), std::abs(p[1] - e.y), std::abs(p[2] - e.z)});
            c.worst = std::max(c.worst, err);
            ++c.checked;
            c.hits += hit;
            c.failures += err > tol;
        }
    return c;
}

}  // namespace

class AnalyticPixelsTest : public test::GlTest {};

TEST_F(AnalyticPixelsTest, SphereUnderDirectionalLightMatchesEquations) {
    for (ShadingModel model : {ShadingModel::Phong, ShadingModel::BlinnPhong}) {
        for (float s : {1.0f, 32.0f, 500.0f}) {
            Scene scene = sphereScene(model, s);
            raster::RasterRenderer renderer;
            renderer.uploadMeshes(scene);
            raster::RasterOutput out = raster::renderRaster(renderer, scene, 160, 120, true);
            PixelCheck c = compareAll(scene, out, 1.0f / 255.0f);
            std::string name = std::string("sphere_") + toString(model) + "_s" + std::to_string(int(s)) + ".png";
            EXPECT_GT(c.hits, 3000) << "the sphere should cover a good part of the image";
            EXPECT_GE(c.checked, 160 * 120 - 200) << "too many rim pixels disagreed on coverage";
            EXPECT_EQ(c.failures, 0) << toString(model) << " s=" << s << ": worst error " << c.worst * 255.0f
                                     << "/255; image: " << test::outputPath(name);
            if (c.failures)
                writePng(test::outputPath(name), toImage8(out.color, Encoding::Srgb, DisplaySettings{}, nullptr));
        }
    }
}

TEST_F(AnalyticPixelsTest, NegativeControlWrongShininessFails) {
    // Rendered with s = 35.2 (10 % above 32), checked against the equations at s = 32: must not pass.
    Scene rendered = sphereScene(ShadingModel::Phong, 35.2f);
    Scene expected = sphereScene(ShadingModel::Phong, 32.0f);
    raster::RasterRenderer renderer;
    raster::RasterOutput out = raster::renderRaster(renderer, rendered, 160, 120, true);
    PixelCheck c = compareAll(expected, out, 1.0f / 255.0f);
    EXPECT_GT(c.failures, 50) << "a 10% shininess change should be visible";
}

TEST_F(AnalyticPixelsTest, BackgroundAndTermSwitches) {
    Scene scene = sphereScene(ShadingModel::Phong, 32.0f);
    scene.terms = Terms{true, false, false, false, false};  // ambient only: a flat disc of Ia·ma
    raster::RasterRenderer renderer;
    raster::RasterOutput out = raster::renderRaster(renderer, scene, 80, 60, true);
    const float* centre = out.color.pixel(40, 30);
    glm::vec3 want = scene.ambient * scene.spheres[0].material.ma;
    EXPECT_NEAR(centre[0], want.x, 1e-6f);
    EXPECT_NEAR(centre[1], want.y, 1e-6f);
    EXPECT_NEAR(centre[2], want.z, 1e-6f);
    const float* corner = out.color.pixel(0, 0);
    EXPECT_NEAR(corner[0], scene.background.x, 1e-6f);
    EXPECT_NEAR(corner[2], scene.background.z, 1e-6f);
    EXPECT_EQ(out.coverage[0], kBackgroundId);
    EXPECT_EQ(out.coverage[30 * 80 + 40], sphereCoverageId(scene, 0));
}
