// Building the 8-wide BVH (design in bvh.h): binned SAH (Wald 2007, "On fast Construction of SAH-based
// Bounding Volume Hierarchies"; cost of MacDonald & Booth 1990) on 32-byte primitive references, nodes made
// by repeated binary splits of the widest child, subtrees built on worker threads and appended in order.
#include "trace/accel/bvh.h"

#include "trace/accel/bvh_binning.h"
#include "trace/accel/bvh_spatial.h"
#include "util/check.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace shadelab::trace {
namespace {

using binning::Bins;
using binning::Box4;
using binning::Grid;
using binning::kMaxBins;
using binning::primHi;
using binning::primLo;

// Below this many binary splits the builder uses SAH; deeper ranges split at the object median, which halves
// the count and so bounds the depth by kMedianDepth + log2(kMaxBvhPrimitives) = 55 < kMaxBvhDepth.
constexpr int kMedianDepth = 28;
// Inputs this small build on the calling thread in one piece (no subtree queue).
constexpr uint32_t kMinQueuedBuild = 4096;
// Ranges this large bin on several threads.
constexpr uint32_t kMinParallelBinning = 1u << 16;

// A worker thread's subtree, on huge pages like the finished tree, Bvh::nodes (aligned_allocators.h): each 2 MiB
// page is touched as the subtree grows into it, and the untouched rest of its reserve stays virtual. On 4 KiB pages
// the subtrees' first touches (about 27,000 on the 4.2 M-triangle grid) cost the build about a tenth.
using NodeArray = std::vector<BvhNode, HugePageAllocator<BvhNode>>;
using FinalNodeArray = decltype(Bvh::nodes);

struct Split {
    int axis = -1;  // -1: none found
    int bin = 0;    // SAH: primitives in bins [0, bin] go left
    bool median = false;
    bool spatial = false;  // across the plane `pos`: the references straddling it are cut in two
    float pos = 0.0f;
    float cost = INFINITY;
};

struct Range {
    uint32_t begin = 0, end = 0;
    uint32_t room = 0;      // the range owns [begin, room): past its end, room for references spatial splits make
    Box4 box, centres;      // of the primitives' boxes and of their doubled centres
    int depth = 0;          // binary splits above it
    Split split;            // set by evaluate()
    bool leaf = false;      // set by evaluate()
    bool overlaps = false;  // set by evaluate(): its object split's children overlap enough to weigh spatial ones

    uint32_t count() const { return end - begin; }
};

class Builder {
public:
    Builder(BvhPrim* prims, const BvhBuildOptions& o, int threads, const BvhReferenceSplitter* splitter)
        : prims_(prims),
          splitter_(splitter),
          options_(o),
          threads_(threads),
          bins_(std::min(std::max(o.bins, 2), kMaxBins)),
          maxLeaf_(uint32_t(std::min(std::max(o.maxLeafSize, 1), int(kMaxLeafCount)))),
          wholeLeaf_(std::min(uint32_t(std::max(o.leafTestWidth, 1)), maxLeaf_)),
          traversalCost_(o.traversalCost) {}

