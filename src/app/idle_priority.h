// The background renderers' threads (the Whitted reference, the path tracer of Global mode) run at idle
// priority, so the UI thread and llvmpipe's threads always come first.
#pragma once

#include <sched.h>
#include <sys/resource.h>

#include <algorithm>
#include <thread>

namespace shadelab::app {

// Drops the calling thread to SCHED_IDLE (only otherwise idle cores), or nice +19 where that is refused. On
// Linux scheduling policy and nice value belong to the thread, and threads inherit them from their creator,
// so workers started afterwards run at idle priority too. Nice +10 alone was not enough: reference workers
// restarted on every slider step still took half of both cores.
inline void lowerToIdlePriority() {
    const sched_param idle{};
    if (sched_setscheduler(0, SCHED_IDLE, &idle) != 0) setpriority(PRIO_PROCESS, 0, 19);
}

// Workers for a background renderer: every core but one, which stays the UI thread's; at least one.
inline int backgroundWorkerCount() { return std::max(1, int(std::thread::hardware_concurrency()) - 1); }

}  // namespace shadelab::app
