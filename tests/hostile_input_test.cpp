// Hostile inputs: every file shadelab reads goes through util/read_file.h, so a FIFO, a device
// behind a symlink, a 10 GB side file or a NUL in a path ends in one line naming the file, exit 1, within a
// second and a small memory bound. Each case runs the real binary under `timeout`, so a hang fails it.
#include "image/png.h"
#include "test_output.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Result {
    int code = -1;
    std::string out;  // stdout and stderr together
    double seconds = 0;
    double peakMiB = 0;  // the process's peak resident set
};

// Runs shadelab with `args` (no shell), killing it after `seconds` (code 124): a refusal must come at once, so
// 10 s is plenty; a negative control that really renders may take longer under a sanitizer. Captures stdout
// and stderr and the process's own peak resident memory (wait4).
Result run(const std::vector<std::string>& args, int seconds = 10) {
    Result r;
    int fds[2];
    if (pipe(fds) != 0) return r;
    const auto t0 = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid == 0) {
        dup2(fds[1], 1);
        dup2(fds[1], 2);
        close(fds[0]);
        close(fds[1]);
        std::vector<char*> argv{const_cast<char*>(SHADELAB_BINARY)};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        execv(SHADELAB_BINARY, argv.data());
        _exit(127);
    }
    close(fds[1]);
    fcntl(fds[0], F_SETFL, O_NONBLOCK);
    int status = 0;
    rusage usage{};
    bool killed = false;
    auto drain = [&] {
        char buf[4096];
        ssize_t n;
        while ((n = read(fds[0], buf, sizeof buf)) > 0) r.out.append(buf, size_t(n));
    };
    for (;;) {
        drain();
        if (wait4(pid, &status, WNOHANG, &usage) == pid) break;
        if (!killed && std::chrono::steady_clock::now() - t0 > std::chrono::seconds(seconds)) {
            kill(pid, SIGKILL);
            killed = true;
        }
        usleep(2000);
    }
    drain();
    close(fds[0]);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.peakMiB = double(usage.ru_maxrss) / 1024.0;  // Linux: KiB
    r.code = killed ? 124 : WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return r;
}

Result render(const std::string& input, const std::string& dir) {
    return run({"render", input, "-o", dir + "/out.png"});
}

// A private folder per test, emptied first.
std::string folder(const std::string& name) {
    const fs::path dir = fs::path(shadelab::test::outputPath("hostile")) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir.string();
}

void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// The bounds each case must meet: under 1 s and 100 MiB. A sanitizer build (scripts/test.sh's first pass) runs the
// same binary several times slower and larger, so it gets room without losing the point (no hang, no
// gigabytes).
#if defined(__SANITIZE_ADDRESS__)
constexpr double kMaxSeconds = 5.0, kMaxPeakMiB = 600.0;
#else
constexpr double kMaxSeconds = 1.0, kMaxPeakMiB = 100.0;
#endif

// One line on stderr, the exit code for bad input (1; compare's is 2, docs/cli.md), naming `file` and
// containing `reason`, within kMaxSeconds and kMaxPeakMiB.
void expectRefused(const Result& r, const std::string& file, const std::string& reason, int code = 1) {
    EXPECT_EQ(r.code, code) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    EXPECT_NE(r.out.find(file), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(reason), std::string::npos) << r.out;
    EXPECT_LT(r.seconds, kMaxSeconds) << r.out;
    EXPECT_LT(r.peakMiB, kMaxPeakMiB) << r.out;
}

std::string gltfWithBuffer(const std::string& uri, int byteLength) {
    return R"({"asset":{"version":"2.0"},"buffers":[{"uri":")" + uri + R"(","byteLength":)" +
           std::to_string(byteLength) + R"(}],"scenes":[{"nodes":[]}],"scene":0})";
}

// A 47-triangle mesh (zero bytes: the count matters, not the shape) under a node DAG `levels` deep, where
// each level's node lists the level below twice: 2^levels instances in a file of about 3 KB.
std::string dagGltf(int levels) {
    const int bytes = 47 * 3 * 12;
    std::string nodes = R"({"mesh":0})";
    for (int l = 1; l <= levels; ++l)
        nodes += R"(,{"children":[)" + std::to_string(l - 1) + "," + std::to_string(l - 1) + "]}";
    return R"({"asset":{"version":"2.0"},"buffers":[{"uri":"data:application/octet-stream;base64,)" +
           std::string(size_t(bytes) / 3 * 4, 'A') + R"(","byteLength":)" + std::to_string(bytes) +
           R"(}],"bufferViews":[{"buffer":0,"byteLength":)" + std::to_string(bytes) +
           R"(}],"accessors":[{"bufferView":0,"componentType":5126,"count":141,"type":"VEC3","min":[0,0,0],"max":[0,0,0]}],)"
           R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[)" +
           nodes + R"(],"scenes":[{"nodes":[)" + std::to_string(levels) + R"(]}],"scene":0})";
}