    // `capacity`: references the array has room for (n without spatial splits).
    Bvh build(uint32_t n, uint32_t capacity) {
        Bvh bvh;
        Range root;
        root.begin = 0;
        root.end = n;
        root.room = capacity;
        measure(root);
        root.depth = 0;
        minOverlap_ = kSpatialSplitAlpha * root.box.area();
        evaluate(root, true);
        // Subtrees below n/16 go to the workers: at least 16 of them, so a few threads stay busy, while the top
        // (which partitions on this thread alone) stays small. n/64 left a third of a 4 M-triangle build on
        // this thread; n/16 builds it 8 % faster on 2 threads (bench/README.md). A function of n alone, so the
        // nodes do not depend on the thread count.
        queueBelow_ = n >= kMinQueuedBuild ? std::max<uint32_t>(n / 16, 1024) : 0;
        // The workers start on the subtrees as the top queues them, while this thread goes on partitioning the
        // top (alone, but for the binning of the largest ranges); it joins them when the top is done.
        std::vector<std::thread> pool;
        if (queueBelow_ > 0)
            for (int t = 1; t < threads_; ++t) pool.emplace_back([this] { buildQueued(); });
        try {
            buildNode(root, bvh.nodes, true);
        } catch (...) {
            finishTop(pool);
            throw;
        }
        finishTop(pool);
        appendQueued(bvh.nodes);
        // With a splitter, buildNode puts a node's children in the order of their ranges, as packLeaves needs.
        bvh.primitives = capacity > n ? spatial::packLeaves(bvh.nodes, prims_) : n;
        bvh.depth = depth_;
        SHADELAB_CHECK_LT(bvh.depth, kMaxBvhDepth);
        for (int a = 0; a < 3; ++a) {
            bvh.bounds.lo[a] = root.box.lane(false, a);
            bvh.bounds.hi[a] = root.box.lane(true, a);
        }
        return bvh;
    }

private:
    struct Queued {
        Range range;
        uint32_t parent;  // node index in the top array
        int slot;         // child slot in it
        NodeArray nodes;  // the subtree, its root at [0], indices local
        int depth = 0;
        bool claimed = false;  // a worker has taken it (under queueMutex_)
    };

    // The box and centre bounds of a range, by scanning it.
    void measure(Range& r) const {
        Box4 box, centres;
        for (uint32_t i = r.begin; i < r.end; ++i) {
            const F4 lo = primLo(prims_[i]), hi = primHi(prims_[i]);
            box.extend(lo, hi);
            const F4 c = lo + hi;
            centres.extend(c, c);
        }
        r.box = box;
        r.centres = centres;
    }

    // Decides whether the range becomes a leaf and, if not, how it splits.
    void evaluate(Range& r, bool mayParallel) const {
        const uint32_t n = r.count();
        r.split = Split{};
        r.leaf = n <= wholeLeaf_;  // one leaf test takes them all
        if (r.leaf) return;
        if (r.depth < kMedianDepth) {
            float overlap = 0.0f;
            r.split = sahSplit(r, mayParallel && n >= kMinParallelBinning, splitter_ ? &overlap : nullptr);
            r.overlaps = r.split.axis >= 0 && overlap > minOverlap_;
            if (r.overlaps && r.room > r.end) {
                const Split spatial = spatialSplit(r, r.split.axis);
                if (spatial.cost < r.split.cost) r.split = spatial;
            }
        }
        if (n <= maxLeaf_ && !(r.split.cost < float(n))) {
            r.leaf = true;  // a leaf is cheaper than any split
            return;
        }
        if (r.split.axis < 0) {
            // No usable SAH split (all centres equal, or too deep): object median on the widest axis.
            float e[3];
            for (int a = 0; a < 3; ++a) e[a] = r.centres.lane(true, a) - r.centres.lane(false, a);
            r.split.axis = e[0] >= e[1] && e[0] >= e[2] ? 0 : (e[1] >= e[2] ? 1 : 2);
            r.split.median = true;
        }
    }

    // Fewer bins for small ranges (at least 4, at most the option): the same candidates matter less there, and
    // sweeping 32 bins for 5 primitives would dominate the build.
    int binsFor(const Range& r) const { return std::min(bins_, std::max(4, int(std::min<uint32_t>(r.count(), 64u)))); }

    Grid grid(const Range& r) const {
        Grid g;
        g.bins = binsFor(r);
        float lo[4] = {0, 0, 0, 0}, scale[4] = {0, 0, 0, 0};
        for (int a = 0; a < 3; ++a) {
            lo[a] = r.centres.lane(false, a);
            const float extent = r.centres.lane(true, a) - lo[a];
            const float s = float(g.bins) / extent;
            g.axisOk[a] = extent > 0.0f && std::isfinite(s);
            scale[a] = g.axisOk[a] ? s : 0.0f;
        }
        g.lo = loadu4(lo);
        g.scale = loadu4(scale);
        g.lastBin = splat4(float(g.bins - 1));
        for (int a = 0; a < 3; ++a) {
            g.loLane[a] = lo[a];
            g.scaleLane[a] = scale[a];
        }
        return g;
    }

