// differenceSites and describeDifference: over-threshold interior pixels counted by object, band pixels left
// out, and the sentence naming the main objects with their usual cause.
#include "compare/difference_sites.h"

#include <gtest/gtest.h>

namespace shadelab {
namespace {

Scene mirrorOnFloor() {
    Scene s;
    Sphere mirror;
    mirror.name = "mirror";
    mirror.material.kr = glm::vec3(0.9f);
    s.spheres.push_back(mirror);
    Sphere matte;
    s.spheres.push_back(matte);
    Plane floor;
    floor.name = "floor";
    s.planes.push_back(floor);
    s.lights.push_back(Light{});
    return s;
}

Image8 gray(int w, int h, uint8_t v) {
    Image8 img;
    img.width = w;
    img.height = h;
    img.channels = 3;
    img.data.assign(size_t(w) * size_t(h) * 3, v);
    return img;
}

TEST(DifferenceSites, CountsInteriorPixelsOverTheThresholdByObject) {
    const int w = 10, h = 1;
    Image8 a = gray(w, h, 100), b = gray(w, h, 100);
    // coverage: 1 1 1 1 1 1 3 3 3 0 (mirror, floor, background)
    std::vector<uint32_t> cov = {1, 1, 1, 1, 1, 1, 3, 3, 3, 0};
    for (int x : {0, 1, 2, 3}) b.data[size_t(x) * 3] = 110;  // four mirror pixels over
    b.data[6 * 3 + 1] = 104;                                 // one floor pixel over (4 > 3)
    b.data[7 * 3 + 2] = 103;                                 // at the threshold: not over
    CompareResult r;
    r.bandMask.assign(size_t(w), 0);
    r.bandMask[3] = 1;  // a band pixel is not counted
    const DifferenceSites d = differenceSites(a, b, cov, r);
    EXPECT_EQ(d.interior, 9);
    EXPECT_EQ(d.over, 4);
    ASSERT_EQ(d.sites.size(), 2u);
    EXPECT_EQ(d.sites[0].id, 1u);
    EXPECT_EQ(d.sites[0].pixels, 3);
    EXPECT_EQ(d.sites[1].id, 3u);
    EXPECT_EQ(d.sites[1].pixels, 1);
    // Negative control: a mismatched coverage buffer counts nothing instead of misattributing.
    cov.pop_back();
    EXPECT_EQ(differenceSites(a, b, cov, r).over, 0);
}

TEST(DifferenceSites, SentenceNamesObjectsAndCauses) {
    const Scene s = mirrorOnFloor();
    DifferenceSites d;
    d.interior = 1000;
    d.over = 20;
    d.sites = {{1, 16}, {3, 3}, {2, 1}};
    const std::string text = describeDifference(s, d, 3);
    EXPECT_EQ(text,
              "The raster and the reference differ visibly (by more than 3/255) in 2.00 % of the image. Where: "
              "mirror (sphere 1), 80 %: its reflection comes from an environment cube; floor (plane 1), 15 %: "
              "mostly shadow-map edges; sphere 2, 5 %: mostly shadow-map edges.");
    d.over = 0;
    d.sites.clear();
    EXPECT_EQ(describeDifference(s, d, 3),
              "The raster and the reference agree within 3/255 everywhere inside the objects.");
    EXPECT_EQ(coverageLabel(s, 0), "the background");
    EXPECT_EQ(coverageLabel(s, 9), "the background");
}

}  // namespace
}  // namespace shadelab
