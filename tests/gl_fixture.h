// A headless GL context shared by every test in one binary, created on first use. No context is a test
// failure, not a skip: CI machines always have Mesa's llvmpipe.
#pragma once

#include "gl/headless_context.h"

#include <gtest/gtest.h>
#include <memory>
#include <string>

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

class GlTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string error;
        if (!sharedContext(&error)) FAIL() << "no headless GL context: " << error;
    }
};

}  // namespace shadelab::test
