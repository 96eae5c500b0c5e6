// Where two renderers' images differ, in plain words: the pixels over the gates' threshold,
// counted per object of the coverage, and a sentence that names the objects with the usual cause of a
// raster/reference difference on each (an environment-cube reflection, transmission drawn by the reference
// only, shadow-map edges). For a class and a first-time user; the verdict under the design.md §4 gates is
// still given beside it.
#pragma once

#include "compare/image_compare.h"
#include "scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadelab {

struct DifferenceSite {
    uint32_t id = 0;     // coverage id (scene/coverage.h); 0 = background
    int64_t pixels = 0;  // interior pixels over the threshold showing this object
};

struct DifferenceSites {
    int64_t over = 0;                   // interior pixels over the threshold
    int64_t interior = 0;               // interior pixels
    std::vector<DifferenceSite> sites;  // most pixels first; objects with none are left out
};

// Counts the interior pixels (outside the silhouette band of `result`) over `result.gates.threshold`,
// by the object `coverage` (the rasterizer's) shows there. `a` and `b` are the images `result` compared.
DifferenceSites differenceSites(const Image8& a, const Image8& b, const std::vector<uint32_t>& coverage,
                                const CompareResult& result);

// "sphere 5 'mirror'" / "plane 1": the object a coverage id names.
std::string coverageLabel(const Scene& scene, uint32_t id);

// One paragraph, e.g. "The raster and the reference differ visibly (by more than 3/255) in 1.49 % of the
// image. Where: mirror (sphere 5), 61 %: its reflection comes from an environment cube; floor (plane 1),
// 35 %: shadow-map edges. ..." Up to `maxSites` objects are named.
std::string describeDifference(const Scene& scene, const DifferenceSites& sites, int threshold, size_t maxSites = 3);

}  // namespace shadelab
