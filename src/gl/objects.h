// Move-only RAII wrappers for GL object names: the destructor deletes, copying is deleted.
// They must be destroyed while their context is current (renderers own them and outlive no context).
#pragma once

#include "gl/gl_api.h"

#include <utility>

namespace shadelab::gl {

template <typename Traits>
class Object {
public:
    Object() = default;
    static Object create() {
        Object o;
        o.id_ = Traits::create();
        return o;
    }
    ~Object() { reset(); }
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;
    Object(Object&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    Object& operator=(Object&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = std::exchange(o.id_, 0);
        }
        return *this;
    }
    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_) Traits::destroy(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

#define SHADELAB_GL_GEN_TRAITS(Name, gen, del)          \
    struct Name##Traits {                               \
        static GLuint create() {                        \
            GLuint id = 0;                              \
            gen(1, &id);                                \
            return id;                                  \
        }                                               \
        static void destroy(GLuint id) { del(1, &id); } \
    };                                                  \
    using Name = Object<Name##Traits>;

SHADELAB_GL_GEN_TRAITS(Buffer, glGenBuffers, glDeleteBuffers)
SHADELAB_GL_GEN_TRAITS(VertexArray, glGenVertexArrays, glDeleteVertexArrays)
SHADELAB_GL_GEN_TRAITS(Texture, glGenTextures, glDeleteTextures)
SHADELAB_GL_GEN_TRAITS(Framebuffer, glGenFramebuffers, glDeleteFramebuffers)
SHADELAB_GL_GEN_TRAITS(Renderbuffer, glGenRenderbuffers, glDeleteRenderbuffers)
#undef SHADELAB_GL_GEN_TRAITS

struct ProgramTraits {
    static GLuint create() { return glCreateProgram(); }
    static void destroy(GLuint id) { glDeleteProgram(id); }
};
using ProgramHandle = Object<ProgramTraits>;

}  // namespace shadelab::gl
