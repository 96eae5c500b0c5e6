// `render --ray-tree X,Y`: the pixel's Whitted ray tree drawn on the PNG and listed on stderr, the
// picture otherwise untouched; its refusals are usage errors.
#include "cli_run.h"
#include "image/png.h"
#include "test_output.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

using namespace shadelab;
using namespace shadelab::test;

TEST(CliRayTree, DrawsThePixelsTreeAndListsItsRays) {
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    const std::string plain = test::outputPath("ray_tree_plain.png"), drawn = test::outputPath("ray_tree_drawn.png");
    const std::string common = " --size 320x180 --renderer trace --threads 2";
    ASSERT_EQ(run("render " + scene + " -o " + plain + common).code, 0);
    // The floor beside the blue sphere: lit by the key, the fill blocked by the sphere.
    Result r = run("render " + scene + " -o " + drawn + common + " --ray-tree 70,125");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("0 primary -> floor (plane 1)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("shadow to L1 warm key: lit"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("blocked by shiny blue (sphere 2)"), std::string::npos) << r.out;
    const Image8 a = readPng(plain), b = readPng(drawn);
    ASSERT_EQ(a.width, b.width);
    // Drawn: pixels near the probed one changed, the far corner did not.
    int changed = 0, changedNear = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const uint8_t *p = a.pixel(x, y), *q = b.pixel(x, y);
            const bool d = p[0] != q[0] || p[1] != q[1] || p[2] != q[2];
            changed += d;
            changedNear += d && std::abs(x - 70) <= 6 && std::abs(y - 125) <= 6;
            if (x > 280 && y > 150) {
                EXPECT_FALSE(d) << "pixel " << x << "," << y << " is far from the tree";
            }
        }
    EXPECT_GT(changedNear, 20) << "the ring at the probed pixel; images: " << plain << ", " << drawn;
    EXPECT_GT(changed, 200) << "the shadow rays' lines";
    // Negative control: another pixel draws another tree.
    const std::string other = test::outputPath("ray_tree_other.png");
    ASSERT_EQ(run("render " + scene + " -o " + other + common + " --ray-tree 250,60").code, 0);
    EXPECT_NE(readAll(other), readAll(drawn));
}

TEST(CliRayTree, RefusalsAreUsageErrors) {
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    const std::string out = test::outputPath("ray_tree_refused.png");
    auto refused = [&](const std::string& args, const std::string& words) {
        Result r = run("render " + scene + " --size 64x36 " + args);
        EXPECT_EQ(r.code, 2) << args << ": " << r.out;
        EXPECT_NE(r.out.find(words), std::string::npos) << args << ": " << r.out;
        EXPECT_EQ(lineCount(r.out), 1) << r.out;
    };
    refused("-o " + out + " --ray-tree 10", "--ray-tree: expected X,Y");
    refused("-o " + out + " --ray-tree a,b", "--ray-tree: expected a whole number");
    refused("-o " + out + " --ray-tree 64,0", "outside the 64x36 image");
    refused("-o " + out + " --ray-tree -1,3", "outside the 64x36 image");
    refused("-o " + out + " --ray-tree 1,1 --renderer both", "only with --renderer raster, trace or path");
    refused("-o " + test::outputPath("ray_tree.exr") + " --ray-tree 1,1", "--ray-tree: only for a PNG output");
}
