// Cutting triangle references for spatial splits (spatial_splits.h): Sutherland–Hodgman clipping of the
// triangle to its reference's box, then at the builder's planes.
#include "trace/accel/spatial_splits.h"

#include "scene/bounds.h"
#include "trace/accel/simd4.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace shadelab::trace {
namespace {

Bounds boxOf(const BvhPrim& p) { return Bounds{{p.lo[0], p.lo[1], p.lo[2]}, {p.hi[0], p.hi[1], p.hi[2]}}; }

BvhPrim withBox(BvhPrim p, const Bounds& b) {
    for (int a = 0; a < 3; ++a) {
        p.lo[a] = b.lo[a];
        p.hi[a] = b.hi[a];
    }
    return p;
}

Bounds grown(const Bounds& b, float pad) { return Bounds{b.lo - glm::vec3(pad), b.hi + glm::vec3(pad)}; }
Bounds intersection(const Bounds& a, const Bounds& b) { return Bounds{glm::max(a.lo, b.lo), glm::min(a.hi, b.hi)}; }

// A convex piece of a triangle. Clipping by a box leaves at most 9 corners and each later cut adds at most one;
// if rounding ever adds more, the piece is marked and bounded by the box it was clipped to instead.
struct Polygon {
    static constexpr int kCapacity = 32;
    glm::vec3 v[kCapacity];
    int n = 0;
    bool overflow = false;

    void add(const glm::vec3& p) {
        if (n < kCapacity)
            v[n++] = p;
        else
            overflow = true;
    }
};

// Sutherland–Hodgman against one plane, both sides at once; corners on the plane go to both.
void cut(const Polygon& in, int axis, float pos, Polygon& below, Polygon& above) {
    below.n = above.n = 0;
    below.overflow = above.overflow = in.overflow;
    for (int i = 0; i < in.n; ++i) {
        const glm::vec3& p = in.v[i];
        const glm::vec3& q = in.v[(i + 1) % in.n];
        if (p[axis] <= pos) below.add(p);
        if (p[axis] >= pos) above.add(p);
        if ((p[axis] < pos && q[axis] > pos) || (p[axis] > pos && q[axis] < pos)) {
            glm::vec3 x = p + (pos - p[axis]) / (q[axis] - p[axis]) * (q - p);
            x[axis] = pos;
            below.add(x);
            above.add(x);
        }
    }
}

// The triangle clipped to `box`: only the sides the triangle crosses are cut, so a whole triangle in its own
// box costs no cut at all.
void clip(const glm::vec3 corners[3], const Bounds& box, Polygon& p) {
    Polygon scratch, unused;
    p.n = 0;
    p.overflow = false;
    for (int k = 0; k < 3; ++k) p.add(corners[k]);
    for (int a = 0; a < 3 && p.n > 0; ++a) {
        float lo = INFINITY, hi = -INFINITY;
        for (int i = 0; i < p.n; ++i) {
            lo = std::min(lo, p.v[i][a]);
            hi = std::max(hi, p.v[i][a]);
        }
        if (lo < box.lo[a]) {
            cut(p, a, box.lo[a], unused, scratch);  // keep what is above lo
            p = scratch;
        }
        if (hi > box.hi[a]) {
            cut(p, a, box.hi[a], scratch, unused);  // keep what is below hi
            p = scratch;
        }
    }
}

// A part's box: its polygon's box grown by the pad, within `limit` (all of `limit` after an overflow).
Bounds partBox(const Polygon& p, const Bounds& limit, float pad) {
    if (p.overflow) return limit;
    Bounds b;
    for (int i = 0; i < p.n; ++i) b.extend(p.v[i]);
    return intersection(grown(b, pad), limit);
}

}  // namespace

