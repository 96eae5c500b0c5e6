// Runs the real viewer window from tests (app_window_test.cpp, app_window_interaction_test.cpp): under a fresh
// Xvfb server of its own, at one small size, with the headless `shadelab render` to compare against.
#pragma once

#include "cli_run.h"
#include "compare/compare_evidence.h"
#include "compare/compare_report.h"
#include "compare/image_compare.h"
#include "image/png.h"
#include "pixel_of.h"
#include "scene/view.h"
#include "test_output.h"

#include <gtest/gtest.h>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace shadelab::test {

inline constexpr const char* kSize = "320x180";
inline constexpr int kW = 320, kH = 180;

inline std::string binary() { return SHADELAB_BINARY; }

// The viewer in a fresh X server of its own (tests/with_xvfb.sh, which returns the viewer's own exit code). The
// screen is larger than any window the tests open.
inline Result view(const std::string& args, const std::string& env = "") {
    return shell(env + SHADELAB_WITH_XVFB " -s 1920x1200x24 " + binary() + " view " + args);
}

inline Result render(const std::string& scene, const std::string& out, const std::string& flags = "") {
    return shell(binary() + " render " + scene + " --size " + kSize + " -o " + out + " " + flags);
}

inline bool haveXvfb() { return shell("command -v Xvfb").code == 0; }

#define REQUIRE_XVFB() \
    if (!haveXvfb()) GTEST_SKIP() << "Xvfb not found: apt-get install xvfb (scripts/install-deps.sh)"

// Exact equality expected (same renderer, same shared conversion), plus the design.md §4 gates; on
// failure both images, the heatmap and the report stay in build/test-output.
inline void expectSameImage(const std::string& stem, const std::string& pathA, const std::string& pathB) {
    const Image8 a = readPng(pathA), b = readPng(pathB);
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    const CompareResult r = compareImages(a, b);
    const bool exact = a.data == b.data;
    if (!exact || !r.pass) {
        const std::vector<std::string> files = writeCompareEvidence(outputPath(stem), a, b, r);
        ADD_FAILURE() << pathA << " vs " << pathB << (exact ? "" : ": not byte-identical") << "\n"
                      << compareSummary(r) << "evidence: " << files[0] << " ...";
    }
}

inline bool sameBytes(const std::string& pathA, const std::string& pathB) {
    return readPng(pathA).data == readPng(pathB).data;
}

// The pixel of the tests' kW x kH images that contains a world point.
inline glm::ivec2 pixelOf(const Scene& scene, const glm::vec3& p) { return pixelOf(scene, kW, kH, p); }

}  // namespace shadelab::test