// A real 16x16 PNG whose IHDR then claims `w` x `h` (the CRC is left stale: nothing may decode it).
std::string pngClaiming(const std::string& path, uint32_t w, uint32_t h) {
    shadelab::Image8 img;
    img.width = img.height = 16;
    img.channels = 3;
    img.data.assign(16 * 16 * 3, 128);
    std::vector<uint8_t> bytes = shadelab::encodePng(img);
    for (int k = 0; k < 4; ++k) {
        bytes[size_t(16 + k)] = uint8_t(w >> (24 - 8 * k));
        bytes[size_t(20 + k)] = uint8_t(h >> (24 - 8 * k));
    }
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return path;
}

// A GLB whose only buffer declares byteLength 0 while a mesh reads from it, with a 4-byte BIN chunk.
void writeEmptyBufferGlb(const std::string& path) {
    std::string json = R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":0}],)"
                       R"("bufferViews":[{"buffer":0,"byteLength":12}],)"
                       R"("accessors":[{"bufferView":0,"componentType":5126,"count":1,"type":"VEC3"}],)"
                       R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],)"
                       R"("scenes":[{"nodes":[0]}],"scene":0})";
    json.append((4 - json.size() % 4) % 4, ' ');
    auto u32 = [](std::string& out, uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    std::string chunks;
    u32(chunks, uint32_t(json.size()));
    u32(chunks, 0x4E4F534Au);  // JSON
    chunks += json;
    u32(chunks, 4);
    u32(chunks, 0x004E4942u);  // BIN
    chunks.append(4, '\0');
    std::string glb;
    u32(glb, 0x46546C67u);  // glTF
    u32(glb, 2);
    u32(glb, uint32_t(12 + chunks.size()));
    std::ofstream(path, std::ios::binary) << glb << chunks;
}

}  // namespace

TEST(HostileInput, LibraryExceptionsBecomeAReason) {
    // tinygltf throws std::out_of_range on this file; the message once read "vector::_M_range_check: __n ...".
    const std::string dir = folder("library");
    writeEmptyBufferGlb(dir + "/empty.glb");
    const Result r = render(dir + "/empty.glb", dir);
    expectRefused(r, "empty.glb", "malformed glTF");
    EXPECT_EQ(r.out.find("_M_range_check"), std::string::npos) << r.out;
}

TEST(HostileInput, FifoAsViewerScriptNeverBlocks) {
    // The script is read before the window opens, so this needs no display.
    const std::string dir = folder("script");
    ASSERT_EQ(mkfifo((dir + "/actions.json").c_str(), 0600), 0);
    const Result r =
        run({"view", shadelab::test::sourcePath("assets/scenes/default.json"), "--script", dir + "/actions.json"});
    if (r.out.find("no viewer") != std::string::npos) GTEST_SKIP() << "this build has no viewer";
    expectRefused(r, "actions.json", "is a FIFO, not a regular file");
}

TEST(HostileInput, PngHeadersAreCheckedBeforeDecoding) {
    const std::string dir = folder("png");
    const std::string bomb = pngClaiming(dir + "/bomb.png", 65536, 65536);
    const std::string big = pngClaiming(dir + "/big.png", 16384, 16384);
    const std::string small = pngClaiming(dir + "/small.png", 16, 16);
    // A decompression bomb is refused from its header; compare exits 2 on any error (docs/cli.md).
    expectRefused(run({"compare", bomb, small}), "bomb.png", "65536x65536 pixels exceeds the limit", 2);
    // A size mismatch is found from the two headers, before the 16384² image would be decoded (1 GiB).
    expectRefused(run({"compare", small, big}), "big.png", "image sizes differ: 16x16", 2);
    // Negative control: the honest 16x16 pair compares.
    const Result ok = run({"compare", small, pngClaiming(dir + "/same.png", 16, 16)});
    EXPECT_EQ(ok.code, 0) << ok.out;
}