// The box of the triangle's part in a slab is the box of its corners in the slab and of its edges' crossings with
// the slab's two planes (the part is convex): three corners, and for each edge one point per plane between its two
// corners' slabs (a corner on a plane counts in the slab below it and, as that edge's crossing, in the one above).
// No polygon is kept. The first and last slabs reach out to infinity, so a corner outside the planes' span still
// counts; each box is then grown by the pad and kept within the reference's box, which bounds a part of a part
// conservatively (split() clips exactly, for the references the tree keeps).
void TriangleSplitter::binParts(const BvhPrim& ref, int axis, const float* planes, int first, int last,
                                Bounds* boxes) const {
    glm::vec3 c[3];
    corners_(ref, c);
    const int slabs = std::min(last - first, 32) + 1;
    last = first + slabs - 1;
    // Points as lanes x y z (the same IEEE operations as on glm::vec3, four at a time); slab k - first, only
    // the first `slabs` set.
    F4 lo[33], hi[33];
    for (int k = 0; k < slabs; ++k) {
        lo[k] = splat4(INFINITY);
        hi[k] = splat4(-INFINITY);
    }
    auto add = [&](int k, F4 v) {
        lo[k] = min4(lo[k], v);
        hi[k] = max4(hi[k], v);
    };
    F4 v[3];
    int slabOf[3];
    for (int i = 0; i < 3; ++i) {
        v[i] = set4(c[i].x, c[i].y, c[i].z, 0.0f);
        int k = first;
        while (k < last && c[i][axis] > planes[k + 1]) ++k;
        slabOf[i] = k - first;
        add(slabOf[i], v[i]);
    }
    for (int e = 0; e < 3; ++e) {
        const int a = slabOf[e], b = slabOf[(e + 1) % 3];
        if (a == b) continue;
        const glm::vec3& p = c[e];
        const F4 d = v[(e + 1) % 3] - v[e];
        const float inv = 1.0f / (c[(e + 1) % 3][axis] - p[axis]);  // different slabs: the coordinates differ
        for (int k = std::min(a, b) + 1; k <= std::max(a, b); ++k) {
            const float pos = planes[first + k];
            const F4 x = withLane(v[e] + splat4((pos - p[axis]) * inv) * d, axis, pos);
            add(k - 1, x);
            add(k, x);
        }
    }
    const F4 pad = splat4(pad_);
    const F4 limitLo = set4(ref.lo[0], ref.lo[1], ref.lo[2], 0.0f),
             limitHi = set4(ref.hi[0], ref.hi[1], ref.hi[2], 0.0f);
    for (int k = 0; k < slabs; ++k) {
        if (!(lessEqualMask(lo[k], hi[k]) & 1)) continue;  // no point in this slab
        const F4 l = max4(lo[k] - pad, limitLo), h = min4(hi[k] + pad, limitHi);
        if ((lessEqualMask(l, h) & 7) != 7) continue;
        float bl[4], bh[4];
        store4(bl, l);
        store4(bh, h);
        boxes[first + k].extend(Bounds{{bl[0], bl[1], bl[2]}, {bh[0], bh[1], bh[2]}});
    }
}

int TriangleSplitter::split(const BvhPrim& ref, int axis, float pos, BvhPrim& below, BvhPrim& above) const {
    glm::vec3 c[3];
    corners_(ref, c);
    const Bounds limit = boxOf(ref);
    Polygon piece, lo, hi;
    clip(c, limit, piece);
    cut(piece, axis, pos, lo, hi);
    Bounds belowLimit = limit, aboveLimit = limit;
    belowLimit.hi[axis] = std::min(limit.hi[axis], pos + pad_);
    aboveLimit.lo[axis] = std::max(limit.lo[axis], pos - pad_);
    int sides = 0;
    if (lo.n > 0) {
        const Bounds b = partBox(lo, belowLimit, pad_);
        if (!b.empty()) {
            below = withBox(ref, b);
            sides |= 1;
        }
    }
    if (hi.n > 0) {
        const Bounds b = partBox(hi, aboveLimit, pad_);
        if (!b.empty()) {
            above = withBox(ref, b);
            sides |= 2;
        }
    }
    return sides;
}

}  // namespace shadelab::trace