    // The best object split; with `overlap`, also the area its two children's boxes share.
    Split sahSplit(const Range& r, bool parallel, float* overlap) const {
        const Grid g = grid(r);
        Split best;
        if (!g.axisOk[0] && !g.axisOk[1] && !g.axisOk[2]) return best;
        Bins bins(g.bins);
        const uint32_t n = r.count();
        if (parallel && threads_ > 1) {
            std::vector<Bins> part;
            part.reserve(size_t(threads_ - 1));
            for (int t = 1; t < threads_; ++t) part.emplace_back(g.bins);
            std::vector<std::thread> pool;
            const uint32_t chunk = (n + uint32_t(threads_) - 1) / uint32_t(threads_);
            for (int t = 1; t < threads_; ++t) {
                const uint32_t b = std::min(n, uint32_t(t) * chunk), e = std::min(n, b + chunk);
                pool.emplace_back([&, t, b, e] { binPrims(prims_ + r.begin + b, e - b, g, part[size_t(t - 1)]); });
            }
            binPrims(prims_ + r.begin, std::min(n, chunk), g, bins);
            for (std::thread& th : pool) th.join();
            for (const Bins& p : part) bins.add(p, g.bins);  // min, max and integer sums: order-independent
        } else {
            binPrims(prims_ + r.begin, n, g, bins);
        }
        const float parentArea = r.box.area();
        for (int axis = 0; axis < 3; ++axis) {
            if (!g.axisOk[axis]) continue;
            // Sweep from the right for each suffix's area and count, then from the left.
            float rightArea[kMaxBins];
            uint32_t rightCount[kMaxBins];
            Box4 acc;
            uint32_t cnt = 0;
            for (int b = g.bins - 1; b > 0; --b) {
                acc.extend(bins.lo[axis][b], bins.hi[axis][b]);
                cnt += bins.count[axis][b];
                rightArea[b] = acc.area();
                rightCount[b] = cnt;
            }
            acc = Box4();
            cnt = 0;
            for (int b = 0; b < g.bins - 1; ++b) {
                acc.extend(bins.lo[axis][b], bins.hi[axis][b]);
                cnt += bins.count[axis][b];
                if (cnt == 0 || rightCount[b + 1] == 0) continue;
                // C = Ct + (A_l·N_l + A_r·N_r) / A, in units of one primitive test.
                const float cost = traversalCost_ +
                                   (acc.area() * float(cnt) + rightArea[b + 1] * float(rightCount[b + 1])) / parentArea;
                if (cost < best.cost) best = Split{axis, b, false, false, 0.0f, cost};
            }
        }
        if (overlap && best.axis >= 0) {
            Box4 left, right;
            for (int b = 0; b < g.bins; ++b)
                (b <= best.bin ? left : right).extend(bins.lo[best.axis][b], bins.hi[best.axis][b]);
            Box4 shared;
            shared.lo = max4(left.lo, right.lo);
            shared.hi = min4(left.hi, right.hi);
            // Counted only where the overlap across the split's axis is wider than half a spatial bin. A surface
            // of small triangles split by objects gives halves that overlap by about one triangle across the
            // plane, yet by most of the surface in area: by area alone, every node of a finely tessellated
            // sphere down to about 64 triangles bins spatially, for no split (the 4.2 M-triangle grid: 28 M
            // references binned, the build 2 to 3 times the plain one). With the rule, 2CylinderEngine's tree
            // and its rays are as without it (instruction guard: coherent and packets within 0.1 %).
            const float across = shared.lane(true, best.axis) - shared.lane(false, best.axis);
            const float width = (r.box.lane(true, best.axis) - r.box.lane(false, best.axis)) / float(binsFor(r));
            *overlap = across > 0.5f * width ? shared.area() : 0.0f;
        }
        return best;
    }

