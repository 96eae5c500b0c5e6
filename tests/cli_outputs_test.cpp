// CLI outputs (docs/cli.md, "Outputs"): nothing is lost. A render that cannot be written fails with one line and
// leaves the existing file and no temporary behind; an output is never one of the inputs, never a device,
// FIFO or a link to one; `-o -` is stdout; the file and then its folder are fsynced around the rename; a
// signal during the write leaves no temporary file.
#include "cli_run.h"
#include "image/png.h"
#include "test_output.h"

#include <gtest/gtest.h>

#include <spawn.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace shadelab;
using namespace shadelab::test;
namespace fs = std::filesystem;

// Nothing lost: a render that cannot be written fails with one line, leaves the existing file as
// it was and leaves no temporary file behind.
namespace {

std::vector<std::string> listDir(const std::string& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace

TEST(CliNothingLost, ReadOnlyFolder) {
    std::string dir = test::outputPath("readonly");
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir + "/out.png") << "previous";
    fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read | fs::perms::group_exec |
                             fs::perms::others_read | fs::perms::others_exec);
    // Root ignores folder permissions: run as the unprivileged user `nobody` instead.
    std::string asUser = geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
    if (!asUser.empty() && std::system((asUser + "test -x " + std::string(SHADELAB_BINARY) + " -a -r " +
                                        test::sourcePath("assets/scenes/default.json"))
                                           .c_str()) != 0) {
        fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add);
        GTEST_SKIP() << "user nobody cannot reach the build tree here, so a permission test cannot be staged";
    }
    Result r = run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + dir + "/out.png --size 64x36",
                   asUser);
    fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add);
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("Permission denied"), std::string::npos) << r.out;
    EXPECT_EQ(lineCount(r.out), 1) << r.out;
    EXPECT_EQ(readAll(dir + "/out.png"), "previous");
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"out.png"});
}

TEST(CliNothingLost, FileSizeLimitHitMidWrite) {
    // RLIMIT_FSIZE makes write() fail part-way (EFBIG), as a disk that fills up during the write would.
    std::string dir = test::outputPath("fsize");
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ofstream(dir + "/out.png") << "previous";
    Result r =
        run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + dir + "/out.png --size 320x180",
            "trap '' XFSZ; ulimit -f 8; ");
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("File too large"), std::string::npos) << r.out;
    EXPECT_EQ(readAll(dir + "/out.png"), "previous");
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"out.png"});
}

TEST(CliNothingLost, FullDisk) {
    std::string dir = test::outputPath("fulldisk");
    fs::create_directories(dir);
    if (std::system(
            ("mountpoint -q " + dir + " || mount -t tmpfs -o size=64k tmpfs " + dir + " 2>/dev/null").c_str()) != 0)
        GTEST_SKIP() << "cannot mount a small tmpfs here (needs root); FileSizeLimitHitMidWrite covers the write path";
    for (const std::string& f : listDir(dir)) fs::remove(dir + "/" + f);
    std::ofstream(dir + "/out.png") << "previous";
    Result r =
        run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + dir + "/out.png --size 640x360");
    std::vector<std::string> left = listDir(dir);
    std::string kept = readAll(dir + "/out.png");
    (void)std::system(("umount " + dir).c_str());
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("No space left on device"), std::string::npos) << r.out;
    EXPECT_EQ(kept, "previous");
    EXPECT_EQ(left, std::vector<std::string>{"out.png"});
}

