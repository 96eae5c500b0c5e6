// Run-time choice of the BVH walks' instruction set (bvh_isa.h).
#include "trace/accel/bvh_isa.h"

#include <cstdlib>
#include <cstring>

namespace shadelab::trace {

bool bvhIsaAvailable(BvhIsa isa) {
    switch (isa) {
        case BvhIsa::Sse2: return true;
        case BvhIsa::Avx2:
#if defined(SHADELAB_BVH_AVX2) && (defined(__GNUC__) || defined(__clang__))
            return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
            return false;
#endif
    }
    return false;
}

BvhIsa defaultBvhIsa() {
    static const BvhIsa isa = [] {
        const char* forced = std::getenv("SHADELAB_BVH_ISA");
        if (forced && std::strcmp(forced, "sse2") == 0) return BvhIsa::Sse2;
        return bvhIsaAvailable(BvhIsa::Avx2) ? BvhIsa::Avx2 : BvhIsa::Sse2;
    }();
    return isa;
}

const char* bvhIsaName(BvhIsa isa) { return isa == BvhIsa::Avx2 ? "avx2" : "sse2"; }

}  // namespace shadelab::trace
