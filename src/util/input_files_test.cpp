// Tests for util/input_files.h: a file read under an InputRecorder cannot be replaced by any write while the
// record lives, under any name for it; once the record is gone (the scene closed), the same write succeeds.
#include "util/input_files.h"

#include "util/atomic_file.h"
#include "util/input_error.h"
#include "util/output_file.h"
#include "util/read_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>
#include <thread>

namespace fs = std::filesystem;
using namespace shadelab;

namespace {

class InputFilesTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "input_files" / info->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

// The message writeFileAtomic throws for `path`, or "" when it writes.
std::string writeRefusal(const std::string& path, const std::string& text) {
    try {
        writeFileAtomic(path, text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_F(InputFilesTest, ARecordedInputIsNeverReplacedUnderAnyName) {
    writeFileAtomic(path("scene.json"), "{\"scene\": 1}");
    fs::create_symlink("scene.json", dir_ / "link.json");
    fs::create_hard_link(path("scene.json"), dir_ / "hard.json");
    std::optional<InputFiles> inputs(std::in_place);
    {
        InputRecorder recorder(*inputs);
        EXPECT_EQ(readFile(path("scene.json")), "{\"scene\": 1}");
    }
    ASSERT_EQ(inputs->paths(), std::vector<std::string>{path("scene.json")});
    for (const std::string name : {"scene.json", "link.json", "hard.json", "./scene.json"}) {
        const std::string target = name[0] == '.' ? (dir_ / "." / "scene.json").string() : path(name);
        EXPECT_NE(writeRefusal(target, "png bytes"), "") << target;
        EXPECT_THROW(checkWritableTarget(target), InputError) << target;
    }
    EXPECT_EQ(writeRefusal(path("scene.json"), "x"),
              path("scene.json") + ": refusing to overwrite an input with the output");
    EXPECT_EQ(readFile(path("scene.json")), "{\"scene\": 1}") << "the input is byte-identical";
    // A copy holds the record too; only when the last copy is gone is the file an ordinary file again.
    const InputFiles copy = *inputs;
    inputs.reset();
    EXPECT_NE(writeRefusal(path("scene.json"), "x"), "");
}

TEST_F(InputFilesTest, NegativeControlAFileOutsideAnyRecordIsWritten) {
    writeFileAtomic(path("scene.json"), "{}");
    EXPECT_EQ(readFile(path("scene.json")), "{}");  // read, but with no recorder alive: not an input
    EXPECT_EQ(writeRefusal(path("scene.json"), "new"), "");
    EXPECT_EQ(readFile(path("scene.json")), "new");
    {
        InputFiles inputs;
        InputRecorder recorder(inputs);
        readFile(path("scene.json"));
    }  // the record died with the scope
    EXPECT_EQ(writeRefusal(path("scene.json"), "newer"), "");
    EXPECT_EQ(readFile(path("scene.json")), "newer");
}

TEST_F(InputFilesTest, RecordersAreScopedToTheirThreadAndNest) {
    writeFileAtomic(path("a"), "a");
    writeFileAtomic(path("b"), "b");
    InputFiles outer, inner;
    InputRecorder o(outer);
    readFile(path("a"));
    {
        InputRecorder i(inner);
        readFile(path("b"));
        std::thread([&] { readFile(path("a")); }).join();  // another thread records nothing
    }
    EXPECT_EQ(outer.paths(), std::vector<std::string>{path("a")});
    EXPECT_EQ(inner.paths(), std::vector<std::string>{path("b")});
}

TEST_F(InputFilesTest, DerivedNamesFromADeviceOrStdoutAreRefused) {
    EXPECT_THROW(derivedOutput("/dev/null", "_heat.png"), InputError);
    EXPECT_THROW(derivedOutput("-", "_report.json"), InputError);
    EXPECT_THROW(derivedOutput(dir_.string(), "_a.png"), InputError) << "a folder is no stem";
    EXPECT_FALSE(fs::exists("/dev/null_heat.png"));
    // Negative control: an ordinary stem, existing or not, gives the derived name.
    EXPECT_EQ(derivedOutput(path("run"), "_heat.png"), path("run_heat.png"));
    writeFileAtomic(path("file"), "x");
    EXPECT_EQ(derivedOutput(path("file"), "_report.json"), path("file_report.json"));
}
