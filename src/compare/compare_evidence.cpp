// writeCompareEvidence: a comparison's images, heatmap and report as files beside each other.
#include "compare/compare_evidence.h"

#include "compare/compare_report.h"
#include "image/png.h"
#include "util/atomic_file.h"
#include "util/output_file.h"

namespace shadelab {

std::vector<std::string> writeCompareEvidence(const std::string& stem, const Image8& a, const Image8& b,
                                              const CompareResult& r) {
    std::vector<std::string> paths;
    for (const char* suffix : {"_a.png", "_b.png", "_heat.png", "_report.json"})
        paths.push_back(derivedOutput(stem, suffix));
    writePng(paths[0], a);
    writePng(paths[1], b);
    writePng(paths[2], diffHeatmap(a, b, r.bandMask));
    writeFileAtomic(paths[3], compareReportJson(r, paths[0], paths[1]));
    return paths;
}

}  // namespace shadelab
