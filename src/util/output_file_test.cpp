// Tests for the output rules of util/output_file.h: an output that is an input (same device and inode,
// however it is spelt) is refused, a new or different file is not, and "-" writes the bytes to stdout.
#include "util/output_file.h"

#include "util/atomic_file.h"
#include "util/input_error.h"
#include "util/read_file.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using namespace shadelab;

namespace {

class OutputFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "output_file" / info->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

// The InputError message refuseInputAsOutput throws, or "" when it accepts.
std::string refusal(const std::string& output, const std::vector<std::string>& inputs) {
    try {
        refuseInputAsOutput(output, "-o", inputs);
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), output);
        return e.what();
    }
    return "";
}

}  // namespace

TEST_F(OutputFileTest, OutputThatIsAnInputIsRefusedHoweverSpelt) {
    writeFileAtomic(path("scene.json"), "{}");
    const std::string scene = path("scene.json");
    EXPECT_EQ(refusal(scene, {scene}), scene + ": refusing to overwrite an input with the output (-o)");
    const std::string dotted = (dir_ / "." / "scene.json").string();
    EXPECT_EQ(refusal(dotted, {scene}),
              dotted + ": refusing to overwrite an input with the output (-o): it is " + scene);
    fs::create_symlink("scene.json", dir_ / "link.json");
    EXPECT_NE(refusal(path("link.json"), {scene}), "");
    fs::create_hard_link(scene, dir_ / "hard.json");
    EXPECT_NE(refusal(path("hard.json"), {"/nonexistent/input", scene}), "") << "the second input counts too";
    // checkOutput makes the same refusal before its writability checks.
    EXPECT_THROW(checkOutput(scene, "-o", {scene}), InputError);
    EXPECT_EQ(readFile(scene), "{}");
}

TEST_F(OutputFileTest, NewOrDifferentFilesAreAccepted) {
    writeFileAtomic(path("scene.json"), "{}");
    writeFileAtomic(path("old.png"), "png");
    EXPECT_EQ(refusal(path("new.png"), {path("scene.json")}), "") << "a file that does not exist is no input";
    EXPECT_EQ(refusal(path("old.png"), {path("scene.json")}), "");
    EXPECT_EQ(refusal(path("old.png"), {path("missing.json")}), "");
    EXPECT_EQ(refusal("-", {"-"}), "") << "stdout is never an input file";
    EXPECT_NO_THROW(checkOutput(path("old.png"), "-o", {path("scene.json")}));
    EXPECT_NO_THROW(checkOutput("-", "-o", {path("scene.json")}));
}

// A missing folder (and its parents) is created by the up-front check, so `-o out/x.png` works in a fresh
// clone; a path through an existing file is still refused in one line, and the check alone of
// checkWritableTarget (negative control) still refuses the missing folder.
TEST_F(OutputFileTest, MissingFoldersAreCreatedButNotThroughAFile) {
    const std::string nested = path("out/sub/x.png");
    EXPECT_THROW(checkWritableTarget(nested), InputError);
    checkOutput(nested, "-o", {});
    EXPECT_TRUE(fs::is_directory(dir_ / "out" / "sub"));
    EXPECT_FALSE(fs::exists(nested)) << "the check writes no file";
    writeOutput(nested, "png", 3);
    EXPECT_EQ(readFile(nested), "png");
    writeOutput(path("file"), "keep", 4);
    for (const char* under : {"file/x.png", "file/sub/x.png"}) {
        try {
            checkOutput(path(under), "-o", {});
            ADD_FAILURE() << under << ": a folder under a file was accepted";
        } catch (const InputError& e) {
            EXPECT_EQ(e.file(), path(under));
            EXPECT_NE(std::string(e.what()).find("Not a directory"), std::string::npos) << e.what();
        }
    }
    EXPECT_EQ(readFile(path("file")), "keep");
}

TEST_F(OutputFileTest, DashWritesToStdout) {
    // Send fd 1 to a file for the duration of the call; flush gtest's own output first so it stays out.
    std::fflush(stdout);
    const int saved = ::dup(STDOUT_FILENO);
    ASSERT_GE(saved, 0);
    const int file = ::open(path("captured").c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    ASSERT_GE(file, 0);
    ::dup2(file, STDOUT_FILENO);
    ::close(file);
    static const char kBytes[] = "\x89PNG\r\n\x1a\n binary \0 data";  // an embedded NUL: sized by the array
    const std::string bytes(kBytes, sizeof kBytes - 1);
    writeOutput("-", bytes.data(), bytes.size());
    ::dup2(saved, STDOUT_FILENO);
    ::close(saved);
    EXPECT_EQ(readFile(path("captured")), bytes);
    EXPECT_FALSE(fs::exists(dir_ / "-")) << "no file named '-'";
    EXPECT_TRUE(isStdout("/dev/stdout"));
    EXPECT_FALSE(isStdout("./-"));
    // Anything else is a file.
    writeOutput(path("out.bin"), bytes.data(), bytes.size());
    EXPECT_EQ(readFile(path("out.bin")), bytes);
}
