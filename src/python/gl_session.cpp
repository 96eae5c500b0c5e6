// GlSession: one context per process, created on first use, made current around each piece of work.
#include "python/gl_session.h"

#include "util/input_error.h"

namespace shadelab::python {
namespace {

// Held while a session is made or torn down, so that a new context is never created on a display that the last
// session's teardown (eglTerminate) is about to close. Recursive: acquire() may drop the last reference itself.
std::recursive_mutex gSessionMutex;
std::weak_ptr<GlSession> gSession;  // the live one; it ends with its last Renderer

}  // namespace

std::shared_ptr<GlSession> GlSession::acquire(gl::GlBackend backend) {
    std::lock_guard<std::recursive_mutex> lock(gSessionMutex);
    if (std::shared_ptr<GlSession> live = gSession.lock()) {
        if (backend != gl::GlBackend::Auto && backend != live->info().backend)
            throw UsageError(std::string("backend: this process already renders through ") +
                             gl::toString(live->info().backend) + "; one GL backend per process (asked for " +
                             gl::toString(backend) + ")");
        return live;
    }
    std::shared_ptr<GlSession> session(new GlSession());
    session->context_ = gl::createHeadlessContext(backend);
    session->context_->release();  // current on no thread until run() makes it so
    gSession = session;
    return session;
}

void GlSession::run(const std::function<void()>& work) {
    std::lock_guard<std::mutex> lock(mutex_);
    context_->makeCurrent();
    try {
        work();
    } catch (...) {
        context_->release();
        throw;
    }
    context_->release();
}

GlSession::~GlSession() {
    // The context is destroyed from whichever thread drops the last reference; it is current on none.
    std::lock_guard<std::recursive_mutex> lock(gSessionMutex);
    context_.reset();
}

}  // namespace shadelab::python
