// CHECK macros for programmer errors: print both operands and abort. Input errors use InputError instead.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <sstream>

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
#define SHADELAB_CHECK_LT(a, b) SHADELAB_CHECK_OP(a, <, b)
#define SHADELAB_CHECK_LE(a, b) SHADELAB_CHECK_OP(a, <=, b)