    // The best spatial split of `r` across `axis` (bvh_spatial.h), in the range's room.
    Split spatialSplit(const Range& r, int axis) const {
        const spatial::Plane plane = spatial::bestPlane(prims_ + r.begin, r.count(), r.box, axis, binsFor(r),
                                                        r.room - r.end, traversalCost_, *splitter_);
        Split best;
        if (plane.bin >= 0) best = Split{axis, plane.bin, false, true, plane.pos, plane.cost};
        return best;
    }

    // Splits `r` as evaluate() decided into two measured, unevaluated ranges, which share its room.
    std::pair<Range, Range> apply(const Range& r) const {
        std::pair<Range, Range> halves;
        if (r.split.spatial) {
            Range cut = r;
            cut.end = spatial::cutStraddlers(prims_, r.begin, r.end, r.room, r.split.axis, r.split.pos, *splitter_);
            const float twice = 2.0f * r.split.pos;
            const int axis = r.split.axis;
            halves = partition(cut, [&](const BvhPrim& p) { return p.lo[axis] + p.hi[axis] < twice; });
            // Rounding can leave every part on one side (the binning saw them straddle): the median splits them.
            if (halves.first.count() == 0 || halves.second.count() == 0) halves = medianSplit(cut, axis);
        } else if (r.split.median) {
            halves = medianSplit(r, r.split.axis);
        } else {
            const Grid g = grid(r);
            const int axis = r.split.axis, bin = r.split.bin;
            halves = partition(r, [&](const BvhPrim& p) { return g.atMost(p, axis, bin); });
        }
        SHADELAB_CHECK(halves.first.count() > 0 && halves.second.count() > 0);
        // Until shareRoom: each side's room by its size, as evaluate() sees it, nothing moved yet.
        const uint32_t share = shareOf(halves.first, halves.second, r.room);
        halves.first.room = halves.first.end + share;
        halves.second.room = r.room - share;
        return halves;
    }

    // The object median across `axis` (ties by id, so the halves do not depend on the input order).
    std::pair<Range, Range> medianSplit(const Range& r, int axis) const {
        Range left, right;
        left.depth = right.depth = r.depth + 1;
        left.begin = r.begin;
        right.end = r.end;
        const uint32_t mid = r.begin + r.count() / 2;
        auto key = [axis](const BvhPrim& p) { return p.lo[axis] + p.hi[axis]; };
        std::nth_element(prims_ + r.begin, prims_ + mid, prims_ + r.end, [&](const BvhPrim& a, const BvhPrim& b) {
            return key(a) < key(b) || (key(a) == key(b) && (a.id < b.id || (a.id == b.id && a.id2 < b.id2)));
        });
        left.end = right.begin = mid;
        measure(left);
        measure(right);
        return {left, right};
    }

    // Hoare partition of `r` by `isLeft`, accumulating both sides' boxes on the way.
    template <class IsLeft>
    std::pair<Range, Range> partition(const Range& r, IsLeft&& isLeft) const {
        Range left, right;
        left.depth = right.depth = r.depth + 1;
        left.begin = r.begin;
        right.end = r.end;
        auto add = [](Range& side, const BvhPrim& p) {
            const F4 lo = primLo(p), hi = primHi(p), c = lo + hi;
            side.box.extend(lo, hi);
            side.centres.extend(c, c);
        };
        uint32_t i = r.begin, j = r.end;
        for (;;) {
            while (i < j && isLeft(prims_[i])) add(left, prims_[i++]);
            while (i < j && !isLeft(prims_[j - 1])) add(right, prims_[--j]);
            if (i >= j) break;
            std::swap(prims_[i], prims_[j - 1]);
            add(left, prims_[i++]);
            add(right, prims_[--j]);
        }
        left.end = right.begin = i;
        return {left, right};
    }

