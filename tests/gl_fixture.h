// A headless GL context shared by every test in one binary, created on first use. No context is a test
// failure, not a skip: CI machines always have Mesa's llvmpipe. In Debug and sanitizer builds a GL error the
// driver reports during a test (gl/debug_output.h) fails that test.
#pragma once

#include "gl/debug_output.h"
#include "gl/headless_context.h"

#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>

namespace shadelab::test {

inline gl::HeadlessContext* sharedContext(std::string* error) {
    static std::unique_ptr<gl::HeadlessContext> ctx;
    static std::string failure;
    if (!ctx && failure.empty()) {
        try {
            ctx = gl::createHeadlessContext();
        } catch (const std::exception& e) {
            failure = e.what();
        }
    }
    if (error) *error = failure;
    return ctx.get();
}

// Fails the current test if the driver reported GL errors since the last call (none are recorded in Release).
inline void expectNoGlErrors(const char* when) {
    const std::vector<std::string> errors = gl::takeDebugErrors();
    std::string list;
    for (const std::string& e : errors) list += "\n  " + e;
    EXPECT_TRUE(errors.empty()) << errors.size() << " GL error(s) " << when << ":" << list;
}

class GlTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string error;
        if (!sharedContext(&error)) FAIL() << "no headless GL context: " << error;
        expectNoGlErrors("before this test (from creating the context, or from a test without this fixture)");
    }
    void TearDown() override { expectNoGlErrors("during this test"); }
};

}  // namespace shadelab::test
