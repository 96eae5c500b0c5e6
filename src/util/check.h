// CHECK macros for programmer errors: print both operands and abort. Input errors use InputError instead.
//
// SHADELAB_CHECK*: always on, in every build type. For invariants whose failure would corrupt output or memory.
// SHADELAB_DCHECK*: the same checks in Debug and sanitizer builds, compiled out in Release (NDEBUG defined), for
// invariants on paths too hot to pay for them, or that only catch a caller's mistake during development. In
// Release their operands are still compiled (they stay valid code, and variables they alone use do not warn) but
// never evaluated, so they must not have side effects the program relies on. shadelab::kDcheckEnabled says which
// a build does.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace shadelab {
#ifdef NDEBUG
inline constexpr bool kDcheckEnabled = false;
#else
inline constexpr bool kDcheckEnabled = true;
#endif
}  // namespace shadelab

#define SHADELAB_CHECK(cond)                                                              \
    do {                                                                                  \
        if (!(cond)) {                                                                    \
            std::fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond); \
            std::abort();                                                                 \
        }                                                                                 \
    } while (0)

#define SHADELAB_CHECK_OP(a, op, b)                                                                        \
    do {                                                                                                   \
        const auto& check_a_ = (a);                                                                        \
        const auto& check_b_ = (b);                                                                        \
        if (!(check_a_ op check_b_)) {                                                                     \
            std::ostringstream check_s_;                                                                   \
            check_s_ << #a " " #op " " #b " (" << check_a_ << " vs " << check_b_ << ")";                   \
            std::fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, check_s_.str().c_str()); \
            std::abort();                                                                                  \
        }                                                                                                  \
    } while (0)

#define SHADELAB_CHECK_EQ(a, b) SHADELAB_CHECK_OP(a, ==, b)
#define SHADELAB_CHECK_NE(a, b) SHADELAB_CHECK_OP(a, !=, b)
#define SHADELAB_CHECK_LT(a, b) SHADELAB_CHECK_OP(a, <, b)
#define SHADELAB_CHECK_LE(a, b) SHADELAB_CHECK_OP(a, <=, b)
#define SHADELAB_CHECK_GE(a, b) SHADELAB_CHECK_OP(a, >=, b)
#define SHADELAB_CHECK_GT(a, b) SHADELAB_CHECK_OP(a, >, b)

// `if (kDcheckEnabled)` with a constant: Release compiles the check and drops it as dead code.
#define SHADELAB_DCHECK(cond)                                 \
    do {                                                      \
        if (::shadelab::kDcheckEnabled) SHADELAB_CHECK(cond); \
    } while (0)
#define SHADELAB_DCHECK_OP(a, op, b)                                 \
    do {                                                             \
        if (::shadelab::kDcheckEnabled) SHADELAB_CHECK_OP(a, op, b); \
    } while (0)

#define SHADELAB_DCHECK_EQ(a, b) SHADELAB_DCHECK_OP(a, ==, b)
#define SHADELAB_DCHECK_NE(a, b) SHADELAB_DCHECK_OP(a, !=, b)
#define SHADELAB_DCHECK_LT(a, b) SHADELAB_DCHECK_OP(a, <, b)
#define SHADELAB_DCHECK_LE(a, b) SHADELAB_DCHECK_OP(a, <=, b)
#define SHADELAB_DCHECK_GE(a, b) SHADELAB_DCHECK_OP(a, >=, b)
#define SHADELAB_DCHECK_GT(a, b) SHADELAB_DCHECK_OP(a, >, b)
