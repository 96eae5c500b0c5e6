// The files a comparison leaves behind on disk: the two images, their heatmap and the JSON report, for tests
// that fail and the CLI's --diff/--json. Native only: it writes PNG (image/png.h), which the web build lacks.
#pragma once

#include "compare/image_compare.h"
#include "image/image.h"

#include <string>
#include <vector>

namespace shadelab {

// Writes <stem>_a.png, <stem>_b.png, <stem>_heat.png and <stem>_report.json (atomically) and returns
// their paths in that order, for tests that fail and the CLI's --diff/--json.
std::vector<std::string> writeCompareEvidence(const std::string& stem, const Image8& a, const Image8& b,
                                              const CompareResult& r);

}  // namespace shadelab
