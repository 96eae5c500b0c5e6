// An LD_PRELOAD shim for cli_test: logs the fsync, linkat and rename calls that reach libc, with the paths
// they touch, and can hold each fsync of a regular file for a while, so a test can check the order of an
// atomic write and signal a render in the middle of it. Test-only; never linked into shadelab.
#include <dlfcn.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>

namespace {

template <class Fn>
Fn real(const char* name) {
    return reinterpret_cast<Fn>(::dlsym(RTLD_NEXT, name));
}

std::string fdPath(int fd) {
    if (fd == AT_FDCWD) return ".";
    char link[64], target[4096];
    std::snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
    ssize_t n = ::readlink(link, target, sizeof target - 1);
    return n < 0 ? "?" : std::string(target, size_t(n));
}

// One line per call to $SHADELAB_PROBE_LOG, appended with one write() so concurrent lines stay whole.
void logLine(const std::string& line) {
    const char* path = std::getenv("SHADELAB_PROBE_LOG");
    if (!path) return;
    int fd = ::open(path, O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) return;
    const std::string text = line + "\n";
    [[maybe_unused]] ssize_t n = ::write(fd, text.data(), text.size());  // a lost line shows in the test
    ::close(fd);
}

}  // namespace

extern "C" int fsync(int fd) {
    struct stat st;
    const bool dir = ::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode);
    logLine(std::string(dir ? "fsync dir " : "fsync file ") + fdPath(fd));
    const char* delayMs = std::getenv("SHADELAB_PROBE_FSYNC_DELAY_MS");
    if (delayMs && !dir) {
        const long ms = std::atol(delayMs);
        const timespec delay{ms / 1000, (ms % 1000) * 1000000};
        ::nanosleep(&delay, nullptr);  // a signal ends it early, as it would end a slow disk's wait
    }
    return real<int (*)(int)>("fsync")(fd);
}

extern "C" int linkat(int oldDir, const char* oldPath, int newDir, const char* newPath, int flags) {
    int rc = real<int (*)(int, const char*, int, const char*, int)>("linkat")(oldDir, oldPath, newDir, newPath, flags);
    if (rc == 0) logLine("link " + fdPath(newDir) + "/" + newPath);
    return rc;
}

extern "C" int renameat(int oldDir, const char* oldPath, int newDir, const char* newPath) {
    int rc = real<int (*)(int, const char*, int, const char*)>("renameat")(oldDir, oldPath, newDir, newPath);
    if (rc == 0) logLine("rename " + fdPath(oldDir) + "/" + oldPath + " " + fdPath(newDir) + "/" + newPath);
    return rc;
}

extern "C" int rename(const char* oldPath, const char* newPath) {
    int rc = real<int (*)(const char*, const char*)>("rename")(oldPath, newPath);
    if (rc == 0) logLine(std::string("rename ") + oldPath + " " + newPath);
    return rc;
}
