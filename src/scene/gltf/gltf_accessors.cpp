// Bounds-checked glTF accessor reading (glTF 2.0 spec, "Binary Data Storage"). Every byte read is first
// proven to lie inside its buffer view and buffer, so a broken file gives an InputError, never a crash.
#include "scene/gltf/gltf_accessors.h"

#include "util/input_error.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>

namespace shadelab::gltf {
namespace {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "readVec3 copies packed floats into glm::vec3");

// Accessors with no bufferView are all zeros; this caps what a tiny malicious file can make us allocate.
constexpr size_t kMaxZeroCount = size_t(1) << 28;

std::string accessorPlace(int index) { return "accessors[" + std::to_string(index) + "]"; }

const char* typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        case TINYGLTF_TYPE_MAT2: return "MAT2";
        case TINYGLTF_TYPE_MAT3: return "MAT3";
        case TINYGLTF_TYPE_MAT4: return "MAT4";
        default: return "an unknown type";
    }
}

const char* componentName(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_INT: return "INT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
        case TINYGLTF_COMPONENT_TYPE_DOUBLE: return "DOUBLE";
        default: return "an unknown component type";
    }
}

// Size of an index component, or 0 when the type is not allowed for indices.
size_t indexSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return 4;
        default: return 0;
    }
}

// Size of a VEC3 component: FLOAT, or the integer types KHR_mesh_quantization allows; 0 otherwise.
size_t vec3ComponentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

uint32_t loadIndex(const unsigned char* p, int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t v;
            std::memcpy(&v, p, sizeof v);
            return v;
        }
        default: {
            uint32_t v;
            std::memcpy(&v, p, sizeof v);
            return v;
        }
    }
}

// glTF 2.0 spec, "Animations" (and KHR_mesh_quantization): normalized integers decode as c / (2^n - 1),
// or max(c / (2^(n-1) - 1), -1) when signed.
float loadComponent(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            int8_t v;
            std::memcpy(&v, p, sizeof v);
            return normalized ? std::max(float(v) / 127.0f, -1.0f) : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? float(*p) / 255.0f : float(*p);
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t v;
            std::memcpy(&v, p, sizeof v);
            return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t v;
            std::memcpy(&v, p, sizeof v);
            return normalized ? float(v) / 65535.0f : float(v);
        }
        default: {
            float v;
            std::memcpy(&v, p, sizeof v);
            return v;
        }
    }
}

// A strided run of elements proven to lie inside one buffer.
struct Span {
    const unsigned char* data = nullptr;
    size_t stride = 0;
    const unsigned char* at(size_t i) const { return data + i * stride; }
};

// Checks that `count` elements of `elementSize` bytes, starting `byteOffset` bytes into buffer view
// `viewIndex` and `stride` apart (the view's byteStride when `strided`, else packed), lie inside the view,
// and the view inside its buffer. `where` names the accessor (or its sparse part) in errors.
Span resolve(const tinygltf::Model& model, int viewIndex, size_t byteOffset, size_t count, size_t elementSize,
             bool strided, const std::string& file, const std::string& where) {
    if (viewIndex < 0 || size_t(viewIndex) >= model.bufferViews.size())
        throw InputError(file, where,
                         "bufferView " + std::to_string(viewIndex) + " out of range (" +
                             std::to_string(model.bufferViews.size()) + " buffer views)");
    const tinygltf::BufferView& view = model.bufferViews[size_t(viewIndex)];
    const std::string viewPlace = "bufferViews[" + std::to_string(viewIndex) + "]";
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
        throw InputError(file, viewPlace,
                         "buffer " + std::to_string(view.buffer) + " out of range (" +
                             std::to_string(model.buffers.size()) + " buffers)");
    const std::vector<unsigned char>& bytes = model.buffers[size_t(view.buffer)].data;
    if (view.byteOffset > bytes.size() || view.byteLength > bytes.size() - view.byteOffset)
        throw InputError(file, viewPlace,
                         "bytes " + std::to_string(view.byteOffset) + ".." +
                             std::to_string(view.byteOffset + view.byteLength) + " lie outside buffers[" +
                             std::to_string(view.buffer) + "] (" + std::to_string(bytes.size()) + " bytes)");
    const size_t stride = strided && view.byteStride != 0 ? view.byteStride : elementSize;
    if (stride < elementSize)
        throw InputError(file, where,
                         "byteStride " + std::to_string(stride) + " of " + viewPlace +
                             " is smaller than the element size " + std::to_string(elementSize));
    // Written to avoid overflow: (count - 1) * stride + elementSize <= byteLength - byteOffset.
    const size_t length = view.byteLength;
    const bool fits = count == 0 || (byteOffset <= length && elementSize <= length - byteOffset &&
                                     count - 1 <= (length - byteOffset - elementSize) / stride);
    if (!fits)
        throw InputError(file, where,
                         std::to_string(count) + " elements of " + std::to_string(elementSize) + " bytes (stride " +
                             std::to_string(stride) + ") from byte " + std::to_string(byteOffset) + " do not fit in " +
                             viewPlace + " (" + std::to_string(length) + " bytes)");
    return {bytes.data() + view.byteOffset + byteOffset, stride};
}