TEST(HostileInput, RenderOverTheMemoryBudgetIsOneLine) {
    // 16384² through both renderers: about 15 GB of images whatever the scene. A limit of 2G is refused as it
    // is read (a usage error, exit 2), before the scene is loaded or a GL context made.
    const std::string dir = folder("memory");
    const std::string scene = shadelab::test::sourcePath("assets/scenes/default.json");
    const Result r = run(
        {"render", scene, "-o", dir + "/out.png", "--size", "16384x16384", "--renderer", "both", "--max-memory", "2G"});
    expectRefused(r, "--max-memory: must be at least ",
                  " MiB for a 16384x16384 both render, whatever the scene; got 2048 MiB", 2);
    // `--max-memory 1` (MiB) was accepted for a 64x48 raster render that peaks at about 108 MB.
    expectRefused(run({"render", scene, "-o", dir + "/out.png", "--size", "64x48", "--max-memory", "1"}),
                  "--max-memory: must be at least ", " MiB for a 64x48 raster render, whatever the scene; got 1 MiB",
                  2);
    const Result bad = run({"render", scene, "-o", dir + "/out.png", "--max-memory", "lots"});
    EXPECT_EQ(bad.code, 2) << bad.out;
    EXPECT_NE(bad.out.find("--max-memory: expected a size such as 512M or 2G, got 'lots'"), std::string::npos);
    // What this scene adds, two 8192² shadow-map layers (512 MiB), is refused from the loaded scene's estimate
    // (exit 1, naming the scene), within the limit: the GL context it made meanwhile is all it took.
    const Result over = run({"render", scene, "-o", dir + "/out.png", "--size", "64x48", "--shadow-map-size", "8192",
                             "--max-memory", "200M"});
    EXPECT_EQ(over.code, 1) << over.out;
    EXPECT_EQ(std::count(over.out.begin(), over.out.end(), '\n'), 1) << over.out;
    EXPECT_NE(over.out.find("default.json: a 64x48 raster render of this scene needs about "), std::string::npos)
        << over.out;
    EXPECT_NE(over.out.find(" MiB, over the limit of 200 MiB (--max-memory)"), std::string::npos) << over.out;
#if !defined(__SANITIZE_ADDRESS__)
    EXPECT_LT(over.peakMiB, 200.0) << over.out;
#endif
    EXPECT_FALSE(fs::exists(dir + "/out.png"));
    // Negative control: the same scene at 64x48 fits in 2G.
    const Result ok = run({"render", scene, "-o", dir + "/ok.png", "--size", "64x48", "--max-memory", "2G"});
    EXPECT_EQ(ok.code, 0) << ok.out;
}

// The estimate of a render, read from the command line's own refusals: the least any render of the request
// needs ("must be at least N MiB", from --max-memory 1), then, raised to each "needs about N MiB" it is
// refused with (the environment map's load, then the render of this scene), the limit it is accepted under.
double estimatedMiB(const std::vector<std::string>& render) {
    const auto number = [](const std::string& text, const std::string& before) {
        const size_t at = text.find(before);
        return at == std::string::npos ? -1.0 : std::atof(text.c_str() + at + before.size());
    };
    std::vector<std::string> args = render;
    args.insert(args.end(), {"--max-memory", "1"});
    double limit = number(run(args).out, "must be at least ");
    for (int tries = 0; limit > 0 && tries < 4; ++tries) {
        args.back() = std::to_string(int(limit));
        const Result r = run(args);
        if (r.code == 0) return limit;
        const double need = number(r.out, "needs about ");
        limit = need > limit ? need : -1.0;
    }
    return -1.0;
}

