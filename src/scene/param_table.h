// A group of a material's scalar parameters named by one table (the principled BRDF's, a glTF layer's), and some
// of them set: what a scene file's nested object gives ("disney": {...}, "clearcoat": {...}). The scene file,
// scripts, the viewer and Python name the parameters through the same table.
#pragma once

#include <iterator>
#include <optional>

namespace shadelab {

// One parameter: its name and its member of the group `P`.
template <class P>
struct ParamField {
    const char* name;
    float P::*member;
};

// Some of the parameters of `P` named by `Fields` (an array of ParamField<P>), each replacing the same one.
template <class P, const auto& Fields>
struct ParamOverride {
    static constexpr int kCount = int(std::size(Fields));
    std::optional<float> value[kCount];

    // Every parameter of `p`, set.
    static ParamOverride all(const P& p) {
        ParamOverride o;
        for (int i = 0; i < kCount; ++i) o.value[i] = p.*Fields[i].member;
        return o;
    }
    static const auto& fields() { return Fields; }
    bool empty() const {
        for (const auto& v : value)
            if (v) return false;
        return true;
    }
    void applyTo(P& p) const {
        for (int i = 0; i < kCount; ++i)
            if (value[i]) p.*Fields[i].member = *value[i];
    }
    bool operator==(const ParamOverride& o) const {
        for (int i = 0; i < kCount; ++i)
            if (value[i] != o.value[i]) return false;
        return true;
    }
};

}  // namespace shadelab
