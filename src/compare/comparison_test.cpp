// comparisonDepth: the user's depth wins; otherwise the scene's, at most the rasterizer's one bounce.
#include "compare/comparison.h"

#include <gtest/gtest.h>

namespace shadelab {
namespace {

TEST(ComparisonDepth, SceneDepthCappedAtOneBounce) {
    Scene scene;
    EXPECT_EQ(scene.maxDepth, 5);
    EXPECT_EQ(comparisonDepth(scene), 1);
    scene.maxDepth = 0;
    EXPECT_EQ(comparisonDepth(scene), 0);
    scene.maxDepth = 1;
    EXPECT_EQ(comparisonDepth(scene, std::nullopt), 1);
}

TEST(ComparisonDepth, RequestedDepthWins) {
    Scene scene;
    EXPECT_EQ(comparisonDepth(scene, 3), 3);
    EXPECT_EQ(comparisonDepth(scene, 0), 0);
    scene.maxDepth = 0;
    EXPECT_EQ(comparisonDepth(scene, 7), 7);
}

}  // namespace
}  // namespace shadelab
