// GlSession: the process's one headless GL context (gl/headless_context.h: EGL device → EGL surfaceless → OSMesa),
// shared by every Python Renderer and handed from thread to thread. One context per process, because GL entry
// points are process-wide (gl/gl_api.h) and EGL displays are shared: tearing down one of two contexts on the same
// display (eglTerminate) would pull the other's from under it.
#pragma once

#include "gl/headless_context.h"

#include <functional>
#include <memory>
#include <mutex>

namespace shadelab::python {

class GlSession {
public:
    // The live session, or a new one. `backend` Auto reads SHADELAB_GL_BACKEND as the binary does. Asking for a
    // backend other than the live session's throws UsageError. Throws gl::ContextError when none works.
    static std::shared_ptr<GlSession> acquire(gl::GlBackend backend);

    // Runs `work` on the calling thread with the context current, one caller at a time, and releases the context
    // afterwards (also when `work` throws), so that the next caller may be another thread.
    void run(const std::function<void()>& work);

    const gl::ContextInfo& info() const { return context_->info(); }
    ~GlSession();

private:
    GlSession() = default;
    std::mutex mutex_;
    std::unique_ptr<gl::HeadlessContext> context_;
};

}  // namespace shadelab::python
