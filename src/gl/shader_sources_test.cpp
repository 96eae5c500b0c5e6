// ShaderLibrary and firstLogError without a GL context: #include expansion, the #line numbers that map
// every line of the expanded text back to its file and line, and driver logs rewritten to "file:line".
#include "gl/shader_sources.h"
#include "gl/program.h"

#include "util/input_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace shadelab::gl {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> linesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    return lines;
}

// Replays the GLSL preprocessor's line counting over `src` (GLSL 3.30 §3.4: after "#line L S" the next line
// is line L of source string S) and returns the lines whose text differs from that line of that file, as
// read by `read`. The prelude before the first #line is skipped.
template <class Read>
std::vector<std::string> misplacedLines(const ShaderSource& src, Read read) {
    std::vector<std::string> wrong;
    std::map<std::string, std::vector<std::string>> files;
    int file = -1, line = 0;
    for (const std::string& l : linesOf(src.text)) {
        if (l.rfind("#line ", 0) == 0) {
            std::istringstream(l.substr(6)) >> line >> file;
            continue;
        }
        if (file < 0) continue;
        const std::string& name = src.files.at(size_t(file));
        if (!files.count(name)) files[name] = linesOf(read(name));
        const std::vector<std::string>& original = files[name];
        if (line < 1 || size_t(line) > original.size() || original[size_t(line) - 1] != l)
            wrong.push_back(src.files[size_t(file)] + ":" + std::to_string(line) + ": " + l);
        ++line;
    }
    return wrong;
}

std::string readText(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

class ShaderFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "shader_files" /
               ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        write("a.frag", "void a1();\n#include \"b.glsl\"\nvoid a3();\n  #include \"c.glsl\"\nvoid a5();\n");
        write("b.glsl", "void b1();\nvoid b2();\n#include \"c.glsl\"\nvoid b4();\n");
        write("c.glsl", "void c1();\nvoid c2();\n");
    }
    void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }
    std::string read(const std::string& name) const { return readText(dir_ / name); }
    fs::path dir_;
};

TEST_F(ShaderFiles, IncludesExpandWithLineMapping) {
    const ShaderLibrary lib(dir_.string());
    const ShaderSource src = lib.load("a.frag", "#define X 1");
    EXPECT_EQ(src.files, (std::vector<std::string>{"a.frag", "b.glsl", "c.glsl", "c.glsl"}));
    EXPECT_EQ(src.text.rfind("#version 330 core\n#define SL_FN\n#define X 1\n#line 1 0\nvoid a1();\n", 0), 0u)
        << src.text;
    EXPECT_EQ(misplacedLines(src, [&](const std::string& f) { return read(f); }), std::vector<std::string>{});
    for (const char* line : {"void a5();", "void b4();", "void c2();"})
        EXPECT_NE(src.text.find(line), std::string::npos) << line;
}

// Negative control: the replay catches a #line directive that is off by one.
TEST_F(ShaderFiles, MisplacedLineIsCaught) {
    ShaderSource src = ShaderLibrary(dir_.string()).load("a.frag");
    const size_t at = src.text.find("#line 4 1");
    ASSERT_NE(at, std::string::npos) << src.text;
    src.text.replace(at, 9, "#line 5 1");
    EXPECT_EQ(misplacedLines(src, [&](const std::string& f) { return read(f); }).size(), 1u);
}