TEST(HostileInput, RendersStayWithinTheirMemoryEstimate) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "ASan's shadow memory and quarantine are no part of a render's estimate";
#endif
    const std::string dir = folder("estimate");
    const auto scene = [](const char* name) {
        return shadelab::test::sourcePath(std::string("assets/scenes/") + name);
    };
    const Result probe = run({"render", scene("default.json"), "-o", dir + "/gl.png", "--size", "8x8", "--verbose"});
    // The GL context's share is llvmpipe's, measured; a GPU driver's host memory is its own.
    const bool llvmpipe = probe.out.find("GL_RENDERER llvmpipe") != std::string::npos;
    std::vector<std::vector<std::string>> renders = {
        {"--renderer", "trace", "--size", "1280x720"},
        {"--renderer", "path", "--size", "320x180", "--spp", "1"},
    };
    std::vector<std::vector<std::string>> rasterRenders = {
        {"--size", "64x48"},
        {"--size", "1280x720"},
        {"--size", "64x48", "--shadow-map-size", "4096"},
        {"--renderer", "both", "--size", "320x180"},
    };
    if (llvmpipe) renders.insert(renders.end(), rasterRenders.begin(), rasterRenders.end());
    for (const char* name : {"default.json", "pbr-sky.json", "torus.json"}) {
        for (const std::vector<std::string>& flags : renders) {
            std::vector<std::string> args = {"render", scene(name), "-o", dir + "/out.png"};
            args.insert(args.end(), flags.begin(), flags.end());
            std::string what = name;
            for (const std::string& f : flags) what += " " + f;
            const double estimate = estimatedMiB(args);
            ASSERT_GT(estimate, 0) << what;
            // Accepted under its own estimate, and its peak stays under it.
            args.insert(args.end(), {"--max-memory", std::to_string(int(estimate))});
            const Result r = run(args);
            EXPECT_EQ(r.code, 0) << what << ": " << r.out;
            EXPECT_LE(r.peakMiB, estimate) << what << ": peak " << r.peakMiB << " MiB, estimate " << estimate;
        }
    }
    // The negative control: what the old estimate left out is real. A 64x48 raster render, which it put at
    // 24 KiB (its pixels alone) and so let `--max-memory 1` through, peaks at tens of MiB for the GL context.
    if (llvmpipe) {
        const Result small = run({"render", scene("default.json"), "-o", dir + "/small.png", "--size", "64x48"});
        EXPECT_EQ(small.code, 0) << small.out;
        EXPECT_GT(small.peakMiB, 32.0) << small.out;
    }
}

// A Radiance .hdr of `w` x `h` pixels of one colour, run-length encoded (about 264 bytes a scanline).
std::string writeFlatHdr(const std::string& path, int w, int h) {
    std::string s = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(h) + " +X " + std::to_string(w) + "\n";
    std::string line = {char(2), char(2), char(w >> 8), char(w & 255)};
    for (unsigned char v : {128, 140, 160, 129})
        for (int x = 0; x < w; x += 127) {
            line += char(128 + std::min(127, w - x));
            line += char(v);
        }
    for (int y = 0; y < h; ++y) s += line;
    writeText(path, s);
    return path;
}

TEST(HostileInput, EnvironmentMapOverTheMemoryLimitIsRefusedFromItsHeader) {
    // 16 Mpixels: 192 MiB of floats once decoded, in a file of 1 MiB. Under --max-memory 100M it is refused
    // from its header, within the bounds of every hostile case (one line, under 1 s and 100 MiB).
    const std::string dir = folder("environment");
    writeFlatHdr(dir + "/big.hdr", 4096, 4096);
    writeText(dir + "/big.json",
              R"({"model": "pbr", "environment": {"hdr": "big.hdr"}, "lights": [],
                  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}]})");
    for (const char* engine : {"trace", "path"}) {
        const Result r = run({"render", dir + "/big.json", "-o", dir + "/out.png", "--size", "64x48", "--renderer",
                              engine, "--spp", "1", "--max-memory", "100M"});
        expectRefused(r, "big.hdr: a 4096x4096 environment map needs about ",
                      " MiB to read and prefilter, over the limit of 100 MiB (--max-memory)");
    }
    // The negative control: with room for it, the same render decodes the map, and its peak is over the
    // 100 MiB that the refusal kept it under.
    const Result ok = run({"render", dir + "/big.json", "-o", dir + "/ok.png", "--size", "64x48", "--renderer", "trace",
                           "--max-memory", "1G"},
                          300);
    EXPECT_EQ(ok.code, 0) << ok.out;
    EXPECT_GT(ok.peakMiB, 192.0) << ok.out;
}