    // The left side's share of the room past the right side's end, up to `room`: by the two sides' sizes.
    static uint32_t shareOf(const Range& left, const Range& right, uint32_t room) {
        const uint32_t spare = room - right.end, nl = left.count(), nr = right.count();
        return uint32_t(uint64_t(spare) * nl / (uint64_t(nl) + nr));
    }

    // Whether a range gets room: it is not a leaf, its box is larger than the overlap spatial splits need (a
    // child's overlap is at most its box), and it or its parent weighed spatial splits. Room follows overlap down
    // the tree: the 4.2 M-triangle grid of spheres, whose large nodes' halves do not overlap enough, keeps it at
    // the end of the array and builds with spatial splits in about the plain build's time; room shared by size
    // alone reached every node of every sphere, for 1.6 times the time and no split taken. On 2CylinderEngine
    // the tree's SAH cost is within 0.5 % of sharing by size, and its rays' instructions within 0.2 %.
    bool mayCut(const Range& r, bool parentOverlaps) const {
        return !r.leaf && r.box.area() > minOverlap_ && (r.overlaps || parentOverlaps);
    }

    // Hands the room past the right side's end, up to `room`, to the two evaluated sides: by their sizes, or all
    // of it to one side if the other could not use it. The right side moves up by the left side's share
    // (spatial::shiftUp). A side that could use room gets at least what evaluate() saw.
    void shareRoom(Range& left, Range& right, uint32_t room, bool parentOverlaps) const {
        const uint32_t toLeft = !mayCut(left, parentOverlaps)    ? 0
                                : !mayCut(right, parentOverlaps) ? room - right.end
                                                                 : shareOf(left, right, room);
        left.room = left.end;
        right.room = room;
        if (toLeft == 0) return;
        spatial::shiftUp(prims_, right.begin, right.end, toLeft);
        right.begin += toLeft;
        right.end += toLeft;
        left.room += toLeft;
    }

    // Makes the node for an evaluated, non-leaf range (or, for the root, any range) and its subtree in
    // `nodes`; returns its index. `top`: subtrees below queueBelow_ primitives go to the queue instead.
    template <class Nodes>
    uint32_t buildNode(const Range& r, Nodes& nodes, bool top) {
        const uint32_t index = uint32_t(nodes.size());
        nodes.emplace_back();
        BvhNode empty;
        for (int k = 0; k < kBvhWidth; ++k) {
            for (int a = 0; a < 3; ++a) {
                empty.bounds[a][k] = INFINITY;
                empty.bounds[3 + a][k] = -INFINITY;
            }
            empty.child[k] = kLeafBit;
        }
        for (uint32_t& p : empty.pad) p = 0;
        nodes[index] = empty;

        Range kids[kBvhWidth];
        float splitArea[kBvhWidth];  // a child's area if it is to be split further, else -1
        auto setKid = [&](int k, const Range& c) {
            kids[k] = c;
            splitArea[k] = c.leaf ? -1.0f : c.box.area();
        };
        int n = 1;
        setKid(0, r);
        for (;;) {
            // Split the child of largest area that is not a leaf, until there are kBvhWidth.
            int pick = -1;
            float pickArea = -1.0f;
            for (int k = 0; k < n; ++k)
                if (splitArea[k] > pickArea) {
                    pick = k;
                    pickArea = splitArea[k];
                }
            if (pick < 0 || n == kBvhWidth) break;
            std::pair<Range, Range> halves = apply(kids[pick]);
            evaluate(halves.first, top);
            evaluate(halves.second, top);
            if (splitter_) shareRoom(halves.first, halves.second, kids[pick].room, kids[pick].overlaps);
            setKid(pick, halves.first);
            setKid(n++, halves.second);
        }
        // With spatial splits, the children in the order of their ranges, for packLeaves.
        if (splitter_) std::sort(kids, kids + n, [](const Range& a, const Range& b) { return a.begin < b.begin; });
        for (int k = 0; k < n; ++k) {
            const Range& c = kids[k];
            float lo[4], hi[4];
            store4(lo, c.box.lo);
            store4(hi, c.box.hi);
            for (int a = 0; a < 3; ++a) {
                nodes[index].bounds[a][k] = lo[a];
                nodes[index].bounds[3 + a][k] = hi[a];
            }
            uint32_t ref;
            if (c.leaf) {
                ref = makeLeafRef(c.begin, c.count());
                depth_ = std::max(depth_, c.depth);
            } else if (top && c.count() < queueBelow_) {
                {
                    const std::lock_guard<std::mutex> lock(queueMutex_);
                    queue_.push_back(std::make_unique<Queued>(Queued{c, index, k, {}, 0, false}));
                }
                ref = kLeafBit;  // set when the built subtree is appended (appendQueued)
            } else {
                ref = buildNode(c, nodes, top);
            }
            nodes[index].child[k] = ref;
        }
        return index;
    }

