#include "compare/difference_sites.h"

#include "scene/coverage.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace shadelab {
namespace {

struct CoveredObject {
    const char* kind = "background";
    size_t index = 0;
    const std::string* name = nullptr;
    const Material* material = nullptr;  // a mesh's first part's
    bool plane = false;
};

CoveredObject covered(const Scene& scene, uint32_t id) {
    CoveredObject o;
    if (id == kBackgroundId) return o;
    size_t i = id - 1;
    if (i < scene.spheres.size()) return {"sphere", i, &scene.spheres[i].name, &scene.spheres[i].material, false};
    i -= scene.spheres.size();
    if (i < scene.planes.size()) return {"plane", i, &scene.planes[i].name, &scene.planes[i].material, true};
    i -= scene.planes.size();
    if (i < scene.meshes.size()) {
        const Mesh& m = scene.meshes[i];
        return {"mesh", i, &m.name, m.parts.empty() ? nullptr : &m.parts.front().material, false};
    }
    return o;
}

bool any(const glm::vec3& v) { return v.r > 0.0f || v.g > 0.0f || v.b > 0.0f; }

// The usual reason the rasterizer departs from the reference on this object (docs/lighting.md).
std::string likelyCause(const Scene& scene, const CoveredObject& o) {
    if (!o.material) return "";
    const Material& m = *o.material;
    const bool reflections = scene.terms.reflections;
    if (reflections && any(m.kt)) return "transmission, which only the reference draws";
    if (reflections && modelOf(m, scene.model) == ShadingModel::Pbr && m.transmission.on())
        return "glTF transmission, which the rasterizer reads from the environment or an environment cube";
    if (reflections && any(m.kr) && !o.plane) return "its reflection comes from an environment cube";
    if (scene.terms.shadows && !scene.lights.empty()) return "mostly shadow-map edges";
    return "";
}

}  // namespace

DifferenceSites differenceSites(const Image8& a, const Image8& b, const std::vector<uint32_t>& coverage,
                                const CompareResult& result) {
    DifferenceSites out;
    const size_t n = size_t(a.width) * size_t(a.height);
    if (a.width != b.width || a.height != b.height || a.channels != b.channels || coverage.size() != n) return out;
    std::map<uint32_t, int64_t> counts;
    const int c = a.channels;
    for (size_t p = 0; p < n; ++p) {
        if (!result.bandMask.empty() && result.bandMask[p]) continue;
        ++out.interior;
        bool over = false;
        for (int k = 0; k < c && !over; ++k)
            over = std::abs(int(a.data[p * size_t(c) + size_t(k)]) - int(b.data[p * size_t(c) + size_t(k)])) >
                   result.gates.threshold;
        if (!over) continue;
        ++out.over;
        ++counts[coverage[p]];
    }
    for (const auto& [id, pixels] : counts) out.sites.push_back({id, pixels});
    std::stable_sort(out.sites.begin(), out.sites.end(),
                     [](const DifferenceSite& x, const DifferenceSite& y) { return x.pixels > y.pixels; });
    return out;
}

std::string coverageLabel(const Scene& scene, uint32_t id) {
    const CoveredObject o = covered(scene, id);
    if (!o.name) return "the background";
    const std::string where = std::string(o.kind) + " " + std::to_string(o.index + 1);
    return o.name->empty() ? where : *o.name + " (" + where + ")";
}

std::string describeDifference(const Scene& scene, const DifferenceSites& sites, int threshold, size_t maxSites) {
    char buf[160];
    if (sites.interior == 0) return "Nothing to compare.";
    const double percent = 100.0 * double(sites.over) / double(sites.interior);
    if (sites.over == 0) {
        std::snprintf(buf, sizeof buf,
                      "The raster and the reference agree within %d/255 everywhere inside the objects.", threshold);
        return buf;
    }
    std::snprintf(buf, sizeof buf,
                  "The raster and the reference differ visibly (by more than %d/255) in %.2f %% of the image.",
                  threshold, percent);
    std::string text = buf;
    text += " Where:";
    size_t named = 0;
    for (const DifferenceSite& s : sites.sites) {
        if (named == maxSites) break;
        const double share = 100.0 * double(s.pixels) / double(sites.over);
        if (named > 0 && share < 5.0) break;  // name the main places only
        std::snprintf(buf, sizeof buf, " %s, %.0f %%", coverageLabel(scene, s.id).c_str(), share);
        text += named ? ";" : "";
        text += buf;
        const std::string cause = likelyCause(scene, covered(scene, s.id));
        if (!cause.empty()) text += ": " + cause;
        ++named;
    }
    text += ".";
    return text;
}

}  // namespace shadelab