const tinygltf::Accessor& accessorAt(const tinygltf::Model& model, int index, const std::string& file) {
    if (index < 0 || size_t(index) >= model.accessors.size())
        throw InputError(file, accessorPlace(index),
                         "no such accessor (" + std::to_string(model.accessors.size()) + " accessors)");
    return model.accessors[size_t(index)];
}

// glTF 2.0 spec, "Sparse Accessors": replaces the elements listed in `sparse.indices` with packed
// values; `store(target, bytes)` writes one element.
template <class Store>
void applySparse(const tinygltf::Model& model, const tinygltf::Accessor& acc, int index, size_t elementSize,
                 const std::string& file, Store store) {
    const std::string where = accessorPlace(index) + ".sparse";
    const auto& sparse = acc.sparse;
    if (sparse.count < 0 || size_t(sparse.count) > acc.count)
        throw InputError(
            file, where,
            "count " + std::to_string(sparse.count) + " exceeds the accessor's count " + std::to_string(acc.count));
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
        throw InputError(file, where, "negative byteOffset");
    const int indexType = sparse.indices.componentType;
    const size_t indexBytes = indexSize(indexType);
    if (indexBytes == 0)
        throw InputError(file, where + ".indices",
                         std::string("componentType must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, got ") +
                             componentName(indexType));
    const size_t n = size_t(sparse.count);
    const Span indices = resolve(model, sparse.indices.bufferView, size_t(sparse.indices.byteOffset), n, indexBytes,
                                 false, file, where + ".indices");
    const Span values = resolve(model, sparse.values.bufferView, size_t(sparse.values.byteOffset), n, elementSize,
                                false, file, where + ".values");
    for (size_t k = 0; k < n; ++k) {
        const uint32_t target = loadIndex(indices.at(k), indexType);
        if (target >= acc.count)
            throw InputError(
                file, where + ".indices",
                "index " + std::to_string(target) + " out of range (count " + std::to_string(acc.count) + ")");
        store(target, values.at(k));
    }
}

void checkZeroCount(const tinygltf::Accessor& acc, int index, const std::string& file) {
    if (acc.count > kMaxZeroCount)
        throw InputError(file, accessorPlace(index),
                         "count " + std::to_string(acc.count) + " is too large for an accessor without a bufferView");
}

// Reads every element of a vector accessor with `load(bytes, element)`: from its bufferView, or zeros when
// it has none, then its sparse substitutions. The one walk readVec3 and readVec2 share.
template <class T, class Load>
void readElements(const tinygltf::Model& model, const tinygltf::Accessor& acc, int index, size_t elementSize,
                  const std::string& file, const Load& load, std::vector<T>& out) {
    if (acc.bufferView >= 0) {
        const Span span =
            resolve(model, acc.bufferView, acc.byteOffset, acc.count, elementSize, true, file, accessorPlace(index));
        out.resize(acc.count);
        for (size_t i = 0; i < acc.count; ++i) load(span.at(i), out[i]);
    } else {
        checkZeroCount(acc, index, file);
        out.assign(acc.count, T(0.0f));
    }
    if (acc.sparse.isSparse)
        applySparse(model, acc, index, elementSize, file,
                    [&](uint32_t target, const unsigned char* p) { load(p, out[target]); });
}

}  // namespace

size_t accessorCount(const tinygltf::Model& model, int index, const std::string& file, const std::string& what) {
    if (index < 0 || size_t(index) >= model.accessors.size())
        throw InputError(file, what,
                         "accessor " + std::to_string(index) + " out of range (" +
                             std::to_string(model.accessors.size()) + " accessors)");
    return model.accessors[size_t(index)].count;
}

void readVec3(const tinygltf::Model& model, int index, const std::string& file, std::vector<glm::vec3>& out) {
    const tinygltf::Accessor& acc = accessorAt(model, index, file);
    if (acc.type != TINYGLTF_TYPE_VEC3)
        throw InputError(file, accessorPlace(index), std::string("expected VEC3, got ") + typeName(acc.type));
    const int type = acc.componentType;
    const size_t componentSize = vec3ComponentSize(type);
    if (componentSize == 0)
        throw InputError(file, accessorPlace(index),
                         std::string("expected FLOAT components (or BYTE/SHORT under KHR_mesh_quantization), got ") +
                             componentName(type));
    const size_t elementSize = 3 * componentSize;
    const bool normalized = acc.normalized;
    auto load = [&](const unsigned char* p, glm::vec3& v) {
        if (type == TINYGLTF_COMPONENT_TYPE_FLOAT) {
            std::memcpy(&v, p, sizeof v);
        } else {
            v = glm::vec3(loadComponent(p, type, normalized), loadComponent(p + componentSize, type, normalized),
                          loadComponent(p + 2 * componentSize, type, normalized));
        }
    };
    readElements(model, acc, index, elementSize, file, load, out);
}

