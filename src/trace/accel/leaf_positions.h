// How MeshBvh stores a leaf's triangle corners: structure of arrays per leaf. A leaf of `count` triangles at
// slots [first, first + count) owns the floats [9·first, 9·(first + count)) of the positions array, as 9 rows
// of `count` floats: row 3·c + a holds axis a (x, y, z) of corner c (v0, v1, v2), triangle j at column j. So the
// AVX2 leaf test reads each row of up to four triangles with one load, where an array of triangles needed a
// masked load, a permute and a transpose per corner; the scalar tests gather a triangle's 9 floats first. The
// array ends with kLeafRowPadding spare floats, so a 4-wide load of the last row stays inside it (the lanes past
// `count` read the next rows and are masked off).
#pragma once

#include <cstddef>
#include <cstdint>

namespace shadelab::trace {

inline constexpr size_t kLeafRowPadding = 3;

// Triangle j of the leaf whose rows start at `rows` (positions + 9·first): its corners as v0, v1, v2.
inline void gatherLeafTriangle(const float* rows, uint32_t count, uint32_t j, float out[9]) {
    for (uint32_t r = 0; r < 9; ++r) out[r] = rows[size_t(r) * count + j];
}

}  // namespace shadelab::trace