TEST_F(ShaderFiles, BadIncludesNameTheFile) {
    write("missing.frag", "void m();\n#include \"nowhere.glsl\"\n");
    write("malformed.frag", "void m();\n#include \"nowhere.glsl\n");
    write("loop.frag", "#include \"loop.frag\"\n");
    const ShaderLibrary lib(dir_.string());
    const auto message = [&](const std::string& name) {
        try {
            lib.load(name);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message("missing.frag").find("nowhere.glsl: cannot read"), std::string::npos) << message("missing.frag");
    EXPECT_EQ(message("malformed.frag"), "shaders/malformed.frag: line 2: malformed #include");
    EXPECT_EQ(message("loop.frag"), "shaders/loop.frag: #include nested too deeply");
    EXPECT_EQ(message("absent.frag").rfind((dir_ / "absent.frag").string() + ": cannot read", 0), 0u);
}

// The copies embedded at build time are the files of shaders/, and every line maps back to them.
TEST(EmbeddedShaders, MatchTheSourceTree) {
    const fs::path shaders = fs::path(SHADELAB_SOURCE_DIR) / "shaders";
    ASSERT_FALSE(embeddedShaders().empty());
    for (const EmbeddedShader& s : embeddedShaders()) EXPECT_EQ(s.text, readText(shaders / s.name)) << s.name;
    const ShaderSource src = ShaderLibrary(shaders.string()).load("sphere.frag");
    for (const char* f : {"surface.glsl", "lighting.glsl", "frame.glsl", "shadow.glsl", "cube_face.glsl"})
        EXPECT_NE(std::find(src.files.begin(), src.files.end(), f), src.files.end()) << f;
    EXPECT_EQ(misplacedLines(src, [&](const std::string& f) { return readText(shaders / f); }),
              std::vector<std::string>{});
}

// The ES dialect changes the prelude only: #version 300 es, every precision the shaders need, clip distances
// off; the defines and files follow as in the desktop dialect, and every line still maps back to its file.
TEST(ShaderDialects, EsPreludeThenTheSameText) {
    const fs::path shaders = fs::path(SHADELAB_SOURCE_DIR) / "shaders";
    const ShaderLibrary desktop(shaders.string());
    const ShaderLibrary es = desktop.withDialect(ShaderDialect::Essl300);
    EXPECT_EQ(desktop.dialect(), ShaderDialect::Glsl330);
    EXPECT_EQ(es.dialect(), ShaderDialect::Essl300);
    const ShaderSource a = desktop.load("mesh.frag", "#define X 1");
    const ShaderSource b = es.load("mesh.frag", "#define X 1");
    const std::string prelude(shaderPrelude(ShaderDialect::Essl300));
    EXPECT_EQ(b.text.rfind("#version 300 es\n", 0), 0u) << b.text.substr(0, 200);
    EXPECT_EQ(b.text.rfind(prelude + "#define X 1\n#line 1 0\n", 0), 0u) << b.text.substr(0, 600);
    for (const char* line : {"precision highp float;", "precision highp int;", "precision highp sampler2DArray;",
                             "precision highp usampler2D;", "#define SL_CLIP_DISTANCE 0", "#define SL_FN"})
        EXPECT_NE(prelude.find(line), std::string::npos) << line;
    // After the prelude the two texts are the same.
    const std::string desktopPrelude(shaderPrelude(ShaderDialect::Glsl330));
    EXPECT_EQ(desktopPrelude, "#version 330 core\n#define SL_FN\n");
    EXPECT_EQ(a.text.substr(desktopPrelude.size()), b.text.substr(prelude.size()));
    EXPECT_EQ(a.files, b.files);
    EXPECT_EQ(misplacedLines(b, [&](const std::string& f) { return readText(shaders / f); }),
              std::vector<std::string>{});
    // GL_VERSION strings: ES contexts say so first; desktop ones start with the number.
    EXPECT_EQ(dialectForVersion("OpenGL ES 3.2 Mesa 22.3.6"), ShaderDialect::Essl300);
    EXPECT_EQ(dialectForVersion("OpenGL ES 3.0 (WebGL 2.0 (OpenGL ES 3.0 Chromium))"), ShaderDialect::Essl300);
    EXPECT_EQ(dialectForVersion("4.5 (Core Profile) Mesa 22.3.6"), ShaderDialect::Glsl330);
    EXPECT_EQ(dialectForVersion("3.3.0 NVIDIA 535.54"), ShaderDialect::Glsl330);
    // Negative control: a text that only mentions ES later is desktop GL.
    EXPECT_EQ(dialectForVersion("4.6 OpenGL ES compatible"), ShaderDialect::Glsl330);
}

TEST(FirstLogError, MesaAndNvidiaLogsNameFileAndLine) {
    ShaderSource src;
    src.files = {"mesh.frag", "surface.glsl", "shadow.glsl"};
    std::string file = "mesh.frag";
    int line = -1;
    // Mesa: warnings are skipped, the first error is rewritten.
    EXPECT_EQ(firstLogError("0:3(5): warning: unused\n2:41(12): error: `q' undeclared\n1:2(1): error: later\n", src,
                            &file, &line),
              "error: `q' undeclared");
    EXPECT_EQ(file, "shadow.glsl");
    EXPECT_EQ(line, 41);
    EXPECT_EQ(firstLogError("1(17) : error C1008: undefined variable \"x\"\n", src, &file, &line),
              "error C1008: undefined variable \"x\"");
    EXPECT_EQ(file, "surface.glsl");
    EXPECT_EQ(line, 17);
    // A source-string number past the map keeps the caller's file; an unknown format gives its first line.
    file = "mesh.frag";
    EXPECT_EQ(firstLogError("7:5(1): error: odd\n", src, &file, &line), "error: odd");
    EXPECT_EQ(file, "mesh.frag");
    EXPECT_EQ(firstLogError("\nsomething broke\nmore\n", src, &file, &line), "something broke");
    EXPECT_EQ(line, 0);
    EXPECT_EQ(firstLogError("", src, &file, &line), "compilation failed with no log");
}

}  // namespace
}  // namespace shadelab::gl