    // A worker: builds queued subtrees, the largest waiting one first, until the top is done and none is left.
    // Each subtree's nodes depend on its range alone, so which thread builds it, and when, changes nothing. An idle
    // worker looks again every 100 us: the top queues a subtree every few milliseconds, and a condition variable's
    // wait would need a newer libstdc++ symbol (GLIBCXX_3.4.30) than the Python wheel's manylinux level allows.
    void buildQueued() {
        for (;;) {
            Queued* q = nullptr;
            {
                const std::lock_guard<std::mutex> lock(queueMutex_);
                for (const std::unique_ptr<Queued>& c : queue_)
                    if (!c->claimed && (!q || c->range.count() > q->range.count())) q = c.get();
                if (q)
                    q->claimed = true;
                else if (topDone_)
                    return;
            }
            if (!q) {
                std::this_thread::sleep_for(std::chrono::microseconds(100));
                continue;
            }
            Builder sub(prims_, options_, threads_, splitter_);
            sub.minOverlap_ = minOverlap_;
            // Room for the usual subtree (about one node per 6 primitives, or 10 with four-triangle leaves) up
            // front: growing by doubling would copy it and leave up to half of a 256-byte-node array as resident
            // slack at the peak, when every subtree and the final array are alive at once. Untouched capacity
            // stays virtual.
            q->nodes.reserve(q->range.count() / 4 + 16);
            sub.buildNode(q->range, q->nodes, false);
            q->depth = sub.depth_;
        }
    }

    // The top is built (or failed): this thread builds what is left with the workers, and waits for them.
    void finishTop(std::vector<std::thread>& pool) {
        {
            const std::lock_guard<std::mutex> lock(queueMutex_);
            topDone_ = true;
        }
        buildQueued();
        for (std::thread& th : pool) th.join();
    }

    // Appends the built subtrees to the top's nodes in queue order (the order the top made them).
    void appendQueued(FinalNodeArray& top) {
        if (queue_.empty()) return;
        size_t total = top.size();
        for (const std::unique_ptr<Queued>& q : queue_) total += q->nodes.size();
        top.reserve(total);
#ifdef __GLIBC__
        size_t freed = 0;
#endif
        for (const std::unique_ptr<Queued>& queued : queue_) {
            Queued& q = *queued;
            const uint32_t offset = uint32_t(top.size());
            for (BvhNode node : q.nodes) {
                for (uint32_t& c : node.child)
                    if (!isLeafRef(c)) c += offset;
                top.push_back(node);
            }
            top[q.parent].child[q.slot] = offset;
            depth_ = std::max(depth_, q.depth);
#ifdef __GLIBC__
            freed += q.nodes.size() * sizeof(BvhNode);
#endif
            NodeArray().swap(q.nodes);
#ifdef __GLIBC__
            // The subtrees were allocated by the worker threads, in their own malloc arenas, which keep freed
            // pages resident: hand them back as the copy proceeds, so the final array and the subtrees not yet
            // copied never add up to twice the nodes (about 140 MiB at 4.2 M triangles).
            if (freed >= (size_t(32) << 20)) {
                malloc_trim(0);
                freed = 0;
            }
#endif
        }
        queue_.clear();
    }