TEST(HostileInput, ControlCharactersAndHugeTextStayOnOneCappedLine) {
    const std::string dir = folder("text");
    // A newline and an ANSI escape in a light type, a name 100,000 characters long in a material reference.
    writeText(dir + "/newline.json",
              R"({"shadelab": 1, "lights": [{"type": "point\n\u001b[31mred", "position": [0,1,0]}]})");
    const Result nl = render(dir + "/newline.json", dir);
    expectRefused(nl, "newline.json", "\\n\\x1b[31mred");
    EXPECT_EQ(nl.out.find('\x1b'), std::string::npos) << nl.out;
    writeText(dir + "/long.json",
              R"({"shadelab": 1, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": ")" +
                  std::string(100000, 'm') + R"("}]})");
    const Result lng = render(dir + "/long.json", dir);
    expectRefused(lng, "long.json", "unknown material");
    EXPECT_LT(lng.out.size(), 400u) << lng.out.substr(0, 400);
    // tinygltf echoes a bad data: URI whole (133 KB lines were seen); the line stays under the cap.
    writeText(dir + "/uri.gltf",
              gltfWithBuffer("data:application/octet-stream;base64," + std::string(100000, '!'), 840));
    const Result uri = render(dir + "/uri.gltf", dir);
    EXPECT_EQ(uri.code, 1) << uri.out.substr(0, 400);
    EXPECT_LT(uri.out.size(), 400u) << uri.out.substr(0, 400);
}

TEST(HostileInput, NodeDagIsRefusedByTheTriangleBudgetBeforeExpanding) {
    // 2^19 × 47 = 24,641,536 triangles from 3 KB: once 6.6 GB and 16 s of raster; now one line at once.
    const std::string dir = folder("dag");
    writeText(dir + "/dag.gltf", dagGltf(19));
    expectRefused(render(dir + "/dag.gltf", dir), "dag.gltf", "24641536 triangles once its node hierarchy is expanded");
    // Negative control: the same graph 8 levels deep (12,032 triangles) renders.
    writeText(dir + "/small.gltf", dagGltf(8));
    const Result ok = run({"render", dir + "/small.gltf", "-o", dir + "/small.png", "--size", "32x24"});
    EXPECT_EQ(ok.code, 0) << ok.out;
}

TEST(HostileInput, FifoAsSceneModelOrCompareInputNeverBlocks) {
    const std::string dir = folder("fifo");
    for (const char* name : {"scene.json", "model.gltf", "model.glb", "image.png"}) {
        const std::string fifo = dir + "/" + name;
        ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
        const bool png = std::string(name) == "image.png";
        const Result r = png ? run({"compare", fifo, fifo}) : render(fifo, dir);
        SCOPED_TRACE(name);
        expectRefused(r, fifo, "is a FIFO, not a regular file", png ? 2 : 1);
    }
    EXPECT_FALSE(fs::exists(dir + "/out.png"));
}

TEST(HostileInput, FifoAsMeshSourceOrGltfBufferNeverBlocks) {
    const std::string dir = folder("fifo-side");
    ASSERT_EQ(mkfifo((dir + "/pipe.gltf").c_str(), 0600), 0);
    ASSERT_EQ(mkfifo((dir + "/pipe.bin").c_str(), 0600), 0);
    writeText(dir + "/scene.json", R"({"shadelab": 1, "objects": [{"type": "mesh", "source": "pipe.gltf"}]})");
    expectRefused(render(dir + "/scene.json", dir), "pipe.gltf", "is a FIFO");
    writeText(dir + "/model.gltf", gltfWithBuffer("pipe.bin", 840));
    expectRefused(render(dir + "/model.gltf", dir), "pipe.bin", "is a FIFO");
}

TEST(HostileInput, RefusedBufferOutsideTheFolderIsNeverOpened) {
    // The path policy comes before any open: a FIFO outside the model's folder is refused by name, at once.
    const std::string outside = folder("outside");
    const std::string dir = folder("outside-model");
    ASSERT_EQ(mkfifo((outside + "/secret.bin").c_str(), 0600), 0);
    writeText(dir + "/model.gltf", gltfWithBuffer("../outside/secret.bin", 840));
    expectRefused(render(dir + "/model.gltf", dir), "secret.bin", "outside the model's folder");
}

TEST(HostileInput, DevZeroBehindASymlinkIsRefusedBeforeReading) {
    const std::string dir = folder("devzero");
    for (const char* name : {"x.json", "x.glb", "x.gltf", "x.png"}) {
        const std::string link = dir + "/" + name;
        fs::create_symlink("/dev/zero", link);
        const bool png = std::string(name) == "x.png";
        const Result r = png ? run({"compare", link, link}) : render(link, dir);
        SCOPED_TRACE(name);
        expectRefused(r, link, "is a device, not a regular file", png ? 2 : 1);
    }
}

