// Tests for writeFileAtomic / readFile: round trips, no temp files left behind, and failures that
// leave the destination untouched and name the path.
#include "util/atomic_file.h"
#include "util/read_file.h"

#include "util/input_error.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <csignal>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;
using namespace shadelab;

namespace {

// A fresh, empty folder per test under the test output directory.
class AtomicFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::path(SHADELAB_TEST_OUTPUT_DIR) / "atomic_file" / info->name();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ec;
        fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, ec);
    }
    std::vector<std::string> listDir() const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

// Asserts that f throws an InputError whose message starts with the path.
template <class F>
std::string expectInputError(const std::string& path, F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), path);
        EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
        return e.what();
    }
    ADD_FAILURE() << "expected InputError for " << path;
    return {};
}

}  // namespace

TEST_F(AtomicFileTest, RoundTrip) {
    std::string data;
    for (int i = 0; i < 300000; ++i) data.push_back(char(i * 7 + (i >> 9)));
    writeFileAtomic(path("a.bin"), data.data(), data.size());
    EXPECT_EQ(readFile(path("a.bin")), data);
    EXPECT_EQ(listDir(), std::vector<std::string>{"a.bin"});
}

TEST_F(AtomicFileTest, EmptyFile) {
    writeFileAtomic(path("empty"), std::string());
    EXPECT_EQ(readFile(path("empty")), "");
    EXPECT_EQ(fs::file_size(path("empty")), 0u);
}

TEST_F(AtomicFileTest, OverwriteLeavesNoTempFiles) {
    for (int i = 0; i < 20; ++i) writeFileAtomic(path("x.txt"), "version " + std::to_string(i));
    EXPECT_EQ(readFile(path("x.txt")), "version 19");
    EXPECT_EQ(listDir(), std::vector<std::string>{"x.txt"});
}

TEST_F(AtomicFileTest, CreatedWithReadablePermissions) {
    writeFileAtomic(path("p"), "x");
    struct stat st;
    ASSERT_EQ(::stat(path("p").c_str(), &st), 0);
    EXPECT_TRUE(st.st_mode & S_IRUSR);
    EXPECT_TRUE(st.st_mode & S_IWUSR);
}

TEST_F(AtomicFileTest, MissingDirectoryThrows) {
    std::string target = path("no/such/dir/out.png");
    std::string msg = expectInputError(target, [&] { writeFileAtomic(target, "data"); });
    EXPECT_NE(msg.find("cannot write: No such file or directory"), std::string::npos) << msg;
    EXPECT_TRUE(listDir().empty());
}

TEST_F(AtomicFileTest, ParentIsRegularFileThrows) {
    writeFileAtomic(path("file"), "keep me");
    std::string target = path("file/out.png");
    std::string msg = expectInputError(target, [&] { writeFileAtomic(target, "data"); });
    EXPECT_NE(msg.find("Not a directory"), std::string::npos) << msg;
    EXPECT_EQ(readFile(path("file")), "keep me");
    EXPECT_EQ(listDir(), std::vector<std::string>{"file"});
}

TEST_F(AtomicFileTest, TargetIsDirectoryThrowsAndKeepsIt) {
    fs::create_directory(dir_ / "sub");
    writeFileAtomic(path("sub/inner"), "inner");
    std::string msg = expectInputError(path("sub"), [&] { writeFileAtomic(path("sub"), "data"); });
    EXPECT_NE(msg.find("is a directory"), std::string::npos) << msg;
    EXPECT_TRUE(fs::is_directory(dir_ / "sub"));
    EXPECT_EQ(readFile(path("sub/inner")), "inner");
    EXPECT_EQ(listDir(), std::vector<std::string>{"sub"});
}

TEST_F(AtomicFileTest, ReadOnlyDirectoryThrowsAndKeepsContent) {
    writeFileAtomic(path("out.txt"), "original");
    // Read-only for everyone. Root ignores folder permissions, so as root the write is attempted in a
    // child process that has dropped to the unprivileged user `nobody`.
    fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                              fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec,
                    fs::perm_options::replace);
    if (::geteuid() == 0) {
        pid_t pid = ::fork();
        ASSERT_GE(pid, 0);
        if (pid == 0) {
            if (::setgid(65534) != 0 || ::setuid(65534) != 0) ::_exit(3);
            try {
                writeFileAtomic(path("out.txt"), "new");
                ::_exit(1);  // the write should have failed
            } catch (const InputError& e) {
                ::_exit(std::string(e.what()).find("Permission denied") != std::string::npos ? 0 : 2);
            }
        }
        int status = 0;
        ::waitpid(pid, &status, 0);
        ASSERT_TRUE(WIFEXITED(status));
        EXPECT_EQ(WEXITSTATUS(status), 0) << "1: write succeeded, 2: wrong message, 3: could not drop privileges";
    } else {
        std::string msg = expectInputError(path("out.txt"), [&] { writeFileAtomic(path("out.txt"), "new"); });
        EXPECT_NE(msg.find("Permission denied"), std::string::npos) << msg;
    }
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add);
    EXPECT_EQ(readFile(path("out.txt")), "original");
    EXPECT_EQ(listDir(), std::vector<std::string>{"out.txt"});
}

TEST_F(AtomicFileTest, WriteFailingPartWayKeepsContent) {
    // RLIMIT_FSIZE makes write() fail part-way with EFBIG, the closest stand-in for a full disk.
    writeFileAtomic(path("out.bin"), "original");
    struct rlimit old;
    ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
    auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
    struct rlimit small = old;
    small.rlim_cur = 4096;
    ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
    std::string big(100000, 'x');
    std::string msg = expectInputError(path("out.bin"), [&] { writeFileAtomic(path("out.bin"), big); });
    ::setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, oldHandler);
    EXPECT_NE(msg.find("cannot write: File too large"), std::string::npos) << msg;
    EXPECT_EQ(readFile(path("out.bin")), "original");
    EXPECT_EQ(listDir(), std::vector<std::string>{"out.bin"});
}

TEST_F(AtomicFileTest, ParentIsDeviceThrows) {
    // ENOSPC itself needs a full file system (the temp file lives beside the target, so /dev/full cannot
    // stand in); a device as parent at least exercises the open failure outside our own folder.
    if (!fs::exists("/dev/full")) GTEST_SKIP() << "/dev/full missing";
    std::string msg = expectInputError("/dev/full/x", [&] { writeFileAtomic("/dev/full/x", "data"); });
    EXPECT_NE(msg.find("cannot write:"), std::string::npos) << msg;
}

TEST_F(AtomicFileTest, ReadMissingFileThrows) {
    std::string msg = expectInputError(path("missing"), [&] { readFile(path("missing")); });
    EXPECT_NE(msg.find("cannot read: No such file or directory"), std::string::npos) << msg;
}

TEST_F(AtomicFileTest, ReadDirectoryThrows) {
    std::string msg = expectInputError(dir_.string(), [&] { readFile(dir_.string()); });
    EXPECT_NE(msg.find("cannot read: is a directory"), std::string::npos) << msg;
}

TEST_F(AtomicFileTest, ReadNonRegularFile) {
    // /proc files report size 0 but have content; readFile must not trust st_size.
    if (!fs::exists("/proc/self/status")) GTEST_SKIP();
    EXPECT_NE(readFile("/proc/self/status").find("Name:"), std::string::npos);
}
