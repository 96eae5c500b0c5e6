// WebContext: the page's WebGL2 context on one canvas, made current, with the extensions the rasterizer's
// float targets need and shadelab's GL entry points loaded from it. The page's counterpart of the native
// headless contexts (gl/headless_context.h); only the web build has it.
#pragma once

#include <string>

namespace shadelab::web {

class WebContext {
public:
    // `canvas`: a CSS selector of the canvas, e.g. "#gl". Throws std::runtime_error with a sentence for the page
    // when the browser has no WebGL2 or lacks EXT_color_buffer_float (float render targets).
    explicit WebContext(const std::string& canvas);
    ~WebContext();
    WebContext(const WebContext&) = delete;
    WebContext& operator=(const WebContext&) = delete;

    // GL_RENDERER and GL_VERSION, for the page's "about" line and the tests' records.
    const std::string& renderer() const { return renderer_; }
    const std::string& version() const { return version_; }

private:
    int handle_ = 0;  // EMSCRIPTEN_WEBGL_CONTEXT_HANDLE
    std::string renderer_, version_;
};

}  // namespace shadelab::web
