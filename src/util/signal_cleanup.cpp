// SignalCleanup: a fixed table of (folder, name) pairs that a SIGINT/SIGTERM/SIGHUP handler unlinks before
// re-raising the signal with its default action. Everything the handler touches is async-signal-safe:
// lock-free atomics, unlinkat, sigaction and raise.
#include "util/signal_cleanup.h"

#include <fcntl.h>
#include <unistd.h>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <mutex>

namespace shadelab {
namespace {

enum SlotState : int { kFree = 0, kFilling = 1, kArmed = 2 };

struct Slot {
    std::atomic<int> state{kFree};
    int dirFd = -1;
    char name[SignalCleanup::kMaxName + 1] = {};
};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads slot states");

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
constexpr int kSignalCount = int(sizeof kSignals / sizeof kSignals[0]);

Slot slots[SignalCleanup::kSlots];

// Guards the handler installation; never taken by the handler itself.
std::mutex installMutex;
int registered = 0;
bool installed[kSignalCount] = {};
struct sigaction previous[kSignalCount];

void onSignal(int sig) {
    const int savedErrno = errno;
    for (Slot& s : slots)
        if (s.state.load(std::memory_order_acquire) == kArmed) ::unlinkat(s.dirFd, s.name, 0);
    // Default action, then the same signal again: it is blocked while this handler runs, so it is
    // delivered on return and the process ends exactly as it would have without us (status, core).
    struct sigaction dfl;
    std::memset(&dfl, 0, sizeof dfl);
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    ::sigaction(sig, &dfl, nullptr);
    ::raise(sig);
    errno = savedErrno;
}

void installHandlers() {
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    // Block the other two while one runs, so the table is walked once.
    for (int sig : kSignals) sigaddset(&action.sa_mask, sig);
    for (int i = 0; i < kSignalCount; ++i) {
        installed[i] = false;
        if (::sigaction(kSignals[i], nullptr, &previous[i]) != 0) continue;
        const bool isDefault = !(previous[i].sa_flags & SA_SIGINFO) && previous[i].sa_handler == SIG_DFL;
        if (isDefault) installed[i] = ::sigaction(kSignals[i], &action, nullptr) == 0;
    }
}

void restoreHandlers() {
    for (int i = 0; i < kSignalCount; ++i)
        if (installed[i]) ::sigaction(kSignals[i], &previous[i], nullptr);
}

}  // namespace

SignalCleanup::SignalCleanup(int dirFd, const std::string& name) {
    if (name.size() > size_t(kMaxName)) return;
    for (int i = 0; i < kSlots; ++i) {
        int expected = kFree;
        if (!slots[i].state.compare_exchange_strong(expected, kFilling, std::memory_order_acquire)) continue;
        slots[i].dirFd = dirFd;
        std::memcpy(slots[i].name, name.c_str(), name.size() + 1);
        slots[i].state.store(kArmed, std::memory_order_release);
        slot_ = i;
        break;
    }
    if (slot_ < 0) return;  // more than kSlots writes at once: this one goes without signal cleanup
    std::lock_guard<std::mutex> lock(installMutex);
    if (registered++ == 0) installHandlers();
}

SignalCleanup::~SignalCleanup() {
    if (slot_ < 0) return;
    slots[slot_].state.store(kFree, std::memory_order_release);
    std::lock_guard<std::mutex> lock(installMutex);
    if (--registered == 0) restoreHandlers();
}

}  // namespace shadelab