TEST(HostileInput, HugeSparseBufferIsRefusedByItsSizeBeforeReading) {
    // 10 GB on disk (sparse), 840 bytes declared: refused from fstat against the declared size, not read.
    const std::string dir = folder("sparse");
    const std::string bin = dir + "/big.bin";
    { std::ofstream(bin).put('x'); }
    std::error_code ec;
    fs::resize_file(bin, uint64_t(10) << 30, ec);
    if (ec) GTEST_SKIP() << "cannot make a 10 GB sparse file here: " << ec.message();
    writeText(dir + "/model.gltf", gltfWithBuffer("big.bin", 840));
    const Result r = render(dir + "/model.gltf", dir);
    fs::remove(bin);
    expectRefused(r, "big.bin", "exceeds the limit of");
}

TEST(HostileInput, NulInAMeshSourceIsRefusedAndEscaped) {
    // "/etc/passwd\u0000.gltf" once passed the extension check and opened /etc/passwd as glTF.
    const std::string dir = folder("nul");
    writeText(dir + "/scene.json",
              R"({"shadelab": 1, "objects": [{"type": "mesh", "source": "/etc/passwd\u0000.gltf"}]})");
    const Result r = render(dir + "/scene.json", dir);
    expectRefused(r, "/etc/passwd\\x00.gltf", "NUL");
}

TEST(HostileInput, NegativeControlARegularBufferIsRead) {
    // The same model with a real 840-byte buffer loads: the refusals above are about the files, not the model.
    const std::string dir = folder("control");
    { std::ofstream(dir + "/ok.bin", std::ios::binary) << std::string(840, '\0'); }
    writeText(dir + "/model.gltf", gltfWithBuffer("ok.bin", 840));
    const Result r = run({"render", dir + "/model.gltf", "-o", dir + "/out.png", "--size", "32x24"});
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_TRUE(fs::exists(dir + "/out.png"));
}

namespace {

// RFC 4648 base64, with padding.
std::string base64(const std::string& bytes) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) v |= uint8_t(bytes[i + 2]);
        for (size_t k = 0; k < 4; ++k) out += k <= bytes.size() - i ? alphabet[(v >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

// A quad with TEXCOORD_0 whose material's base colour is texture 0 from image 0, whose JSON is `image`.
std::string texturedQuadGltf(const std::string& image) {
    std::string bytes;
    const float positions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const float uvs[] = {0, 1, 1, 1, 1, 0, 0, 0};
    const uint32_t indices[] = {0, 1, 2, 0, 2, 3};
    bytes.append(reinterpret_cast<const char*>(positions), sizeof positions);
    bytes.append(reinterpret_cast<const char*>(uvs), sizeof uvs);
    bytes.append(reinterpret_cast<const char*>(indices), sizeof indices);
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"indices":2,"material":0}]}],
      "materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],
      "textures":[{"source":0}],"images":[)" +
           image + R"(],
      "buffers":[{"byteLength":104,"uri":"data:application/octet-stream;base64,)" +
           base64(bytes) + R"("}],
      "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":32},
                     {"buffer":0,"byteOffset":80,"byteLength":24}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},
                   {"bufferView":1,"componentType":5126,"count":4,"type":"VEC2"},
                   {"bufferView":2,"componentType":5125,"count":6,"type":"SCALAR"}]})";
}

// A grey 8 × 8 baseline JPEG (a few hundred bytes) whose frame header claims `side` × `side`; stb_image
// decodes such a file to the size it claims, making up what the data lacks.
std::string forgedJpegDataUri(uint16_t side) {
    std::vector<uint8_t> jpeg = {0xFF, 0xD8,  // SOI, a quantisation table of ones, the frame, a Huffman table each
                                 0xFF, 0xDB, 0x00, 0x43, 0x00};
    jpeg.insert(jpeg.end(), 64, 1);
    jpeg.insert(jpeg.end(), {0xFF, 0xC0, 0x00, 0x0B, 0x08, uint8_t(side >> 8), uint8_t(side), uint8_t(side >> 8),
                             uint8_t(side), 0x01, 0x01, 0x11, 0x00});
    // DC table 0: one code of length 1 for category 0; AC table 0: one code of length 1 for EOB (0x00).
    for (uint8_t tc : {uint8_t(0x00), uint8_t(0x10)}) {
        jpeg.insert(jpeg.end(), {0xFF, 0xC4, 0x00, 0x14, tc, 0x01});
        jpeg.insert(jpeg.end(), 15, 0);
        jpeg.push_back(0x00);
    }
    jpeg.insert(jpeg.end(), {0xFF, 0xDA, 0x00, 0x08, 0x01, 0x01, 0x00, 0x00, 0x3F, 0x00});  // SOS, one component
    jpeg.insert(jpeg.end(), 8, 0x00);  // a few blocks of "DC 0, EOB"; the rest of the image is missing
    jpeg.insert(jpeg.end(), {0xFF, 0xD9});
    return R"({"uri":"data:image/jpeg;base64,)" + base64(std::string(jpeg.begin(), jpeg.end())) + R"("})";
}

