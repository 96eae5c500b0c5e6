// _compare: `shadelab compare --json` for images in memory (compare/image_compare.h, compare/compare_report.h): the
// same gates, metrics, JSON report and heatmap. With coverage on both sides (render(..., coverage=True)) the silhouette
// band is masked as in the raster-against-reference tests.
#include "compare/compare_report.h"
#include "compare/image_compare.h"
#include "python/bindings.h"
#include "python/image_data.h"
#include "python/py_json.h"

#include <pybind11/stl.h>

#include <memory>
#include <optional>

namespace py = pybind11;

namespace shadelab::python {

void bindCompare(py::module_& m) {
    m.def(
        "_compare",
        [](const ImageData& a, const ImageData& b, int threshold, double maxFractionOver, int hardMax,
           double maxSilhouetteFraction, std::optional<double> maxMean, int gain, const std::string& nameA,
           const std::string& nameB) {
            CompareGates gates;
            gates.threshold = threshold;
            gates.maxFractionOver = maxFractionOver;
            gates.hardMax = hardMax;
            gates.maxSilhouetteFraction = maxSilhouetteFraction;
            gates.maxMean = maxMean;
            if (gain < 1 || gain > 255) throw py::value_error("gain: must be in [1, 255], got " + std::to_string(gain));
            auto heat = std::make_shared<ImageData>();
            std::string json, summary;
            bool pass = false;
            {
                py::gil_scoped_release released;
                const bool coverage = !a.coverage.empty() && !b.coverage.empty() && a.pixels.width == b.pixels.width &&
                                      a.pixels.height == b.pixels.height;
                const CompareResult r = coverage ? compareImages(a.pixels, b.pixels, a.coverage, b.coverage, gates)
                                                 : compareImages(a.pixels, b.pixels, gates);
                heat->pixels = coverage ? diffHeatmap(a.pixels, b.pixels, r.bandMask, gain)
                                        : diffHeatmap(a.pixels, b.pixels, gain);
                // The heatmap's floats are its levels read as linear, so np.asarray(heatmap) is the ramp itself.
                heat->linear = ImageF(heat->pixels.width, heat->pixels.height);
                for (size_t i = 0; i < heat->pixels.data.size() / 3; ++i) {
                    for (size_t c = 0; c < 3; ++c)
                        heat->linear.rgba[i * 4 + c] = float(heat->pixels.data[i * 3 + c]) / 255.0f;
                    heat->linear.rgba[i * 4 + 3] = 1.0f;
                }
                heat->encoding = Encoding::Linear;
                heat->source = "array";
                json = compareReportJson(r, nameA, nameB);
                summary = compareSummary(r);
                pass = r.pass;
            }
            return py::make_tuple(jsonTextToPython(json), summary, heat, pass);
        },
        py::arg("a"), py::arg("b"), py::arg("threshold") = CompareGates{}.threshold,
        py::arg("max_fraction_over") = CompareGates{}.maxFractionOver, py::arg("hard_max") = CompareGates{}.hardMax,
        py::arg("max_silhouette_fraction") = CompareGates{}.maxSilhouetteFraction, py::arg("max_mean") = py::none(),
        py::arg("gain") = 16, py::arg("name_a") = "", py::arg("name_b") = "");

    // design.md §4's gates as CompareGates holds them, under the JSON report's names.
    const CompareGates defaults;
    py::dict gates;
    gates["threshold"] = defaults.threshold;
    gates["max_fraction_over"] = defaults.maxFractionOver;
    gates["hard_max"] = defaults.hardMax;
    gates["max_silhouette_fraction"] = defaults.maxSilhouetteFraction;
    gates["max_mean"] = py::none();
    m.attr("default_gates") = gates;
}

}  // namespace shadelab::python
