// WebContext: emscripten's WebGL2 context, and shadelab's GL entry points loaded through its proc lookup.
#include "web_context.h"

#include "gl/gl_api.h"

#include <emscripten/html5.h>
#include <emscripten/html5_webgl.h>
#include <stdexcept>

namespace shadelab::web {
namespace {

void* procAddress(const char* name) { return emscripten_webgl_get_proc_address(name); }

}  // namespace

WebContext::WebContext(const std::string& canvas) {
    EmscriptenWebGLContextAttributes attrs;
    emscripten_webgl_init_context_attributes(&attrs);
    attrs.majorVersion = 2;
    attrs.minorVersion = 0;
    attrs.alpha = false;
    attrs.depth = true;
    attrs.antialias = false;  // the rasterizer supersamples on its own grid, as natively
    attrs.preserveDrawingBuffer = false;
    attrs.powerPreference = EM_WEBGL_POWER_PREFERENCE_HIGH_PERFORMANCE;
    handle_ = int(emscripten_webgl_create_context(canvas.c_str(), &attrs));
    if (handle_ <= 0) throw std::runtime_error("this browser has no WebGL2, which the page's rasterizer needs");
    emscripten_webgl_make_context_current(EMSCRIPTEN_WEBGL_CONTEXT_HANDLE(handle_));
    // Float colour targets (the rasterizer draws linear RGBA32F, as natively) and blending into them.
    if (!emscripten_webgl_enable_extension(EMSCRIPTEN_WEBGL_CONTEXT_HANDLE(handle_), "EXT_color_buffer_float"))
        throw std::runtime_error("this browser's WebGL2 cannot render to float textures (EXT_color_buffer_float)");
    emscripten_webgl_enable_extension(EMSCRIPTEN_WEBGL_CONTEXT_HANDLE(handle_), "EXT_float_blend");
    if (const char* missing = gl::loadFunctions(procAddress))
        throw std::runtime_error(std::string("this browser's WebGL2 lacks ") + missing);
    renderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    version_ = reinterpret_cast<const char*>(glGetString(GL_VERSION));
}

WebContext::~WebContext() {
    if (handle_ > 0) emscripten_webgl_destroy_context(EMSCRIPTEN_WEBGL_CONTEXT_HANDLE(handle_));
}

}  // namespace shadelab::web