void readVec2(const tinygltf::Model& model, int index, const std::string& file, std::vector<glm::vec2>& out) {
    const tinygltf::Accessor& acc = accessorAt(model, index, file);
    if (acc.type != TINYGLTF_TYPE_VEC2)
        throw InputError(file, accessorPlace(index), std::string("expected VEC2, got ") + typeName(acc.type));
    const int type = acc.componentType;
    const bool floats = type == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const bool normalizedInts = acc.normalized && (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                   type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    if (!floats && !normalizedInts)
        throw InputError(file, accessorPlace(index),
                         std::string("texture coordinates must be FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT, "
                                     "got ") +
                             componentName(type));
    const size_t componentSize = floats ? 4 : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ? 1 : 2;
    const size_t elementSize = 2 * componentSize;
    auto load = [&](const unsigned char* p, glm::vec2& v) {
        v = glm::vec2(loadComponent(p, type, true), loadComponent(p + componentSize, type, true));
    };
    readElements(model, acc, index, elementSize, file, load, out);
}

void readVec4(const tinygltf::Model& model, int index, const std::string& file, std::vector<glm::vec4>& out) {
    const tinygltf::Accessor& acc = accessorAt(model, index, file);
    if (acc.type != TINYGLTF_TYPE_VEC4)
        throw InputError(file, accessorPlace(index), std::string("expected VEC4, got ") + typeName(acc.type));
    const int type = acc.componentType;
    const size_t componentSize = vec3ComponentSize(type);
    if (componentSize == 0)
        throw InputError(file, accessorPlace(index),
                         std::string("expected FLOAT components (or BYTE/SHORT under KHR_mesh_quantization), got ") +
                             componentName(type));
    const bool normalized = acc.normalized;
    auto load = [&](const unsigned char* p, glm::vec4& v) {
        if (type == TINYGLTF_COMPONENT_TYPE_FLOAT) {
            std::memcpy(&v, p, sizeof v);
        } else {
            v = glm::vec4(loadComponent(p, type, normalized), loadComponent(p + componentSize, type, normalized),
                          loadComponent(p + 2 * componentSize, type, normalized),
                          loadComponent(p + 3 * componentSize, type, normalized));
        }
    };
    readElements(model, acc, index, 4 * componentSize, file, load, out);
}

std::string bufferViewBytes(const tinygltf::Model& model, int view, const std::string& file, const std::string& where) {
    if (view < 0 || size_t(view) >= model.bufferViews.size())
        throw InputError(file, where,
                         "bufferView " + std::to_string(view) + " out of range (" +
                             std::to_string(model.bufferViews.size()) + " buffer views)");
    const size_t length = model.bufferViews[size_t(view)].byteLength;
    const Span span = resolve(model, view, 0, length ? 1 : 0, length, false, file, where);  // 0: no stride
    return std::string(reinterpret_cast<const char*>(span.data), length);
}

void readIndices(const tinygltf::Model& model, int index, const std::string& file, std::vector<uint32_t>& out) {
    const tinygltf::Accessor& acc = accessorAt(model, index, file);
    if (acc.type != TINYGLTF_TYPE_SCALAR)
        throw InputError(file, accessorPlace(index), std::string("indices must be SCALAR, got ") + typeName(acc.type));
    const int type = acc.componentType;
    const size_t size = indexSize(type);
    if (size == 0)
        throw InputError(
            file, accessorPlace(index),
            std::string("indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, got ") + componentName(type));

    if (acc.bufferView >= 0) {
        const Span span =
            resolve(model, acc.bufferView, acc.byteOffset, acc.count, size, true, file, accessorPlace(index));
        out.resize(acc.count);
        if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT && span.stride == 4) {
            if (acc.count > 0) std::memcpy(out.data(), span.data, acc.count * 4);
        } else {
            for (size_t i = 0; i < acc.count; ++i) out[i] = loadIndex(span.at(i), type);
        }
    } else {
        checkZeroCount(acc, index, file);
        out.assign(acc.count, 0u);
    }
    if (acc.sparse.isSparse)
        applySparse(model, acc, index, size, file,
                    [&](uint32_t target, const unsigned char* p) { out[target] = loadIndex(p, type); });
}

}  // namespace shadelab::gltf
