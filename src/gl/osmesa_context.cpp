// OSMesa fallback context (design.md §3), loaded with dlopen so shadelab runs where libOSMesa is absent
// (Mesa removed it in 25.1). Draws into a 1x1 client buffer; real rendering uses framebuffer objects.
#include "gl/headless_context.h"

#include <dlfcn.h>

#include <string>

namespace shadelab::gl {
namespace {

// From GL/osmesa.h; repeated here so this file needs neither the header nor the library at build time.
constexpr int kOsmesaFormat = 0x22, kOsmesaRgba = 0x1908, kOsmesaDepthBits = 0x30, kOsmesaProfile = 0x33,
              kOsmesaCoreProfile = 0x34, kOsmesaMajor = 0x36, kOsmesaMinor = 0x37;
constexpr unsigned kGlUnsignedByte = 0x1401;

using OSMesaContextPtr = void*;
using CreateContextAttribsFn = OSMesaContextPtr (*)(const int*, OSMesaContextPtr);
using MakeCurrentFn = unsigned char (*)(OSMesaContextPtr, void*, unsigned, int, int);
using DestroyContextFn = void (*)(OSMesaContextPtr);
using GetProcAddressFn = void* (*)(const char*);

GetProcAddressFn gGetProcAddress = nullptr;  // for the capture-less lambda passed to finishContextInfo

class OSMesaHeadless : public HeadlessContext {
public:
    // Loads the library, creates a 3.3 core context and makes it current; throws on failure.
    void init() {
        for (const char* name : {"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"})
            if ((lib_ = dlopen(name, RTLD_NOW | RTLD_LOCAL))) break;
        if (!lib_) throw std::runtime_error("libOSMesa not found (Debian package libosmesa6)");
        auto create = reinterpret_cast<CreateContextAttribsFn>(dlsym(lib_, "OSMesaCreateContextAttribs"));
        makeCurrent_ = reinterpret_cast<MakeCurrentFn>(dlsym(lib_, "OSMesaMakeCurrent"));
        destroy_ = reinterpret_cast<DestroyContextFn>(dlsym(lib_, "OSMesaDestroyContext"));
        gGetProcAddress = reinterpret_cast<GetProcAddressFn>(dlsym(lib_, "OSMesaGetProcAddress"));
        if (!create || !makeCurrent_ || !destroy_ || !gGetProcAddress)
            throw std::runtime_error("libOSMesa lacks OSMesaCreateContextAttribs");
        const int attribs[] = {kOsmesaFormat,
                               kOsmesaRgba,
                               kOsmesaDepthBits,
                               0,
                               kOsmesaProfile,
                               kOsmesaCoreProfile,
                               kOsmesaMajor,
                               3,
                               kOsmesaMinor,
                               3,
                               0};
        context_ = create(attribs, nullptr);
        if (!context_) throw std::runtime_error("OSMesaCreateContextAttribs (OpenGL 3.3 core) failed");
        makeCurrent();
        info_.backend = GlBackend::OSMesa;
        info_.device = "OSMesa";
        finishContextInfo(info_, [](const char* name) { return gGetProcAddress(name); });
    }
    void makeCurrent() override {
        if (!makeCurrent_(context_, pixel_, kGlUnsignedByte, 1, 1))
            throw std::runtime_error("OSMesaMakeCurrent failed");
    }
    // OSMesa's documented way to unbind: a null context.
    void release() override { makeCurrent_(nullptr, nullptr, 0, 0, 0); }

    ~OSMesaHeadless() override {
        if (context_) destroy_(context_);
        // The library stays loaded: Mesa registers atexit handlers that must outlive this object.
    }

private:
    void* lib_ = nullptr;
    OSMesaContextPtr context_ = nullptr;
    MakeCurrentFn makeCurrent_ = nullptr;
    DestroyContextFn destroy_ = nullptr;
    unsigned char pixel_[4] = {};
};

}  // namespace

std::unique_ptr<HeadlessContext> createOSMesaContext() {
    auto ctx = std::make_unique<OSMesaHeadless>();
    ctx->init();
    return ctx;
}

}  // namespace shadelab::gl
