// Tests for writeFileAtomic / readFile: round trips, no temp files left behind (also on signals), failures
// and refused targets (devices, FIFOs, sockets, links to them) that leave the destination untouched.
#include "util/atomic_file.h"
#include "util/read_file.h"

#include "util/input_error.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
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
    fs::permissions(dir_,
                    fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read | fs::perms::group_exec |
                        fs::perms::others_read | fs::perms::others_exec,
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

// Outputs that never destroy (docs/cli.md, "Outputs"): only regular files are replaced, no temporary name is visible
// while the data is written (O_TMPFILE), the fallback's name fits any target name and is removed on signals.
namespace {

// Whether this folder's file system can make an unnamed file (ext4, xfs, btrfs, tmpfs can).
bool supportsTmpFile(const fs::path& dir) {
    int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
    if (fd < 0) return false;
    ::close(fd);
    return true;
}

std::string bigPayload() { return std::string(3u << 20, 'n'); }  // three 1 MiB chunks

}  // namespace

TEST_F(AtomicFileTest, TmpFileHasNoNameDuringTheWrite) {
    if (!supportsTmpFile(dir_)) GTEST_SKIP() << dir_ << ": file system without O_TMPFILE";
    writeFileAtomic(path("out.bin"), "original");
    std::vector<std::vector<std::string>> seen;
    AtomicWriteOptions options;
    options.afterChunk = [&](size_t) { seen.push_back(listDir()); };
    writeFileAtomic(path("out.bin"), bigPayload(), options);
    ASSERT_EQ(seen.size(), 3u);
    for (const auto& names : seen) EXPECT_EQ(names, std::vector<std::string>{"out.bin"});
    EXPECT_EQ(readFile(path("out.bin")), bigPayload());
    EXPECT_EQ(listDir(), std::vector<std::string>{"out.bin"});
}

TEST_F(AtomicFileTest, NamedFallbackUsesAShortHiddenName) {
    // Negative control for the test above: the same probe sees the fallback's temporary.
    writeFileAtomic(path("out.bin"), "original");
    std::vector<std::string> during;
    AtomicWriteOptions options;
    options.allowTmpFile = false;
    options.afterChunk = [&](size_t) {
        if (during.empty()) during = listDir();
    };
    writeFileAtomic(path("out.bin"), bigPayload(), options);
    ASSERT_EQ(during.size(), 2u);
    const std::string temp = during[0] == "out.bin" ? during[1] : during[0];
    EXPECT_EQ(temp[0], '.') << temp;
    EXPECT_LE(temp.size(), 40u) << temp;
    EXPECT_EQ(readFile(path("out.bin")), bigPayload());
    EXPECT_EQ(listDir(), std::vector<std::string>{"out.bin"});
}

TEST_F(AtomicFileTest, LongestFileNamesWork) {
    // 254 and 255 bytes (NAME_MAX): the old "<name>.tmp.<pid>.<n>" temporary made both fail.
    for (bool tmpFile : {true, false}) {
        AtomicWriteOptions options;
        options.allowTmpFile = tmpFile;
        for (size_t length : {254u, 255u}) {
            const std::string name(length, tmpFile ? 'a' : 'b');
            writeFileAtomic(path(name), "long " + std::to_string(length), options);
            writeFileAtomic(path(name), "again " + std::to_string(length), options);
            EXPECT_EQ(readFile(path(name)), "again " + std::to_string(length));
        }
    }
    EXPECT_EQ(listDir().size(), 4u);
    // Past NAME_MAX is the file system's refusal, one line naming the path.
    const std::string tooLong = path(std::string(256, 'c'));
    std::string msg = expectInputError(tooLong, [&] { writeFileAtomic(tooLong, "x"); });
    EXPECT_NE(msg.find("File name too long"), std::string::npos) << msg;
}

TEST_F(AtomicFileTest, FifoIsRefusedWithoutBlocking) {
    ASSERT_EQ(::mkfifo(path("pipe").c_str(), 0644), 0);
    // Opening a FIFO for writing blocks until a reader comes; refusing must not open it.
    std::string msg = expectInputError(path("pipe"), [&] { writeFileAtomic(path("pipe"), "data"); });
    EXPECT_NE(msg.find("refusing to replace a FIFO"), std::string::npos) << msg;
    EXPECT_TRUE(fs::is_fifo(path("pipe")));
    expectInputError(path("pipe"), [&] { checkWritableTarget(path("pipe")); });
    EXPECT_EQ(listDir(), std::vector<std::string>{"pipe"});
}

TEST_F(AtomicFileTest, CharacterDeviceIsRefusedAlsoThroughSymlinks) {
    // A private copy of /dev/null (major 1, minor 3): as root a broken writer would replace it, not the real one.
    if (::mknod(path("null").c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
        GTEST_SKIP() << "mknod: " << std::strerror(errno) << " (making a device node needs root)";
    std::string msg = expectInputError(path("null"), [&] { writeFileAtomic(path("null"), "data"); });
    EXPECT_NE(msg.find("refusing to replace a character device; only regular files are written"), std::string::npos)
        << msg;
    fs::create_symlink("null", dir_ / "link.png");
    msg = expectInputError(path("link.png"), [&] { writeFileAtomic(path("link.png"), "data"); });
    EXPECT_NE(msg.find("a character device (through a symlink)"), std::string::npos) << msg;
    EXPECT_TRUE(fs::is_character_file(path("null")));
    EXPECT_TRUE(fs::is_symlink(path("link.png")));
    EXPECT_EQ(listDir(), (std::vector<std::string>{"link.png", "null"}));
}

TEST_F(AtomicFileTest, SymlinkToFifoIsRefusedAndKept) {
    // The -o /dev/stdout-into-a-pipe case, staged with a private FIFO. Never a link to the real /dev/null:
    // as root, a writer that follows links and renames (this one with its type check removed) replaces it.
    ASSERT_EQ(::mkfifo(path("pipe").c_str(), 0644), 0);
    fs::create_symlink("pipe", dir_ / "out.png");
    std::string msg = expectInputError(path("out.png"), [&] { writeFileAtomic(path("out.png"), "data"); });
    EXPECT_NE(msg.find("refusing to replace a FIFO (through a symlink)"), std::string::npos) << msg;
    EXPECT_TRUE(fs::is_symlink(path("out.png")));
    EXPECT_TRUE(fs::is_fifo(path("pipe")));
    EXPECT_EQ(listDir(), (std::vector<std::string>{"out.png", "pipe"}));
}

TEST_F(AtomicFileTest, SocketIsRefused) {
    int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
    ASSERT_GE(s, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    const std::string where = path("sock");
    if (where.size() >= sizeof addr.sun_path) {
        ::close(s);
        GTEST_SKIP() << "test folder path too long for a unix socket";
    }
    std::memcpy(addr.sun_path, where.c_str(), where.size() + 1);
    ASSERT_EQ(::bind(s, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0) << std::strerror(errno);
    std::string msg = expectInputError(where, [&] { writeFileAtomic(where, "data"); });
    ::close(s);
    EXPECT_NE(msg.find("refusing to replace a socket"), std::string::npos) << msg;
    EXPECT_TRUE(fs::is_socket(where));
}

TEST_F(AtomicFileTest, SymlinkToRegularFileIsWrittenThrough) {
    // The documented choice: the link stays and the file it names gets the new content.
    fs::create_directory(dir_ / "real");
    writeFileAtomic(path("real/target.png"), "old");
    fs::create_symlink("real/target.png", dir_ / "link.png");
    writeFileAtomic(path("link.png"), "new");
    EXPECT_TRUE(fs::is_symlink(path("link.png")));
    EXPECT_EQ(fs::read_symlink(path("link.png")), "real/target.png");
    EXPECT_EQ(readFile(path("real/target.png")), "new");
    EXPECT_EQ(listDir(), (std::vector<std::string>{"link.png", "real"}));
    std::vector<std::string> inReal;
    for (const auto& e : fs::directory_iterator(dir_ / "real")) inReal.push_back(e.path().filename().string());
    EXPECT_EQ(inReal, std::vector<std::string>{"target.png"}) << "the temporary lives beside the target";
}

TEST_F(AtomicFileTest, DanglingSymlinkIsRefused) {
    fs::create_symlink("missing.png", dir_ / "link.png");
    std::string msg = expectInputError(path("link.png"), [&] { writeFileAtomic(path("link.png"), "data"); });
    EXPECT_NE(msg.find("a symlink to a missing file"), std::string::npos) << msg;
    EXPECT_EQ(listDir(), std::vector<std::string>{"link.png"});
}

TEST_F(AtomicFileTest, CheckWritableTargetNamesTheProblemUpFront) {
    checkWritableTarget(path("new.png"));  // a new file in an existing folder: fine
    EXPECT_TRUE(listDir().empty()) << "checking creates nothing";
    std::string msg = expectInputError(path("no/out.png"), [&] { checkWritableTarget(path("no/out.png")); });
    EXPECT_NE(msg.find("No such file or directory"), std::string::npos) << msg;
    fs::create_directory(dir_ / "sub");
    msg = expectInputError(path("sub"), [&] { checkWritableTarget(path("sub")); });
    EXPECT_NE(msg.find("is a directory"), std::string::npos) << msg;
}

// Signals during the write. A child process writes 3 MiB and, after the first chunk, reports what the
// folder holds and raises `sig` at itself, as a Ctrl-C or kill would arrive mid-write.
namespace {

struct SignalRun {
    bool killedBySignal = false;
    int signal = 0;
    int exitCode = -1;
    int namesDuring = -1;  // entries in the folder when the signal was raised
};

SignalRun writeAndSignal(const std::string& dir, const std::string& target, bool tmpFile, int sig,
                         void (*disposition)(int) = SIG_DFL) {
    int fds[2];
    SignalRun run;
    if (::pipe(fds) != 0) return run;
    pid_t pid = ::fork();
    if (pid == 0) {
        ::close(fds[0]);
        // Whatever the test runner left (a background job ignores SIGINT), start from the case under test.
        std::signal(sig, disposition);
        AtomicWriteOptions options;
        options.allowTmpFile = tmpFile;
        options.afterChunk = [&](size_t done) {
            if (done != (1u << 20)) return;
            int n = 0;
            for (auto it = fs::directory_iterator(dir); it != fs::directory_iterator(); ++it) ++n;
            if (::write(fds[1], &n, sizeof n) != sizeof n) ::_exit(4);
            ::raise(sig);
        };
        try {
            writeFileAtomic(target, bigPayload(), options);
        } catch (...) {
            ::_exit(3);
        }
        ::_exit(0);
    }
    ::close(fds[1]);
    if (::read(fds[0], &run.namesDuring, sizeof run.namesDuring) != sizeof run.namesDuring) run.namesDuring = -1;
    ::close(fds[0]);
    int status = 0;
    ::waitpid(pid, &status, 0);
    run.killedBySignal = WIFSIGNALED(status);
    run.signal = run.killedBySignal ? WTERMSIG(status) : 0;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

}  // namespace

TEST_F(AtomicFileTest, SignalDuringWriteLeavesNoTemporary) {
    const bool tmpFileHere = supportsTmpFile(dir_);
    for (bool tmpFile : {false, true}) {
        if (tmpFile && !tmpFileHere) continue;
        for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
            SCOPED_TRACE(std::string(tmpFile ? "O_TMPFILE" : "named temporary") + ", " + strsignal(sig));
            writeFileAtomic(path("out.bin"), "original");
            SignalRun run = writeAndSignal(dir_.string(), path("out.bin"), tmpFile, sig);
            // The process ends by the signal itself, so its parent sees the usual status (130, 143, 129).
            EXPECT_TRUE(run.killedBySignal) << "exit code " << run.exitCode;
            EXPECT_EQ(run.signal, sig);
            EXPECT_EQ(run.namesDuring, tmpFile ? 1 : 2)
                << "the named temporary is visible mid-write, an O_TMPFILE is not";
            EXPECT_EQ(readFile(path("out.bin")), "original");
            EXPECT_EQ(listDir(), std::vector<std::string>{"out.bin"});
        }
    }
}

TEST_F(AtomicFileTest, SigkillLeavesTheNamedTemporaryButNoTmpFile) {
    // Negative control: SIGKILL cannot be caught, so the fallback's temporary stays; that is what the test
    // above would see without the handlers. An O_TMPFILE leaves nothing even then.
    writeFileAtomic(path("out.bin"), "original");
    SignalRun named = writeAndSignal(dir_.string(), path("out.bin"), false, SIGKILL);
    EXPECT_EQ(named.signal, SIGKILL);
    EXPECT_EQ(listDir().size(), 2u);
    for (const std::string& name : listDir())
        if (name != "out.bin") fs::remove(dir_ / name);
    if (!supportsTmpFile(dir_)) GTEST_SKIP() << dir_ << ": file system without O_TMPFILE";
    SignalRun anonymous = writeAndSignal(dir_.string(), path("out.bin"), true, SIGKILL);
    EXPECT_EQ(anonymous.signal, SIGKILL);
    EXPECT_EQ(readFile(path("out.bin")), "original");
    EXPECT_EQ(listDir(), std::vector<std::string>{"out.bin"});
}

TEST_F(AtomicFileTest, IgnoredSignalStaysIgnored) {
    // Under nohup SIGHUP is ignored; the write must not turn it back into a fatal signal.
    writeFileAtomic(path("out.bin"), "original");
    SignalRun run = writeAndSignal(dir_.string(), path("out.bin"), false, SIGHUP, SIG_IGN);
    EXPECT_FALSE(run.killedBySignal) << strsignal(run.signal);
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_EQ(readFile(path("out.bin")), bigPayload());
    EXPECT_EQ(listDir(), std::vector<std::string>{"out.bin"});
}

TEST_F(AtomicFileTest, HandlersAreOnlyInstalledDuringTheWrite) {
    struct sigaction during, after;
    std::memset(&during, 0, sizeof during);
    AtomicWriteOptions options;
    options.allowTmpFile = false;
    options.afterChunk = [&](size_t) { ::sigaction(SIGTERM, nullptr, &during); };
    auto old = std::signal(SIGTERM, SIG_DFL);
    writeFileAtomic(path("out.bin"), "x", options);
    ::sigaction(SIGTERM, nullptr, &after);
    std::signal(SIGTERM, old);
    EXPECT_NE(during.sa_handler, SIG_DFL) << "a handler removes the temporary while it exists";
    EXPECT_EQ(after.sa_handler, SIG_DFL) << "and is gone afterwards";
}
