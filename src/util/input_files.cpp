// The process's open inputs: one list of live records under a mutex (a handful of scenes at most, each a
// few files), searched by device and inode when a file is about to be written.
#include "util/input_files.h"

#include "util/input_error.h"

#include <sys/stat.h>
#include <algorithm>
#include <mutex>

namespace shadelab {

struct InputFiles::Registration {
    struct File {
        dev_t dev;
        ino_t ino;
        std::string path;
    };
    std::vector<File> files;  // guarded by registryMutex()

    Registration();
    ~Registration();
};

namespace {

// Both live for the whole process and are never destroyed: a Scene held by a static or freed during the
// interpreter's shutdown must still find them (no static destruction order to get wrong).
std::mutex& registryMutex() {
    static std::mutex* m = new std::mutex;
    return *m;
}

// Every live Registration; guarded by registryMutex().
std::vector<const InputFiles::Registration*>& registry() {
    static auto* r = new std::vector<const InputFiles::Registration*>;
    return *r;
}

thread_local InputRecorder* innermost = nullptr;

}  // namespace

InputFiles::Registration::Registration() {
    std::lock_guard<std::mutex> lock(registryMutex());
    registry().push_back(this);
}

InputFiles::Registration::~Registration() {
    std::lock_guard<std::mutex> lock(registryMutex());
    auto& r = registry();
    r.erase(std::remove(r.begin(), r.end(), this), r.end());
}

void InputFiles::add(const std::string& path) {
    struct stat st;
    if (path.empty() || ::stat(path.c_str(), &st) != 0) return;
    if (!reg_) reg_ = std::make_shared<Registration>();
    std::lock_guard<std::mutex> lock(registryMutex());
    for (const Registration::File& f : reg_->files)
        if (f.dev == st.st_dev && f.ino == st.st_ino) return;
    reg_->files.push_back({st.st_dev, st.st_ino, path});
}

std::vector<std::string> InputFiles::paths() const {
    std::vector<std::string> out;
    if (!reg_) return out;
    std::lock_guard<std::mutex> lock(registryMutex());
    for (const Registration::File& f : reg_->files) out.push_back(f.path);
    return out;
}

InputRecorder::InputRecorder(InputFiles& files) : files_(files), outer_(innermost) { innermost = this; }

InputRecorder::~InputRecorder() { innermost = outer_; }

void noteInputRead(const std::string& path) {
    if (innermost) innermost->files_.add(path);
}

std::optional<std::string> openInputAt(const std::string& path) {
    struct stat st;
    if (path.empty() || ::stat(path.c_str(), &st) != 0) return std::nullopt;  // a new file is no input
    std::lock_guard<std::mutex> lock(registryMutex());
    for (const InputFiles::Registration* reg : registry())
        for (const InputFiles::Registration::File& f : reg->files)
            if (f.dev == st.st_dev && f.ino == st.st_ino) return f.path;
    return std::nullopt;
}

void refuseOpenInput(const std::string& path) {
    if (const std::optional<std::string> input = openInputAt(path))
        throw InputError(path, "refusing to overwrite an input with the output" +
                                   (*input == path ? std::string() : ": it is " + *input));
}

}  // namespace shadelab