// `path` as a copy of a good 16x8 PNG with `change` applied to its bytes.
std::string pngChanged(const std::string& path, void (*change)(std::vector<uint8_t>&)) {
    shadelab::Image8 img;
    img.width = 16;
    img.height = 8;
    img.channels = 3;
    for (int i = 0; i < 16 * 8 * 3; ++i) img.data.push_back(uint8_t(i * 37));
    std::vector<uint8_t> bytes = shadelab::encodePng(img);
    if (change) change(bytes);
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    return path;
}

// Whether `text` holds a byte a terminal could act on: a C0 control other than the line's end, DEL, a C1
// control (U+0080..U+009F in UTF-8) or a byte that is not UTF-8 at all (checked coarsely: 0xC0, 0xC1, 0xF5..0xFF
// or a continuation byte with no lead).
bool hasRawControl(const std::string& text) {
    for (size_t i = 0; i < text.size(); ++i) {
        const auto u = static_cast<unsigned char>(text[i]);
        if ((u < 0x20 && u != '\n') || u == 0x7F || u == 0xC0 || u == 0xC1 || u >= 0xF5) return true;
        if (u == 0xC2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) <= 0x9F) return true;
        if ((u & 0xC0) == 0x80 && (i == 0 || static_cast<unsigned char>(text[i - 1]) < 0x80)) return true;
    }
    return false;
}

}  // namespace

TEST(HostileInput, CompareRefusesBadChecksums) {
    const std::string dir = folder("checksums");
    const std::string good = pngChanged(dir + "/good.png", nullptr);
    // IDAT starts at byte 33 (signature 8, IHDR 25); its CRC follows its data.
    const std::string crc = pngChanged(dir + "/crc.png", [](std::vector<uint8_t>& b) {
        const size_t len = size_t(b[33]) << 24 | size_t(b[34]) << 16 | size_t(b[35]) << 8 | b[36];
        b[33 + 8 + len] ^= 0x01;
    });
    expectRefused(run({"compare", good, crc}), "crc.png: corrupt PNG: the IDAT chunk at byte 33 has a bad CRC", "", 2);
    // The zlib stream's Adler-32 changed, and the chunk's CRC made to match it.
    const std::string adler = pngChanged(dir + "/adler.png", [](std::vector<uint8_t>& b) {
        const size_t len = size_t(b[33]) << 24 | size_t(b[34]) << 16 | size_t(b[35]) << 8 | b[36];
        b[33 + 8 + len - 1] ^= 0x01;
        const uint32_t c = uint32_t(crc32(0L, &b[37], uInt(len + 4)));
        for (int k = 0; k < 4; ++k) b[33 + 8 + len + size_t(k)] = uint8_t(c >> (24 - 8 * k));
    });
    expectRefused(run({"compare", adler, good}), "adler.png: corrupt PNG: the IDAT chunk at byte 33", "Adler-32", 2);
    // Negative control: the untouched file compares equal to itself.
    const Result ok = run({"compare", good, pngChanged(dir + "/same.png", nullptr)});
    EXPECT_EQ(ok.code, 0) << ok.out;
}