// Outputs that never destroy: an output is never one of the inputs, never a device, FIFO or a
// link to one; `-o -` is stdout; the file and then its folder are fsynced around the rename; a signal
// during the write leaves no temporary file.
namespace {

std::string freshDir(const std::string& name) {
    const std::string dir = test::outputPath(name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return fs::canonical(dir).string();
}

struct SplitResult {
    int code = -1;
    std::string out;  // stdout alone, possibly binary
    std::string err;
};

// Runs shadelab with stdout and stderr captured apart.
// The capture files are named after the running test: ctest runs tests in parallel processes.
SplitResult runSplit(const std::string& args) {
    const std::string stem = std::string("split_") + ::testing::UnitTest::GetInstance()->current_test_info()->name();
    const std::string out = test::outputPath(stem + "_stdout.bin"), err = test::outputPath(stem + "_stderr.txt");
    const int status = std::system((std::string(SHADELAB_BINARY) + " " + args + " > " + out + " 2> " + err).c_str());
    SplitResult r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = readAll(out);
    r.err = readAll(err);
    return r;
}

// The environment that loads write_probe (tests/write_probe.cpp) into shadelab.
std::vector<std::string> probeEnvironment(const std::string& log, int fsyncDelayMs) {
    return {"LD_PRELOAD=" + std::string(SHADELAB_WRITE_PROBE), "SHADELAB_PROBE_LOG=" + log,
            "SHADELAB_PROBE_FSYNC_DELAY_MS=" + std::to_string(fsyncDelayMs),
            // A sanitizer build accepts the preload; Mesa's allocations are not ours to leak-check (test.sh).
            "ASAN_OPTIONS=verify_asan_link_order=0:detect_leaks=0"};
}

std::vector<std::string> linesWith(const std::string& text, const std::string& needle) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        if (line.find(needle) != std::string::npos) lines.push_back(line);
        start = end + 1;
    }
    return lines;
}

}  // namespace

TEST(CliOutputs, RenderOntoItsSceneIsRefused) {
    const std::string dir = freshDir("out_is_scene");
    const std::string scene = dir + "/scene.json";
    fs::copy_file(test::sourcePath("assets/scenes/default.json"), scene);
    const std::string before = readAll(scene);
    for (const std::string& output : {scene, dir + "/./scene.json"}) {
        Result r = run("render " + scene + " -o " + output + " --size 32x18");
        EXPECT_EQ(r.code, 1) << r.out;
        EXPECT_NE(r.out.find("shadelab: error: " + output + ": refusing to overwrite an input with the output (-o)"),
                  std::string::npos)
            << r.out;
        EXPECT_EQ(lineCount(r.out), 1) << r.out;
        EXPECT_EQ(readAll(scene), before);
    }
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"scene.json"});
    // Negative control: another name in the same folder is written.
    EXPECT_EQ(run("render " + scene + " -o " + dir + "/other.png --size 32x18").code, 0);
}

// The README's first render, `-o out/phong.png` in a fresh clone, creates the folder; a folder under a file
// is refused in one line, nothing written (the negative control).
TEST(CliOutputs, RenderCreatesAMissingOutputFolder) {
    const std::string dir = freshDir("missing_folder");
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    Result r = run("render " + scene + " -o " + dir + "/out/sub/phong.png --size 32x18");
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(fs::is_regular_file(dir + "/out/sub/phong.png"));
    std::ofstream(dir + "/file") << "keep";
    r = run("render " + scene + " -o " + dir + "/file/phong.png --size 32x18");
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_EQ(lineCount(r.out), 1) << r.out;
    EXPECT_NE(r.out.find(dir + "/file/phong.png"), std::string::npos) << r.out;
    EXPECT_EQ(readAll(dir + "/file"), "keep");
}

TEST(CliOutputs, RenderOntoItsModelIsRefused) {
    const std::string dir = freshDir("out_is_model");
    fs::create_directories(dir + "/models");
    fs::create_directories(dir + "/scenes");
    const std::string gltf = dir + "/models/torus.gltf", scene = dir + "/scenes/torus.json";
    fs::copy_file(test::sourcePath("assets/models/torus.gltf"), gltf);
    fs::copy_file(test::sourcePath("assets/scenes/torus.json"), scene);  // names ../models/torus.gltf
    const std::string before = readAll(gltf);

    Result direct = run("render " + gltf + " -o " + gltf + " --size 32x18");
    EXPECT_EQ(direct.code, 1) << direct.out;
    EXPECT_NE(direct.out.find(gltf + ": refusing to overwrite an input with the output (-o)"), std::string::npos)
        << direct.out;
    EXPECT_EQ(lineCount(direct.out), 1) << direct.out;
    // The model a scene loads is an input too; it is known once the scene is read, before the render.
    Result viaScene = run("render " + scene + " -o " + gltf + " --size 32x18");
    EXPECT_EQ(viaScene.code, 1) << viaScene.out;
    EXPECT_NE(viaScene.out.find(gltf + ": refusing to overwrite an input with the output (-o): it is " + dir +
                                "/scenes/../models/torus.gltf"),
              std::string::npos)
        << viaScene.out;
    EXPECT_EQ(lineCount(viaScene.out), 1) << viaScene.out;
    EXPECT_EQ(readAll(gltf), before);
    EXPECT_EQ(run("render " + scene + " -o " + dir + "/torus.png --size 32x18").code, 0) << "control";

    const std::string glb = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    if (!fs::exists(glb)) GTEST_SKIP() << "assimp-testmodels not installed: " << glb;
    fs::copy_file(glb, dir + "/box.glb");
    const std::string glbBefore = readAll(dir + "/box.glb");
    Result binary = run("render " + dir + "/box.glb -o " + dir + "/box.glb --size 32x18");
    EXPECT_EQ(binary.code, 1) << binary.out;
    EXPECT_NE(binary.out.find("refusing to overwrite an input"), std::string::npos) << binary.out;
    EXPECT_EQ(readAll(dir + "/box.glb"), glbBefore);
}

