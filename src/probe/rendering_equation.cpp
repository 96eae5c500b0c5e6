// The rendering equation at a pixel: the path tracer's BSDF and lights at the hit, the hemisphere over its
// shading normal in an equal-area map, and for global illumination its paths along each texel's directions.
#include "probe/rendering_equation.h"

#include "scene/light_at.h"
#include "scene/view.h"
#include "shading/local_illumination.h"
#include "trace/integrator.h"
#include "trace/path/path_bsdf.h"
#include "trace/path/path_integrator.h"
#include "trace/path/warp.h"
#include "trace/tile_renderer.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>

namespace shadelab {
namespace {

bool positive(const glm::vec3& c) { return c.x > 0.0f || c.y > 0.0f || c.z > 0.0f; }

}  // namespace

glm::vec3 hemisphereDirection(glm::vec2 uv) {
    // Shirley & Chiu 1997: the square [−1, 1]² onto the unit disc, area for area.
    const float a = 2.0f * uv.x - 1.0f, b = 1.0f - 2.0f * uv.y;  // b up: row 0 is the top
    float r = 0.0f, phi = 0.0f;
    if (a == 0.0f && b == 0.0f) return {0.0f, 0.0f, 1.0f};
    if (std::fabs(a) > std::fabs(b)) {
        r = a;
        phi = (trace::kPi / 4.0f) * (b / a);
    } else {
        r = b;
        phi = (trace::kPi / 2.0f) - (trace::kPi / 4.0f) * (a / b);
    }
    const float x = r * std::cos(phi), y = r * std::sin(phi);
    // Lambert's azimuthal equal-area projection: the disc's area π onto the hemisphere's 2π, uniformly.
    const float r2 = x * x + y * y, s = std::sqrt(std::max(2.0f - r2, 0.0f));
    return glm::normalize(glm::vec3(x * s, y * s, 1.0f - r2));
}

glm::vec2 hemisphereTexel(const glm::vec3& d) {
    // The inverse: the disc point at radius sqrt(1 − z) along the direction's azimuth, then disc to square.
    const float z = std::clamp(d.z, 0.0f, 1.0f), rd = std::sqrt(1.0f - z);
    const float len = std::sqrt(d.x * d.x + d.y * d.y);
    const float x = len > 0.0f ? rd * d.x / len : 0.0f, y = len > 0.0f ? rd * d.y / len : 0.0f;
    const float r = std::sqrt(x * x + y * y);
    float phi = std::atan2(y, x);
    if (phi < -trace::kPi / 4.0f) phi += 2.0f * trace::kPi;
    float a = 0.0f, b = 0.0f;
    if (phi < trace::kPi / 4.0f) {
        a = r, b = phi * a / (trace::kPi / 4.0f);
    } else if (phi < 3.0f * trace::kPi / 4.0f) {
        b = r, a = -(phi - trace::kPi / 2.0f) * b / (trace::kPi / 4.0f);
    } else if (phi < 5.0f * trace::kPi / 4.0f) {
        a = -r, b = (phi - trace::kPi) * a / (trace::kPi / 4.0f);
    } else {
        b = -r, a = -(phi - 3.0f * trace::kPi / 2.0f) * b / (trace::kPi / 4.0f);
    }
    return {0.5f * (a + 1.0f), 0.5f * (1.0f - b)};
}

RenderingEquation renderingEquationAt(const trace::TraceScene& scene, int width, int height, int x, int y, bool global,
                                      int size, int samplesPerTexel) {
    using namespace trace;
    RenderingEquation out;
    out.global = global;
    const Scene& sc = scene.scene();
    const ViewSetup view = makeViewSetup(sc, width, height);
    WhittedIntegrator whitted(scene, sc.maxDepth);
    whitted.setPixelFootprint(pixelFootprint(view));
    const Ray ray = sampleRay(view, 1, x, y, 0, 0);
    const std::optional<Hit> hit = whitted.visibleHit(ray, 0.0f, 0);
    if (!hit) return out;
    out.hit = true;
    out.size = size;
    const Surface s = whitted.surfaceAt(ray, *hit, 0);
    const Material& m = *s.material;
    const glm::vec3 V = -ray.dir;
    const int model = s.model;  // the material's own, else the scene's
    const shading::SurfaceParams params = whitted.shadingParams(s, V);
    const PathBsdf bsdf(s, params, V, model, BsdfTerms{sc.terms.diffuse, sc.terms.specular, sc.terms.reflections});
    const Frame frame(glm::normalize(s.N));
    out.deltaLobes = sc.terms.reflections && (positive(m.kr) || positive(m.kt));
    out.emission = m.emission * s.emissive;
    const bool lit = sc.terms.diffuse || sc.terms.specular;

    // The delta lights: the Whitted tracer's (and the path tracer's) terms, π f(ω_l) Il cos θ_l vis_l.
    for (size_t k = 0; k < sc.lights.size(); ++k) {
        const LightAt at = lightAt(sc.lights[k], s.P);
        HemisphereLight hl;
        hl.light = int(k);
        const glm::vec3 L = glm::normalize(at.L);
        const glm::vec3 local = frame.toLocal(L);
        hl.above = local.z > 0.0f;
        hl.at = hemisphereTexel(local);
        const glm::vec3 f = bsdf.evalCos(L);
        hl.visible =
            !(sc.terms.shadows && lit && positive(f) && positive(at.Il)) || whitted.visibility(s, sc.lights[k]) > 0.0f;
        hl.term = hl.visible ? kPi * f * at.Il : glm::vec3(0.0f);
        out.lightSum += hl.term;
        out.lights.push_back(hl);
    }
    if (!global && sc.terms.ambient) out.ambient = sc.ambient * params.ma;

    // The hemisphere, texel by texel; under global illumination, samplesPerTexel paths stratified in each.
    PathSettings ps;
    ps.maxDepth = std::max(sc.maxDepth - 1, 0);
    // Only the global view traces paths (its environment sampler is built from the whole map, if any).
    std::optional<PathIntegrator> paths;
    if (global) paths.emplace(scene, ps);
    const glm::vec3 above = s.P + scene.epsilon() * s.Nf;
    const int k = std::max(1, int(std::lround(std::sqrt(double(std::max(samplesPerTexel, 1))))));
    const float texel = 2.0f * kPi / float(size * size);
    const size_t n = size_t(size) * size_t(size);
    out.incoming.assign(n, glm::vec3(0.0f));
    out.brdfCos.assign(n, glm::vec3(0.0f));
    out.product.assign(n, glm::vec3(0.0f));
    glm::dvec3 variance(0.0);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const size_t t = size_t(j) * size_t(size) + size_t(i);
            const glm::vec3 centre =
                frame.toWorld(hemisphereDirection({(float(i) + 0.5f) / float(size), (float(j) + 0.5f) / float(size)}));
            out.brdfCos[t] = bsdf.evalCos(centre);
            if (!global) {
                out.incoming[t] = sc.terms.ambient ? sc.ambient : glm::vec3(0.0f);  // the ambient as a sky
                out.product[t] = out.incoming[t] * out.brdfCos[t];
                continue;
            }
            // Stratified: one path through each cell of a k x k grid inside the texel.
            glm::vec3 sumL(0.0f), sumP(0.0f), sumP2(0.0f);
            for (int b = 0; b < k; ++b)
                for (int a = 0; a < k; ++a) {
                    const SampleRng rng{uint32_t(t), uint32_t(b * k + a), 0x4E0u, PathSampler::Independent};
                    const glm::vec4 u = rng.draw(0, 7);
                    const glm::vec2 uv((float(i) + (float(a) + u.x) / float(k)) / float(size),
                                       (float(j) + (float(b) + u.y) / float(k)) / float(size));
                    const glm::vec3 w = frame.toWorld(hemisphereDirection(uv));
                    if (glm::dot(w, s.Nf) <= 0.0f) continue;  // under the geometric surface: no light from there
                    const SampleRng pathRng{uint32_t(t), uint32_t(b * k + a), 0x4E1u, PathSampler::Independent};
                    const glm::vec3 L = paths->trace(Ray{above, w}, pathRng).color;
                    const glm::vec3 p = L * bsdf.evalCos(w);
                    sumL += L;
                    sumP += p;
                    sumP2 += p * p;
                }
            const float count = float(k * k);
            out.incoming[t] = sumL / count;
            out.product[t] = sumP / count;
            // The texel's mean has variance σ²/count; the integral's is the sum over texels times texel².
            if (k * k > 1) {
                const glm::vec3 mean = sumP / count;
                const glm::vec3 var = glm::max((sumP2 - count * mean * mean) / (count - 1.0f), glm::vec3(0.0f));
                variance += glm::dvec3(var / count) * double(texel) * double(texel);
            }
        }
    glm::dvec3 sum(0.0);
    for (const glm::vec3& p : out.product) sum += glm::dvec3(p);
    out.imageIntegral = glm::vec3(sum * double(texel));
    out.imageError = glm::vec3(glm::sqrt(variance));
    if (shading::noIllumination(sc.terms.ambient, sc.terms.diffuse, sc.terms.specular)) {
        out.total = shading::unlitColour(s.md, s.baseColor, model) + out.emission;  // the lecture's step 0
    } else {
        out.total =
            global ? out.emission + out.lightSum + out.imageIntegral : out.ambient + out.lightSum + out.emission;
    }
    return out;
}

}  // namespace shadelab