TEST(HostileInput, AForgedJpegIsRefusedByItsHeaderBeforeDecoding) {
    // A few hundred bytes claiming 8000²: stb_image once decoded it to a gigabyte, with or without --strict.
    const std::string dir = folder("jpeg");
    writeText(dir + "/bomb.gltf", texturedQuadGltf(forgedJpegDataUri(8000)));
    ASSERT_LT(fs::file_size(dir + "/bomb.gltf"), 2000u);
    const std::vector<std::string> trace = {"-o", dir + "/out.png", "--renderer", "trace", "--size", "8x8"};
    std::vector<std::string> strict = {"render", dir + "/bomb.gltf", "--strict"};
    strict.insert(strict.end(), trace.begin(), trace.end());
    expectRefused(run(strict), "bomb.gltf", "8000x8000 = 64000000 pixels, over the limit of 16777216 pixels");
    // Without --strict, a warning and the factor alone, still within the bounds.
    std::vector<std::string> lenient = {"render", dir + "/bomb.gltf"};
    lenient.insert(lenient.end(), trace.begin(), trace.end());
    const Result warned = run(lenient);
    EXPECT_EQ(warned.code, 0) << warned.out;
    EXPECT_NE(warned.out.find("warning: " + dir + "/bomb.gltf: images[0]"), std::string::npos) << warned.out;
    EXPECT_LT(warned.peakMiB, kMaxPeakMiB) << warned.out;
    // Negative control: the same forgery claiming 64² is a texture the limits allow, and decodes without a
    // word: stb_image believes the header, so the header's size is what must be checked.
    writeText(dir + "/small.gltf", texturedQuadGltf(forgedJpegDataUri(64)));
    strict[1] = dir + "/small.gltf";
    const Result ok = run(strict);
    EXPECT_EQ(ok.code, 0) << ok.out;
}

TEST(HostileInput, MessagesAreOneLineOfPrintableUtf8) {
    const std::string dir = folder("utf8");
    // A C1 control (U+009B, the one-byte CSI) in a light type, and invalid UTF-8 quoted by a JSON parse error.
    writeText(dir + "/c1.json", R"({"shadelab": 1, "lights": [{"type": "\u009b31mred", "position": [0,1,0]}]})");
    const Result c1 = render(dir + "/c1.json", dir);
    expectRefused(c1, "c1.json", "\\xc2\\x9b31mred");
    EXPECT_FALSE(hasRawControl(c1.out)) << c1.out;
    writeText(dir + "/bytes.json", "{\"shadelab\": 1, \"lights\": \"\xFF\xC2\x9B\"}");
    const Result bytes = render(dir + "/bytes.json", dir);
    expectRefused(bytes, "bytes.json", "\\xff");
    EXPECT_FALSE(hasRawControl(bytes.out)) << bytes.out;
    // Negative control: the checker sees the raw bytes the files hold.
    std::ifstream in(dir + "/bytes.json", std::ios::binary);
    EXPECT_TRUE(hasRawControl(std::string(std::istreambuf_iterator<char>(in), {})));
    EXPECT_TRUE(hasRawControl("\xC2\x9B"));
    EXPECT_FALSE(hasRawControl("caf\xC3\xA9 \xC2\xA0\n"));  // é and U+00A0 are text
    // Newlines in an image URI ("%0A", or "\n" in JSON) stay inside the warning's one line.
    writeText(dir + "/nl.gltf", texturedQuadGltf(R"({"uri":"x%0Ay\nz.png"})"));
    const Result nl = run({"render", dir + "/nl.gltf", "-o", dir + "/out.png", "--renderer", "trace", "--size", "8x8"});
    EXPECT_EQ(nl.code, 0) << nl.out;
    EXPECT_EQ(std::count(nl.out.begin(), nl.out.end(), '\n'), 1) << nl.out;  // the split gave three lines
    EXPECT_NE(nl.out.find("cannot read \"x%0Ay\\nz.png\""), std::string::npos) << nl.out;
}

TEST(HostileInput, ModelLoadIsHeldToTheMemoryBudgetBeforeExpanding) {
    // 2^18 × 47 = 12,320,768 triangles: under the 16 M triangle limit, so it once loaded to 1.2 GB before
    // --max-memory 512M refused the render; now the budget lowers the triangle limit and the load never starts.
    const std::string dir = folder("dag_budget");
    writeText(dir + "/dag.gltf", dagGltf(18));
    const Result r =
        run({"render", dir + "/dag.gltf", "-o", dir + "/out.png", "--size", "64x48", "--max-memory", "512M"});
    EXPECT_EQ(r.code, 1) << r.out;
    EXPECT_NE(r.out.find("12320768 triangles"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("the most 512 MiB (--max-memory) can load"), std::string::npos) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    EXPECT_LT(r.peakMiB, 200.0) << "refused from the accessor counts, before any vertex";
    EXPECT_FALSE(fs::exists(dir + "/out.png"));
    // Negative control: the same graph 8 levels deep renders under the same budget.
    writeText(dir + "/small.gltf", dagGltf(8));
    const Result ok =
        run({"render", dir + "/small.gltf", "-o", dir + "/small.png", "--size", "64x48", "--max-memory", "512M"});
    EXPECT_EQ(ok.code, 0) << ok.out;
}