TEST(CliOutputs, CompareOutputsOntoInputsAreRefused) {
    const std::string dir = freshDir("compare_out_is_input");
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    const std::string a = dir + "/a.png", b = dir + "/b.png";
    ASSERT_EQ(run("render " + scene + " -o " + a + " --size 48x27").code, 0);
    ASSERT_EQ(run("render " + scene + " -o " + b + " --size 48x27 --model blinn-phong").code, 0);
    const std::string aBefore = readAll(a), bBefore = readAll(b);
    // compare's own convention: 2 for any error (1 means "outside the gates").
    for (const std::string& flags : {"--diff " + a, "--json " + b, "--diff " + dir + "/c.png --json " + a}) {
        Result r = run("compare " + a + " " + b + " " + flags);
        EXPECT_EQ(r.code, 2) << flags << "\n" << r.out;
        EXPECT_NE(r.out.find("refusing to overwrite an input with the output (--"), std::string::npos) << r.out;
        EXPECT_EQ(lineCount(r.out), 1) << r.out;
        EXPECT_EQ(readAll(a), aBefore);
        EXPECT_EQ(readAll(b), bBefore);
    }
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"a.png", "b.png"})) << "refused before anything is written";
}

TEST(CliOutputs, FifoIsRefusedWithoutBlocking) {
    const std::string dir = freshDir("out_fifo");
    const std::string fifo = dir + "/out.png";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0);
    // `timeout` turns a writer that opens the FIFO (and waits for a reader forever) into exit 124.
    Result r = run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + fifo + " --size 32x18",
                   "timeout 10 ");
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find(fifo + ": refusing to replace a FIFO; only regular files are written"), std::string::npos)
        << r.out;
    EXPECT_EQ(lineCount(r.out), 1) << r.out;
    EXPECT_TRUE(fs::is_fifo(fifo));
    const std::string png = test::outputPath("cmp_fifo_input.png");
    ASSERT_EQ(run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + png + " --size 16x9").code, 0);
    Result cmp = run("compare " + png + " " + png + " --diff " + fifo, "timeout 10 ");
    EXPECT_EQ(cmp.code, 2) << cmp.out;
    EXPECT_NE(cmp.out.find("refusing to replace a FIFO"), std::string::npos) << cmp.out;
    EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST(CliOutputs, DevicesAndLinksToThemAreRefused) {
    // -o /dev/null, /dev/full or a /dev/stdout that is a pipe, staged with private nodes and links to them.
    // Never the real ones: as root, a writer that follows links and renames replaces the system's device
    // (it happened once, checking that this test fails without the type check).
    const std::string dir = freshDir("out_device");
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    auto expectRefused = [&](const std::string& name, const std::string& what) {
        Result r = run("render " + scene + " -o " + dir + "/" + name + " --size 32x18", "timeout 10 ");
        EXPECT_EQ(r.code, 1) << name << ": " << r.out;
        EXPECT_NE(r.out.find(dir + "/" + name + ": refusing to replace " + what), std::string::npos) << r.out;
        EXPECT_EQ(lineCount(r.out), 1) << r.out;
    };
    ASSERT_EQ(::mkfifo((dir + "/pipe").c_str(), 0644), 0);
    fs::create_symlink("pipe", dir + "/to-pipe.png");
    expectRefused("to-pipe.png", "a FIFO (through a symlink)");
    EXPECT_TRUE(fs::is_symlink(dir + "/to-pipe.png"));
    EXPECT_TRUE(fs::is_fifo(dir + "/pipe"));

    // A character device made here (a copy of /dev/null: major 1, minor 3). mknod needs root.
    const std::string node = dir + "/null";
    if (::mknod(node.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
        GTEST_SKIP() << "mknod " << node << ": " << std::strerror(errno) << " (making a device node needs root)";
    expectRefused("null", "a character device; only regular files are written");
    fs::create_symlink("null", dir + "/to-null.png");
    expectRefused("to-null.png", "a character device (through a symlink)");
    EXPECT_TRUE(fs::is_character_file(node));
    EXPECT_TRUE(fs::is_symlink(dir + "/to-null.png"));
    EXPECT_EQ(listDir(dir), (std::vector<std::string>{"null", "pipe", "to-null.png", "to-pipe.png"}));
}

TEST(CliOutputs, DashWritesThePngToStdout) {
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    const std::string file = test::outputPath("stdout_reference.png");
    ASSERT_EQ(run("render " + scene + " -o " + file + " --size 160x90").code, 0);
    // --verbose and --timings talk on stderr, so stdout carries the PNG alone.
    SplitResult r = runSplit("render " + scene + " -o - --size 160x90 --verbose --timings");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, readAll(file)) << "stdout holds exactly the bytes -o FILE writes";
    EXPECT_NE(r.err.find("wrote stdout"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists("-")) << "no file named '-' in the working folder";
    // -o /dev/stdout means the same (isStdout, output_file_test); not run here, since a regression would
    // replace the system's /dev/stdout link when the tests run as root.
}

TEST(CliOutputs, CompareWritesJsonOrHeatmapToStdout) {
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    const std::string a = test::outputPath("stdout_cmp_a.png"), b = test::outputPath("stdout_cmp_b.png");
    ASSERT_EQ(run("render " + scene + " -o " + a + " --size 48x27").code, 0);
    ASSERT_EQ(run("render " + scene + " -o " + b + " --size 48x27 --model blinn-phong").code, 0);
    SplitResult json = runSplit("compare " + a + " " + b + " --json -");
    EXPECT_EQ(json.code, 1) << json.err;  // Phong against Blinn-Phong fails the gates
    EXPECT_EQ(json.out.rfind("{", 0), 0u) << json.out;
    EXPECT_NE(json.out.find("\"pass\": false"), std::string::npos) << json.out;
    EXPECT_EQ(json.out.find("FAIL"), std::string::npos) << "the summary goes to stderr";
    EXPECT_NE(json.err.find("FAIL"), std::string::npos) << json.err;

    const std::string heat = test::outputPath("stdout_cmp_heat.png");
    ASSERT_EQ(run("compare " + a + " " + b + " --diff " + heat).code, 1);
    SplitResult diff = runSplit("compare " + a + " " + b + " --diff - -q");
    EXPECT_EQ(diff.code, 1) << diff.err;
    EXPECT_EQ(diff.out, readAll(heat));
    EXPECT_EQ(diff.err, "FAIL\n");
    EXPECT_EQ(runSplit("compare " + a + " " + b + " --diff - --json -").code, 2) << "one stdout, one output";
}

TEST(CliOutputs, LongestOutputNamesWork) {
    // 254 bytes: the old "<name>.tmp.<pid>.<n>" temporary pushed it past NAME_MAX (255).
    const std::string dir = freshDir("long_name");
    const std::string name = std::string(250, 'x') + ".png";
    Result r =
        run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + dir + "/" + name + " --size 32x18");
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(readPng(dir + "/" + name).width, 32);
    EXPECT_EQ(listDir(dir), std::vector<std::string>{name});
}

TEST(CliOutputs, FileThenFolderAreSyncedAroundTheRename) {
    const std::string dir = freshDir("sync_order");
    const std::string log = test::outputPath("sync_order_probe.log");
    fs::remove(log);
    std::string env;
    for (const std::string& v : probeEnvironment(log, 0)) env += v + " ";
    Result r =
        run("render " + test::sourcePath("assets/scenes/default.json") + " -o " + dir + "/out.png --size 32x18", env);
    ASSERT_EQ(r.code, 0) << r.out;
    const std::vector<std::string> calls = linesWith(readAll(log), dir);
    ASSERT_GE(calls.size(), 3u) << readAll(log);
    // The data is durable before it gets the name, and the name is durable before shadelab says done.
    EXPECT_EQ(calls.front().rfind("fsync file " + dir + "/", 0), 0u) << calls.front();
    EXPECT_EQ(calls[calls.size() - 2].rfind("rename " + dir + "/.shadelab.", 0), 0u) << calls[calls.size() - 2];
    EXPECT_NE(calls[calls.size() - 2].find(" " + dir + "/out.png"), std::string::npos) << calls[calls.size() - 2];
    EXPECT_EQ(calls.back(), "fsync dir " + dir);
    EXPECT_EQ(listDir(dir), std::vector<std::string>{"out.png"});
}

TEST(CliOutputs, SignalDuringTheWriteLeavesNothing) {
    // The probe holds the fsync of the new file for 5 s: the data is written and nothing is renamed yet.
    // The signal arrives then, as a Ctrl-C, kill or closed terminal would during a slow write.
    const std::string scene = test::sourcePath("assets/scenes/default.json");
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
        SCOPED_TRACE(strsignal(sig));
        const std::string dir = freshDir("signal_" + std::to_string(sig));
        std::ofstream(dir + "/out.png") << "previous";
        const std::string log = test::outputPath("signal_probe_" + std::to_string(sig) + ".log");
        fs::remove(log);

        std::vector<std::string> args = {SHADELAB_BINARY, "render", scene, "-o", dir + "/out.png", "--size", "64x36"};
        std::vector<std::string> env = probeEnvironment(log, 5000);
        for (char** e = environ; *e; ++e) env.push_back(*e);
        std::vector<char*> argv, envp;
        for (std::string& a : args) argv.push_back(a.data());
        for (std::string& e : env) envp.push_back(e.data());
        argv.push_back(nullptr);
        envp.push_back(nullptr);
        // Default dispositions: a test runner started in the background ignores SIGINT, and its children too.
        posix_spawnattr_t attr;
        posix_spawnattr_init(&attr);
        sigset_t defaults, none;
        sigemptyset(&defaults);
        sigemptyset(&none);
        for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&defaults, s);
        posix_spawnattr_setsigdefault(&attr, &defaults);
        posix_spawnattr_setsigmask(&attr, &none);
        posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
        pid_t pid = -1;
        ASSERT_EQ(posix_spawn(&pid, SHADELAB_BINARY, nullptr, &attr, argv.data(), envp.data()), 0);
        posix_spawnattr_destroy(&attr);

        bool midWrite = false, exited = false;
        int status = 0;
        for (int waited = 0; waited < 20000 && !midWrite && !exited; waited += 5) {
            midWrite = !linesWith(readAll(log), "fsync file " + dir + "/").empty();
            exited = !midWrite && ::waitpid(pid, &status, WNOHANG) == pid;
            if (!midWrite && !exited) ::usleep(5000);
        }
        if (!exited) {
            ::kill(pid, midWrite ? sig : SIGKILL);
            ::waitpid(pid, &status, 0);
        }
        ASSERT_TRUE(midWrite) << "the render never reached the write; probe log:\n" << readAll(log);
        EXPECT_TRUE(WIFSIGNALED(status)) << "exit code " << (WIFEXITED(status) ? WEXITSTATUS(status) : -1);
        EXPECT_EQ(WIFSIGNALED(status) ? WTERMSIG(status) : 0, sig) << "ended by the signal itself";
        EXPECT_TRUE(linesWith(readAll(log), "rename").empty()) << readAll(log);
        EXPECT_EQ(readAll(dir + "/out.png"), "previous");
        EXPECT_EQ(listDir(dir), std::vector<std::string>{"out.png"});
    }
}
