// SignalCleanup: removes a temporary file's name when SIGINT, SIGTERM or SIGHUP ends the process, then lets
// the signal terminate it as it would have (same exit status). Used by writeFileAtomic; not a general
// signal framework.
#pragma once

#include <string>

namespace shadelab {

// Registers `name` (relative to the open folder `dirFd`) for removal while the object lives. The handlers
// are installed while at least one name is registered, and only for signals whose disposition is the
// default: an ignored SIGHUP (nohup) stays ignored, and a program's own handler is left alone.
class SignalCleanup {
public:
    SignalCleanup(int dirFd, const std::string& name);
    SignalCleanup(const SignalCleanup&) = delete;
    SignalCleanup& operator=(const SignalCleanup&) = delete;
    ~SignalCleanup();

    // True when the name fits the async-signal-safe table (at most kMaxName bytes, kSlots at once).
    bool armed() const { return slot_ >= 0; }

    static constexpr int kSlots = 32;
    static constexpr int kMaxName = 63;

private:
    int slot_ = -1;
};

}  // namespace shadelab
