// RedrawPlan: the keys of a raster draw and the comparison that allows a partial redraw.
#include "raster/redraw_plan.h"

#include "scene/coverage.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/vec4.hpp>
#include <limits>

namespace shadelab::raster {
namespace {

void addTexture(KeyBytes& k, const TextureBinding& t) {
    k.add(static_cast<const void*>(t.texture.get()));
    k.add(t.sampler.wrapS).add(t.sampler.wrapT);
    k.add(t.sampler.magLinear).add(t.sampler.minLinear).add(t.sampler.mipmaps).add(t.sampler.mipLinear);
    k.add(t.texCoord).add(t.strength).add(t.offset).add(t.rotation).add(t.scale);
}

}  // namespace

// Every field of Material and TextureBinding: a field left out would let its edit keep a stale image. The
// sizes below change when a field is added, so the build stops here until the key has it too.
// (64-bit sizes, checked where pointers are 64-bit; the static_asserts are a reminder, not a portability rule.
// The web build's 32-bit WebAssembly has other sizes and relies on the native builds to remind.)
#if UINTPTR_MAX == UINT64_MAX
static_assert(sizeof(TextureBinding) == 56, "a new TextureBinding field: add it to addTexture");
static_assert(sizeof(Material) == 688, "a new Material field: add it to materialKey");
#endif

KeyBytes materialKey(const Material& m) {
    KeyBytes k;
    k.add(m.ma).add(m.md).add(m.ms).add(m.s).add(m.kr).add(m.kt).add(m.ior);
    k.add(m.baseColor).add(m.metallic).add(m.roughness).add(m.emission);
    k.add(m.disney.lobes0()).add(m.disney.lobes1()).add(m.clearcoat.packed()).add(m.specular.packed(m.ior));
    k.add(m.sheen.packed()).add(m.anisotropy.packed()).add(m.transmission.factor);
    k.add(m.volume.thickness).add(m.volume.attenuationDistance).add(m.volume.attenuationColor);
    for (const TextureBinding* t :
         {&m.baseColorTexture, &m.metallicRoughnessTexture, &m.normalTexture, &m.occlusionTexture, &m.emissiveTexture,
          &m.clearcoatTexture, &m.clearcoatRoughnessTexture, &m.clearcoatNormalTexture})
        addTexture(k, *t);
    k.add(m.alphaMode).add(m.alpha).add(m.alphaCutoff);
    k.add(m.model.has_value()).add(m.model.value_or(ShadingModel::Phong));
    // Material::derived is not in the key: which fields were given changes no pixel.
    return k;
}

KeyBytes planeMaterialKey(const Plane& p) {
    KeyBytes k = materialKey(p.material);
    k.add(p.checker.has_value());
    if (p.checker) k.add(p.checker->md2).add(p.checker->size);
    return k;
}

KeyBytes sceneKeyWithoutMaterials(const Scene& scene) {
    KeyBytes k;
    const Camera& c = scene.camera;
    k.add(c.position).add(c.target).add(c.up).add(c.fovY);
    k.add(scene.model).add(scene.normalized).add(scene.energyCompensation);
    const Terms& t = scene.terms;
    k.add(t.ambient).add(t.diffuse).add(t.specular).add(t.shadows).add(t.reflections);
    k.add(scene.ambient).add(scene.background).add(scene.maxDepth);
    const RasterSettings& r = scene.raster;
    k.add(r.shadowMapSize).add(r.depthBias).add(r.normalBias).add(r.pcf).add(r.reflectionCubeSize);
    k.add(scene.environment.has_value());
    if (scene.environment) {
        const Environment& e = *scene.environment;
        k.addString(e.hdr).add(e.intensity).add(e.rotation).add(static_cast<const void*>(e.map.get()));
    }
    k.add(scene.lights.size());
    for (const Light& l : scene.lights) {
        k.add(l.type).add(l.position).add(l.direction).add(l.color).add(l.attenuation);
        k.add(l.innerConeAngle).add(l.outerConeAngle).add(l.range);
    }
    k.add(scene.spheres.size());
    for (const Sphere& s : scene.spheres) k.add(s.center).add(s.radius);
    k.add(scene.planes.size());
    for (const Plane& p : scene.planes) k.add(p.normal).add(p.offset);
    k.add(scene.meshes.size());
    for (const Mesh& m : scene.meshes) {
        k.add(m.parts.size());
        for (const MeshPart& part : m.parts) k.add(static_cast<const void*>(part.geometry.get()));
    }
    return k;
}

DrawKey drawKey(const Scene& scene) {
    DrawKey key;
    key.shared = sceneKeyWithoutMaterials(scene);
    for (size_t mi = 0; mi < scene.meshes.size(); ++mi)
        for (const MeshPart& part : scene.meshes[mi].parts) {
            key.ids.push_back(meshCoverageId(scene, mi));
            key.materials.push_back(materialKey(part.material));
        }
    for (size_t i = 0; i < scene.spheres.size(); ++i) {
        key.ids.push_back(sphereCoverageId(scene, i));
        key.materials.push_back(materialKey(scene.spheres[i].material));
    }
    for (size_t i = 0; i < scene.planes.size(); ++i) {
        key.ids.push_back(planeCoverageId(scene, i));
        key.materials.push_back(planeMaterialKey(scene.planes[i]));
    }
    return key;
}

PixelRect unite(const PixelRect& a, const PixelRect& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

PixelRect boxPixelRect(const glm::mat4& viewProj, const glm::vec3& lo, const glm::vec3& hi, int width, int height) {
    const PixelRect whole{0, 0, width, height};
    glm::vec4 corner[8];
    for (int c = 0; c < 8; ++c)
        corner[c] = viewProj * glm::vec4(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z, 1.0f);
    // The box clipped by the near plane (z >= -w, where GL clips): its corners inside, and where its edges cross.
    glm::vec4 kept[20];
    int count = 0;
    for (int c = 0; c < 8; ++c)
        if (corner[c].z + corner[c].w >= 0.0f) kept[count++] = corner[c];
    for (int c = 0; c < 8; ++c)
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (c & bit) continue;
            const glm::vec4 &a = corner[c], &b = corner[c | bit];
            const float da = a.z + a.w, db = b.z + b.w;
            if ((da >= 0.0f) != (db >= 0.0f)) kept[count++] = a + (da / (da - db)) * (b - a);
        }
    if (count == 0) return PixelRect{};  // wholly on the eye's side of the near plane: all clipped
    const float inf = std::numeric_limits<float>::infinity();
    float x0 = inf, y0 = inf, x1 = -inf, y1 = -inf;
    for (int i = 0; i < count; ++i) {
        const glm::vec4& p = kept[i];
        if (!(p.w > 0.0f)) return whole;  // not a perspective view in front of the eye: no bound taken
        const float x = (0.5f * p.x / p.w + 0.5f) * float(width), y = (0.5f * p.y / p.w + 0.5f) * float(height);
        if (!std::isfinite(x) || !std::isfinite(y)) return whole;
        x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    }
    // Two pixels of margin for the GPU's own rounding; clamped before the conversion to int.
    const auto clampX = [width](float v) { return int(std::clamp(v, 0.0f, float(width))); };
    const auto clampY = [height](float v) { return int(std::clamp(v, 0.0f, float(height))); };
    return {clampX(std::floor(x0) - 2.0f), clampY(std::floor(y0) - 2.0f), clampX(std::ceil(x1) + 2.0f),
            clampY(std::ceil(y1) + 2.0f)};
}

void addToPlan(RedrawPlan& plan, uint32_t id, size_t maxIds) {
    if (plan.full || std::find(plan.ids.begin(), plan.ids.end(), id) != plan.ids.end()) return;
    if (plan.ids.size() >= maxIds) {
        plan = RedrawPlan{};
        return;
    }
    plan.ids.push_back(id);
}

RedrawPlan planRedraw(const DrawKey* last, const DrawKey& next, size_t maxIds) {
    if (!last || last->shared != next.shared || last->ids != next.ids ||
        last->materials.size() != next.materials.size())
        return RedrawPlan{};
    RedrawPlan plan;
    plan.full = false;
    for (size_t i = 0; i < next.materials.size() && !plan.full; ++i)
        if (last->materials[i] != next.materials[i]) addToPlan(plan, next.ids[i], maxIds);
    return plan;
}

}  // namespace shadelab::raster
