// The files this process reads its work from: a scene and everything it reads (glTF models, buffers,
// images, the environment map), and a viewer script, for as long as something made from them is alive.
// No output may replace one of them, whatever name it is given (the same name, a symlink, a hard link,
// `./x`, a derived `<stem>_heat.png`): writeFileAtomic and checkWritableTarget (atomic_file.h) ask
// refuseOpenInput before writing, so every command, the viewer, scripts and Python follow the one rule.
//
// Files are known by device and inode. They are recorded as readFile reads them while an InputRecorder is
// alive on the reading thread, and stay registered while any copy of the InputFiles that holds them lives
// (a Scene carries one): a scene that was closed no longer protects its files.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {

class InputFiles {
public:
    InputFiles() = default;

    // Records `path` (nothing when it does not exist). Copies share the record: adding through one adds
    // for all.
    void add(const std::string& path);
    // The names the files were read by, in order, each once.
    std::vector<std::string> paths() const;

    struct Registration;  // the shared record, listed with the process while it lives

private:
    std::shared_ptr<Registration> reg_;
};

// While alive, every file readFile reads on this thread is added to `files` (the innermost recorder when
// they nest). Not copyable; lives on the stack of a loader.
class InputRecorder {
public:
    explicit InputRecorder(InputFiles& files);
    ~InputRecorder();
    InputRecorder(const InputRecorder&) = delete;
    InputRecorder& operator=(const InputRecorder&) = delete;

private:
    friend void noteInputRead(const std::string& path);
    InputFiles& files_;
    InputRecorder* outer_;
};

// Called by readFile for each file it has read.
void noteInputRead(const std::string& path);

// The name an open input was read by when `path` is that same file (through symlinks), else nothing.
std::optional<std::string> openInputAt(const std::string& path);

// Throws InputError(path, "refusing to overwrite an input with the output[: it is <input>]") when
// openInputAt(path) finds one.
void refuseOpenInput(const std::string& path);

}  // namespace shadelab
