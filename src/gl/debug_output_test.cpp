// Tests for gl/debug_output.h on a headless context (llvmpipe): Debug builds record the GL errors the driver
// reports, and a deliberately wrong call is the negative control that shows the record is not blind; Release
// builds have no callback and record nothing.
#include "gl/debug_output.h"

#include "gl/gl_api.h"
#include "gl/headless_context.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace {

using namespace shadelab;

// Not a texture target: glBindTexture must fail with GL_INVALID_ENUM (and change nothing).
constexpr GLenum kNotATextureTarget = 0x1234;

class DebugOutput : public ::testing::Test {
protected:
    static void SetUpTestSuite() { context_ = gl::createHeadlessContext(); }
    static void TearDownTestSuite() { context_.reset(); }
    void SetUp() override {
        ASSERT_TRUE(context_);
        gl::takeDebugErrors();
        while (glGetError() != GL_NO_ERROR) {}
    }

    static std::unique_ptr<gl::HeadlessContext> context_;
};

std::unique_ptr<gl::HeadlessContext> DebugOutput::context_;

TEST_F(DebugOutput, OnInDebugBuildsOnly) {
    EXPECT_EQ(gl::debugOutputActive(), gl::kDebugOutputBuild)
        << "on " << context_->info().device << ", " << context_->info().renderer;
#ifdef NDEBUG
    EXPECT_FALSE(gl::kDebugOutputBuild);
#else
    EXPECT_TRUE(gl::kDebugOutputBuild);
#endif
}

// The negative control: one wrong call is one recorded error, naming the call, in the build that checks.
TEST_F(DebugOutput, AnInjectedErrorIsRecorded) {
    glBindTexture(kNotATextureTarget, 0);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));  // the error itself is there in every build
    const std::vector<std::string> errors = gl::takeDebugErrors();
    if (!gl::kDebugOutputBuild) {
        EXPECT_TRUE(errors.empty());
        return;
    }
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_NE(errors[0].find("API error"), std::string::npos) << errors[0];
    EXPECT_NE(errors[0].find("glBindTexture"), std::string::npos) << errors[0];
    EXPECT_TRUE(gl::takeDebugErrors().empty()) << "taking the errors forgets them";
}

TEST_F(DebugOutput, CorrectCallsRecordNothing) {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    const unsigned char texel[4] = {1, 2, 3, 4};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    glBindTexture(GL_TEXTURE_2D, 0);
    glDeleteTextures(1, &texture);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    EXPECT_TRUE(gl::takeDebugErrors().empty());
}

// A shader that does not compile is an input error (Program::build names its file and line), not a GL error.
TEST_F(DebugOutput, ShaderCompileErrorsAreNotRecorded) {
    const GLuint shader = glCreateShader(GL_FRAGMENT_SHADER);
    const char* text = "#version 330 core\nthis is not GLSL;\n";
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_TRUE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    glDeleteShader(shader);
    EXPECT_EQ(ok, GL_FALSE);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    EXPECT_TRUE(gl::takeDebugErrors().empty());
}

TEST_F(DebugOutput, ARunOfErrorsIsCappedAndCounted) {
    if (!gl::kDebugOutputBuild) GTEST_SKIP() << "Release build: no callback";
    const size_t extra = 10;
    for (size_t i = 0; i < gl::kMaxRecordedErrors + extra; ++i) glBindTexture(kNotATextureTarget, 0);
    while (glGetError() != GL_NO_ERROR) {}
    const std::vector<std::string> errors = gl::takeDebugErrors();
    ASSERT_EQ(errors.size(), gl::kMaxRecordedErrors + 1);
    EXPECT_EQ(errors.back(), "and " + std::to_string(extra) + " more GL errors");
}

}  // namespace