    BvhPrim* prims_;
    const BvhReferenceSplitter* splitter_;  // null: objects only
    float minOverlap_ = INFINITY;           // spatial splits are weighed above this overlap (kSpatialSplitAlpha)
    BvhBuildOptions options_;               // as given: a queued subtree's builder starts from them
    int threads_;
    int bins_;
    uint32_t maxLeaf_;
    uint32_t wholeLeaf_;  // ranges this small are leaves without a split search
    float traversalCost_;
    uint32_t queueBelow_ = 0;
    int depth_ = 0;
    // Subtrees for the workers, in the order the top made them; shared with the workers under queueMutex_.
    std::mutex queueMutex_;
    std::vector<std::unique_ptr<Queued>> queue_;
    bool topDone_ = false;
};

}  // namespace

namespace {

Bvh build(BvhPrim* prims, size_t count, size_t capacity, const BvhReferenceSplitter* splitter,
          const BvhBuildOptions& options) {
    if (count == 0) return Bvh{};
    SHADELAB_CHECK_LE(count, capacity);
    SHADELAB_CHECK_LT(capacity, size_t(kMaxBvhPrimitives));
    int threads = options.threads > 0 ? options.threads : int(std::thread::hardware_concurrency());
    threads = std::max(1, std::min(threads, 64));
    if (count < kMinQueuedBuild) threads = 1;
    return Builder(prims, options, threads, splitter).build(uint32_t(count), uint32_t(capacity));
}

}  // namespace

Bvh buildBvh(BvhPrim* prims, size_t count, const BvhBuildOptions& options) {
    return build(prims, count, count, nullptr, options);
}

Bvh buildBvh(BvhPrim* prims, size_t count, size_t capacity, const BvhReferenceSplitter& splitter,
             const BvhBuildOptions& options) {
    return build(prims, count, capacity, &splitter, options);
}

Bvh buildBvh(std::vector<BvhPrim>& prims, const BvhBuildOptions& options) {
    return buildBvh(prims.data(), prims.size(), options);
}

Bvh buildBvh(const std::vector<Bounds>& boxes, const BvhBuildOptions& options) {
    std::vector<BvhPrim> prims(boxes.size());
    for (size_t i = 0; i < boxes.size(); ++i)
        prims[i] = BvhPrim{{boxes[i].lo.x, boxes[i].lo.y, boxes[i].lo.z},
                           uint32_t(i),
                           {boxes[i].hi.x, boxes[i].hi.y, boxes[i].hi.z},
                           0};
    Bvh bvh = buildBvh(prims, options);
    bvh.order.resize(prims.size());
    for (size_t k = 0; k < prims.size(); ++k) bvh.order[k] = prims[k].id;
    return bvh;
}

float sahCost(const Bvh& bvh, const BvhBuildOptions& options) {
    if (bvh.empty()) return 0.0f;
    const float rootArea = std::max(bvh.bounds.area(), 1e-30f);
    double cost = options.traversalCost;  // the root
    for (const BvhNode& nd : bvh.nodes)
        for (int k = 0; k < kBvhWidth; ++k) {
            if (!nd.used(k)) continue;
            Bounds b;
            b.lo = glm::vec3(nd.bounds[0][k], nd.bounds[1][k], nd.bounds[2][k]);
            b.hi = glm::vec3(nd.bounds[3][k], nd.bounds[4][k], nd.bounds[5][k]);
            const double p = b.area() / rootArea;
            cost += isLeafRef(nd.child[k]) ? p * leafCount(nd.child[k]) : p * options.traversalCost;
        }
    return float(cost);
}

}  // namespace shadelab::trace
