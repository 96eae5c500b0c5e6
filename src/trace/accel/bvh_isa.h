// Which instruction set the BVH walks use: x86-64's baseline SSE2 everywhere, or AVX2 with FMA (8 child boxes in
// one register, bvh_traverse_avx2.h) where the build has the AVX2 walks and the CPU runs them. Both find the same
// hits bit for bit; only the speed differs. Chosen once per process at run time.
#pragma once

namespace shadelab::trace {

enum class BvhIsa { Sse2, Avx2 };

// Whether this build and this CPU can run the walks of `isa` (Sse2 always).
bool bvhIsaAvailable(BvhIsa isa);

// The walks MeshBvh uses unless told otherwise: Avx2 when available, else Sse2. The environment variable
// SHADELAB_BVH_ISA=sse2 forces the baseline (for benchmarks and for checking that both give the same images).
BvhIsa defaultBvhIsa();

const char* bvhIsaName(BvhIsa isa);

}  // namespace shadelab::trace
