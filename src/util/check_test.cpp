// Tests for util/check.h: a failing CHECK prints the condition (and the _OP forms both operands) and aborts, in
// every build; DCHECKs do the same without NDEBUG and in Release neither fail nor evaluate their operands.
#include "util/check.h"

#include <gtest/gtest.h>

namespace {

int gCalls = 0;
int counted(int v) {
    ++gCalls;
    return v;
}

class CheckDeathTest : public ::testing::Test {
protected:
    // Death tests fork; "threadsafe" re-runs the test binary in the child, which is safe with the threads other
    // tests in the binary may have started.
    void SetUp() override { GTEST_FLAG_SET(death_test_style, "threadsafe"); }
};

TEST_F(CheckDeathTest, PassingChecksDoNothing) {
    SHADELAB_CHECK(1 + 1 == 2);
    SHADELAB_CHECK_EQ(2, 2);
    SHADELAB_CHECK_NE(2, 3);
    SHADELAB_CHECK_LT(2, 3);
    SHADELAB_CHECK_LE(3, 3);
    SHADELAB_CHECK_GE(3, 3);
    SHADELAB_CHECK_GT(4, 3);
}

// The negative control for every test that relies on a CHECK: a false condition aborts, naming itself.
TEST_F(CheckDeathTest, FailingCheckAbortsNamingTheCondition) {
    EXPECT_DEATH(SHADELAB_CHECK(1 + 1 == 3), "CHECK failed: 1 \\+ 1 == 3");
    const int width = 640, height = 480;
    EXPECT_DEATH(SHADELAB_CHECK_EQ(width, height), "CHECK failed: width == height \\(640 vs 480\\)");
    EXPECT_DEATH(SHADELAB_CHECK_LT(height, width / 2), "CHECK failed: height < width / 2 \\(480 vs 320\\)");
    EXPECT_DEATH(SHADELAB_CHECK_NE(width, 640), "CHECK failed: width != 640");
}

TEST_F(CheckDeathTest, CheckEvaluatesEachOperandOnce) {
    gCalls = 0;
    SHADELAB_CHECK_EQ(counted(3), 3);
    SHADELAB_CHECK(counted(1) == 1);
    EXPECT_EQ(gCalls, 2);
}

TEST_F(CheckDeathTest, DcheckFailsOnlyWithoutNdebug) {
    gCalls = 0;
    SHADELAB_DCHECK(counted(1) == 1);
    SHADELAB_DCHECK_EQ(counted(2), 2);
    EXPECT_EQ(gCalls, shadelab::kDcheckEnabled ? 2 : 0);
    if (shadelab::kDcheckEnabled) {
        EXPECT_DEATH(SHADELAB_DCHECK(counted(1) == 2), "CHECK failed: counted\\(1\\) == 2");
        EXPECT_DEATH(SHADELAB_DCHECK_GE(counted(-2), -1), "CHECK failed: counted\\(-2\\) >= -1 \\(-2 vs -1\\)");
    } else {
        // Compiled out: a false DCHECK neither aborts nor runs its operands.
        SHADELAB_DCHECK(counted(1) == 2);
        SHADELAB_DCHECK_GE(counted(-2), -1);
        EXPECT_EQ(gCalls, 0);
    }
}

}  // namespace
