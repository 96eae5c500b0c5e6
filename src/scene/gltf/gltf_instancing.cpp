// instancedTriangles: triangles per mesh from accessor counts, then per node by memoised depth-first sums.
#include "scene/gltf/gltf_instancing.h"

#include "scene/gltf/gltf_accessors.h"

#include <limits>

namespace shadelab::gltf {
namespace {

constexpr uint64_t kSaturated = std::numeric_limits<uint64_t>::max();

uint64_t add(uint64_t a, uint64_t b) { return a > kSaturated - b ? kSaturated : a + b; }

// Triangles of one mesh: lists make count / 3, strips and fans count − 2; points and lines none.
uint64_t meshTriangles(const tinygltf::Model& model, size_t m, const std::string& file) {
    uint64_t n = 0;
    const tinygltf::Mesh& mesh = model.meshes[m];
    for (size_t i = 0; i < mesh.primitives.size(); ++i) {
        const tinygltf::Primitive& prim = mesh.primitives[i];
        const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode < TINYGLTF_MODE_TRIANGLES || mode > TINYGLTF_MODE_TRIANGLE_FAN) continue;
        const auto position = prim.attributes.find("POSITION");
        if (position == prim.attributes.end()) continue;
        const std::string where = "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(i) + "]";
        const uint64_t count = prim.indices >= 0
                                   ? accessorCount(model, prim.indices, file, where + ".indices")
                                   : accessorCount(model, position->second, file, where + ".attributes.POSITION");
        n = add(n, mode == TINYGLTF_MODE_TRIANGLES ? count / 3 : (count >= 3 ? count - 2 : 0));
    }
    return n;
}

class Counter {
public:
    Counter(const tinygltf::Model& model, const std::string& file)
        : model_(model),
          file_(file),
          state_(model.nodes.size(), 0),
          memo_(model.nodes.size(), 0),
          meshMemo_(model.meshes.size(), kSaturated) {}

    uint64_t node(int index) {
        if (index < 0 || size_t(index) >= model_.nodes.size()) return 0;  // the importer names it
        const size_t i = size_t(index);
        if (state_[i] == 2) return memo_[i];
        if (state_[i] == 1) return 0;  // a cycle: the importer refuses the file
        state_[i] = 1;
        const tinygltf::Node& n = model_.nodes[i];
        uint64_t total = 0;
        if (n.mesh >= 0 && size_t(n.mesh) < model_.meshes.size()) total = mesh(size_t(n.mesh));
        for (int child : n.children) total = add(total, node(child));
        state_[i] = 2;
        return memo_[i] = total;
    }

private:
    uint64_t mesh(size_t m) {
        if (meshMemo_[m] == kSaturated) meshMemo_[m] = meshTriangles(model_, m, file_);
        return meshMemo_[m];
    }

    const tinygltf::Model& model_;
    const std::string& file_;
    std::vector<char> state_;     // 0 unseen, 1 on the current path, 2 done
    std::vector<uint64_t> memo_;  // triangles under each node, itself included
    std::vector<uint64_t> meshMemo_;
};

}  // namespace

uint64_t instancedTriangles(const tinygltf::Model& model, const std::vector<int>& roots, const std::string& file) {
    Counter counter(model, file);
    uint64_t total = 0;
    for (int r : roots) total = add(total, counter.node(r));
    return total;
}

}  // namespace shadelab::gltf
