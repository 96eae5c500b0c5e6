// Tests for Program's typed uniform setters on a headless context: they set what glUniform* sets, and in Debug
// builds they abort on the two mistakes they exist to catch (a program that is not current, a required uniform
// the program lacks); the death tests are the negative controls that show those checks are on.
#include "gl/program.h"

#include "gl/debug_output.h"
#include "gl/headless_context.h"
#include "util/check.h"

#include <gtest/gtest.h>

#include <glm/vec3.hpp>
#include <memory>

namespace {

using namespace shadelab;
using Uniform = gl::Program::Uniform;

// partial_merge.frag: a sampler, a uint array and an int that every build of it reads.
gl::Program partialMerge() { return gl::Program::build(gl::ShaderLibrary(), "fullscreen.vert", "partial_merge.frag"); }

class ProgramUniforms : public ::testing::Test {
protected:
    static void SetUpTestSuite() { context_ = gl::createHeadlessContext(); }
    static void TearDownTestSuite() { context_.reset(); }
    void SetUp() override {
        GTEST_FLAG_SET(death_test_style, "threadsafe");  // each death test re-runs the binary: its own context
        ASSERT_TRUE(context_);
        gl::takeDebugErrors();
    }
    void TearDown() override { EXPECT_TRUE(gl::takeDebugErrors().empty()); }

    static std::unique_ptr<gl::HeadlessContext> context_;
};

std::unique_ptr<gl::HeadlessContext> ProgramUniforms::context_;

TEST_F(ProgramUniforms, SettersSetTheUniformsValue) {
    const gl::Program p = partialMerge();
    glUseProgram(p.id());
    p.set("u_idCount", 5, Uniform::Required);
    p.set("u_ids[3]", 7u, Uniform::Required);
    p.setSampler("t_coverage", 2, Uniform::Required);
    p.set("u_notInTheShader", glm::vec3(1.0f));  // optional: GL ignores location -1
    GLint count = 0, coverageUnit = 0;
    glGetUniformiv(p.id(), p.uniform("u_idCount"), &count);
    glGetUniformiv(p.id(), p.uniform("t_coverage"), &coverageUnit);
    GLuint id = 0;
    glGetUniformuiv(p.id(), p.uniform("u_ids[3]"), &id);
    EXPECT_EQ(count, 5);
    EXPECT_EQ(coverageUnit, 2);
    EXPECT_EQ(id, 7u);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    glUseProgram(0);
}

TEST_F(ProgramUniforms, DebugBuildsAbortOnAProgramThatIsNotCurrent) {
    if (!kDcheckEnabled) GTEST_SKIP() << "Release build: the setters make the bare glUniform call";
    const gl::Program p = partialMerge();
    glUseProgram(0);
    EXPECT_DEATH(p.set("u_idCount", 1), "Program::set\\(\"u_idCount\"\\): program [0-9]+ is not current");
}

TEST_F(ProgramUniforms, DebugBuildsAbortOnAMissingRequiredUniform) {
    if (!kDcheckEnabled) GTEST_SKIP() << "Release build: the setters make the bare glUniform call";
    const gl::Program p = partialMerge();
    glUseProgram(p.id());
    EXPECT_DEATH(p.set("u_idCuont", 1, Uniform::Required), "Program::set\\(\"u_idCuont\"\\): .* no active uniform");
    glUseProgram(0);
}

}  // namespace
