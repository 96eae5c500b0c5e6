// outsideClip: the conservative box-against-clip-volume cull of the colour, mirror and shadow passes.
#include "raster/draw_range.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace shadelab::raster {
namespace {

const glm::mat4 kIdentity(1.0f);

TEST(OutsideClip, BoxesAgainstTheUnitClipCube) {
    EXPECT_FALSE(outsideClip(kIdentity, glm::vec3(-0.5f), glm::vec3(0.5f)));        // inside
    EXPECT_FALSE(outsideClip(kIdentity, glm::vec3(-5.0f), glm::vec3(5.0f)));        // contains it
    EXPECT_FALSE(outsideClip(kIdentity, {0.9f, 0.0f, 0.0f}, {3.0f, 0.1f, 0.1f}));   // straddles x = 1
    EXPECT_TRUE(outsideClip(kIdentity, {1.1f, 0.0f, 0.0f}, {3.0f, 0.1f, 0.1f}));    // beyond x = 1
    EXPECT_TRUE(outsideClip(kIdentity, {-3.0f, 0.0f, 0.0f}, {-1.1f, 0.1f, 0.1f}));  // beyond x = -1
    EXPECT_TRUE(outsideClip(kIdentity, {0.0f, 1.1f, 0.0f}, {0.1f, 2.0f, 0.1f}));    // above
    EXPECT_TRUE(outsideClip(kIdentity, {0.0f, -2.0f, 0.0f}, {0.1f, -1.1f, 0.1f}));  // below
    EXPECT_TRUE(outsideClip(kIdentity, {0.0f, 0.0f, -2.0f}, {0.1f, 0.1f, -1.1f}));  // before near
    EXPECT_FALSE(outsideClip(kIdentity, {0.0f, 0.0f, 1.1f}, {0.1f, 0.1f, 2.0f}));   // far is ignored
}

// Conservative: only a box with all eight corners beyond one plane is culled.
TEST(OutsideClip, CornersSplitBetweenPlanes) {
    EXPECT_TRUE(outsideClip(kIdentity, {1.2f, 1.2f, 0.0f}, {3.0f, 3.0f, 0.1f}));
    EXPECT_FALSE(outsideClip(kIdentity, {0.5f, 0.5f, 0.0f}, {3.0f, 3.0f, 0.1f}));
    // Rotated 45° about z, the box around (1.8, 0, 0) of half-size 0.3 becomes a diamond wholly beyond the
    // clip square's corner (its nearest edge has x' + y' > 2), but with corners beyond x' = 1 only and
    // beyond y' = 1 only: no single plane holds all eight, so it is kept (drawn, and clipped by GL).
    const glm::mat4 rot = glm::rotate(glm::mat4(1.0f), glm::radians(45.0f), glm::vec3(0, 0, 1));
    const glm::vec3 c(1.8f, 0.0f, 0.0f), h(0.3f, 0.3f, 0.1f);
    const glm::vec4 a = rot * glm::vec4(c.x - h.x, c.y + h.y, 0, 1), b = rot * glm::vec4(c.x - h.x, c.y - h.y, 0, 1);
    ASSERT_LT(a.x, 1.0f);
    ASSERT_GT(b.x, 1.0f);
    ASSERT_LT(b.y, 1.0f);
    ASSERT_GT(a.x + a.y, 2.0f);
    EXPECT_FALSE(outsideClip(rot, c - h, c + h));
}

// Through a camera: a box behind the eye is culled by the near plane, one in front is kept, one off to the
// side of a 90° frustum is culled.
TEST(OutsideClip, PerspectiveCamera) {
    const glm::mat4 vp = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f) *
                         glm::lookAt(glm::vec3(0.0f), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
    EXPECT_FALSE(outsideClip(vp, {-0.5f, -0.5f, -6.0f}, {0.5f, 0.5f, -5.0f}));
    EXPECT_TRUE(outsideClip(vp, {-0.5f, -0.5f, 5.0f}, {0.5f, 0.5f, 6.0f}));
    EXPECT_TRUE(outsideClip(vp, {6.0f, -0.5f, -5.0f}, {7.0f, 0.5f, -4.0f}));        // x > |z|: right of the frustum
    EXPECT_FALSE(outsideClip(vp, {4.0f, -0.5f, -5.0f}, {7.0f, 0.5f, -4.0f}));       // straddles its right side
    EXPECT_FALSE(outsideClip(vp, {-0.5f, -0.5f, -500.0f}, {0.5f, 0.5f, -400.0f}));  // beyond far: kept
}

}  // namespace
}  // namespace shadelab::raster
