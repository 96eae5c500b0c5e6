// glTF 2.0 import through tinygltf: node hierarchy → world-space MeshParts, KHR_lights_punctual lights,
// the perspective cameras, and metallic-roughness → Phong (docs/gltf-import.md). Reading the file is
// gltf_file.cpp; accessor bytes are read, bounds-checked, by gltf_accessors.cpp.
//
// Node transforms, triangulation and generated normals are gltf_geometry.cpp; materials gltf_materials.cpp;
// a node's camera and light gltf_lights_cameras.cpp.
// Sections: 1. the importer: hierarchy walk, meshes   2. public functions
#include "scene/gltf/gltf_import.h"

#include "scene/gltf/gltf_accessors.h"
#include "scene/gltf/gltf_file.h"
#include "scene/gltf/gltf_geometry.h"
#include "scene/gltf/gltf_instancing.h"
#include "scene/gltf/gltf_lights_cameras.h"
#include "scene/gltf/gltf_materials.h"
#include "scene/gltf/gltf_textures.h"
#include "scene/gltf/gltf_values.h"
#include "scene/mesh_tangents.h"
#include "scene/scene_limits.h"
#include "util/input_error.h"

#include <tiny_gltf.h>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <unordered_set>

namespace shadelab {
namespace {

constexpr int kMaxNodeDepth = 1000;                 // deeper hierarchies are rejected, not walked
constexpr size_t kMaxNodeVisits = size_t(1) << 20;  // bounds node sharing (a node under several parents)

std::string indexed(const char* array, size_t i) { return std::string(array) + "[" + std::to_string(i) + "]"; }

// ---------------------------------------------------------------------------------------------------------
// 1. The importer
// ---------------------------------------------------------------------------------------------------------

class Importer {
public:
    Importer(const gltf::LoadedModel& loaded, const std::string& file, GltfImport& out, const GltfLimits& limits,
             uint64_t trianglesBefore = 0)
        : model_(loaded.model),
          file_(file),
          out_(out),
          limits_(limits),
          trianglesBefore_(trianglesBefore),
          triangles_(trianglesBefore),
          onPath_(loaded.model.nodes.size(), 0),
          seen_(loaded.model.nodes.size(), 0),
          textures_(loaded.model, loaded.imageProblems, limits, [this](const std::string& line) { warnOnce(line); }) {
        const tinygltf::Model& model = loaded.model;
        // Deliberately not glTF's "Default Material" (a rough white metal, md = 0): a model with no
        // materials should show the lecture's diffuse and specular terms, so it gets shadelab's default.
        defaultMaterial_ = Material{};
        defaultMaterial_.derived = kPhongFields | kPbrFields;  // as an imported material's: an override derives
        // Every material map is decoded and rendered (gltf_textures.cpp).
        for (size_t i = 0; i < model.materials.size(); ++i) {
            const tinygltf::Material& gm = model.materials[i];
            const std::string place = indexed("materials", i);
            materials_.push_back(materialFrom(gm, place, out_.warnings));
            Material& m = materials_.back();
            auto bind = [&](int index, int texCoord, const tinygltf::ExtensionMap& ext, bool srgb,
                            const std::string& where) {
                const auto transform = ext.find("KHR_texture_transform");
                if (index < 0) {
                    // tinygltf writes -1 for a texture info that is absent, and also for "index": -1; the
                    // parameter maps say which (pbrMetallicRoughness's keys in values, the rest in
                    // additionalValues). A negative index given is out of range like any other.
                    const std::string key = where.substr(where.rfind('.') + 1);
                    const bool inPbr = where.rfind(".pbrMetallicRoughness.", 0) == 0;
                    if (index < -1 || (inPbr ? gm.values : gm.additionalValues).count(key) > 0)
                        warnOnce(place + where + ": texture " + std::to_string(index) + " out of range (" +
                                 std::to_string(model.textures.size()) + " textures); using the factor alone");
                    return TextureBinding{};
                }
                return textures_.binding(index, texCoord, srgb, place + where,
                                         transform == ext.end() ? nullptr : &transform->second);
            };
            const auto& pbr = gm.pbrMetallicRoughness;
            m.baseColorTexture = bind(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                                      pbr.baseColorTexture.extensions, true, ".pbrMetallicRoughness.baseColorTexture");
            m.metallicRoughnessTexture =
                bind(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord,
                     pbr.metallicRoughnessTexture.extensions, false, ".pbrMetallicRoughness.metallicRoughnessTexture");
            m.normalTexture = bind(gm.normalTexture.index, gm.normalTexture.texCoord, gm.normalTexture.extensions,
                                   false, ".normalTexture");
            m.normalTexture.strength = finiteClamp(gm.normalTexture.scale, -1e6f, 1e6f, 1.0f);
            m.occlusionTexture = bind(gm.occlusionTexture.index, gm.occlusionTexture.texCoord,
                                      gm.occlusionTexture.extensions, false, ".occlusionTexture");
            m.occlusionTexture.strength = finiteClamp(gm.occlusionTexture.strength, 0.0f, 1.0f, 1.0f);
            m.emissiveTexture = bind(gm.emissiveTexture.index, gm.emissiveTexture.texCoord,
                                     gm.emissiveTexture.extensions, true, ".emissiveTexture");
            if (auto coat = gm.extensions.find("KHR_materials_clearcoat"); coat != gm.extensions.end())
                bindClearcoatMaps(m, coat->second, place + ".extensions.KHR_materials_clearcoat");
        }
        if (!model.animations.empty()) warnOnce("animations are ignored (the static pose is imported)");
        for (const std::string& line : unshadedMaterialExtensions(model)) warnOnce(line);
        for (const std::string& ext : model.extensionsRequired) {
            if (ext == "KHR_draco_mesh_compression" || ext == "EXT_meshopt_compression")
                throw InputError(file_, "extensionsRequired", ext + " is not supported");
        }
    }

    void run(const glm::dmat4& transform) {
        std::vector<int> roots;
        if (!model_.scenes.empty()) {
            size_t scene = 0;
            if (model_.defaultScene >= 0 && size_t(model_.defaultScene) < model_.scenes.size())
                scene = size_t(model_.defaultScene);
            else if (model_.defaultScene >= 0)
                warnOnce("scene " + std::to_string(model_.defaultScene) + " out of range; using scene 0");
            roots = model_.scenes[scene].nodes;
            for (int r : roots) checkNode(r, indexed("scenes", scene) + ".nodes");
        } else {
            // No scenes: every node that is nobody's child is a root.
            std::vector<char> isChild(model_.nodes.size(), 0);
            for (size_t i = 0; i < model_.nodes.size(); ++i)
                for (int c : model_.nodes[i].children) {
                    checkNode(c, indexed("nodes", i) + ".children");
                    isChild[size_t(c)] = 1;
                }
            for (size_t i = 0; i < model_.nodes.size(); ++i)
                if (!isChild[i]) roots.push_back(int(i));
        }
        // The price tag first, from accessor counts alone: a node DAG can place millions of triangles.
        const uint64_t planned = gltf::instancedTriangles(model_, roots, file_);
        if (planned > limits_.maxTriangles - std::min(trianglesBefore_, limits_.maxTriangles))
            throw InputError(
                file_,
                "the model places " + std::to_string(planned) + " triangles once its node hierarchy is expanded" +
                    (trianglesBefore_ ? " (and the scene's other models " + std::to_string(trianglesBefore_) + ")"
                                      : std::string()) +
                    ", which exceeds the limit of " + std::to_string(limits_.maxTriangles) + " triangles" +
                    limits_.maxTrianglesWhy);
        for (int r : roots) visit(size_t(r), transform, 0);

        // KHR_lights_punctual intensities are candela (point) or lux (directional); the lighting contract has
        // no units and no falloff by default, so keep only the ratios: the brightest light gets Il = color.
        const float brightest =
            lightIntensities_.empty() ? 0.0f : *std::max_element(lightIntensities_.begin(), lightIntensities_.end());
        for (size_t i = 0; i < out_.lights.size(); ++i)
            out_.lights[i].color *= brightest > 0.0f ? lightIntensities_[i] / brightest : 0.0f;
        if (out_.parts.empty()) warnOnce("no triangles imported");
    }

private:
    void warnOnce(const std::string& line) {
        if (warned_.insert(line).second) out_.warnings.push_back(line);
    }

    // KHR_materials_clearcoat's texture infos (`coat`, the extension's object at `where`): clearcoatTexture
    // (red), clearcoatRoughnessTexture (green), clearcoatNormalTexture (with its scale); the factors are
    // materialFrom's. A texture info that is not an object, or whose index or texCoord is not a whole number,
    // is warned about and left out.
    void bindClearcoatMaps(Material& m, const tinygltf::Value& coat, const std::string& where) {
        const auto bindInfo = [&](const char* key) {
            if (!coat.IsObject() || !coat.Has(key)) return TextureBinding{};
            const tinygltf::Value& info = coat.Get(key);
            const std::string place = where + "." + key;
            const std::optional<int> index = wholeNumber(numberOr(info, "index", -1.5), 0, 1 << 30);
            const std::optional<int> texCoord = wholeNumber(numberOr(info, "texCoord", 0.0), 0, 1 << 30);
            if (!info.IsObject() || !index || !texCoord) {
                warnOnce(place + ": not a texture info with a whole index and texCoord; using the factor alone");
                return TextureBinding{};
            }
            const tinygltf::Value* transform = nullptr;
            if (info.Has("extensions") && info.Get("extensions").Has("KHR_texture_transform"))
                transform = &info.Get("extensions").Get("KHR_texture_transform");
            return textures_.binding(*index, *texCoord, false, place, transform);
        };
        m.clearcoatTexture = bindInfo("clearcoatTexture");
        m.clearcoatRoughnessTexture = bindInfo("clearcoatRoughnessTexture");
        m.clearcoatNormalTexture = bindInfo("clearcoatNormalTexture");
        if (m.clearcoatNormalTexture)
            m.clearcoatNormalTexture.strength =
                finiteClamp(numberOr(coat.Get("clearcoatNormalTexture"), "scale", 1.0), -1e6f, 1e6f, 1.0f);
    }

    void checkNode(int index, const std::string& place) const {
        if (index < 0 || size_t(index) >= model_.nodes.size())
            throw InputError(
                file_, place,
                "node " + std::to_string(index) + " out of range (" + std::to_string(model_.nodes.size()) + " nodes)");
    }

    void visit(size_t index, const glm::dmat4& parent, int depth) {
        const std::string place = indexed("nodes", index);
        if (onPath_[index]) throw InputError(file_, place, "node hierarchy has a cycle");
        if (depth > kMaxNodeDepth)
            throw InputError(file_, place, "node hierarchy is deeper than " + std::to_string(kMaxNodeDepth));
        if (++visits_ > kMaxNodeVisits)
            throw InputError(file_, place, "node hierarchy expands to too many node instances");
        if (seen_[index]) warnOnce(place + " has more than one parent; instanced under each");
        seen_[index] = onPath_[index] = 1;

        const tinygltf::Node& node = model_.nodes[index];
        const glm::dmat4 world = parent * localMatrix(node, place, file_, out_.warnings);
        if (node.skin >= 0) warnOnce("skins are ignored (meshes are placed by their node transform)");
        if (node.mesh >= 0) addMesh(node, place, world);
        const gltf::Warn warn = [this](const std::string& line) { warnOnce(line); };
        if (node.camera >= 0)
            if (std::optional<Camera> c = gltf::importCamera(model_, node, file_, place, world, warn))
                out_.cameras.push_back(*c);
        if (node.extensions.count("KHR_lights_punctual"))
            if (std::optional<gltf::ImportedLight> l = gltf::importLight(model_, node, file_, place, world, warn)) {
                lightIntensities_.push_back(l->intensity);
                out_.lights.push_back(std::move(l->light));
            }
        for (int child : node.children) {
            checkNode(child, place + ".children");
            visit(size_t(child), world, depth + 1);
        }
        onPath_[index] = 0;
    }

    void addMesh(const tinygltf::Node& node, const std::string& place, const glm::dmat4& world) {
        if (size_t(node.mesh) >= model_.meshes.size())
            throw InputError(file_, place,
                             "mesh " + std::to_string(node.mesh) + " out of range (" +
                                 std::to_string(model_.meshes.size()) + " meshes)");
        const glm::dmat3 linear(world);
        const glm::mat4 toWorld(world);
        const glm::mat3 toWorldNormal = normalMatrix(linear);
        const bool mirrored = glm::determinant(linear) < 0.0;
        const tinygltf::Mesh& mesh = model_.meshes[size_t(node.mesh)];
        for (size_t i = 0; i < mesh.primitives.size(); ++i)
            addPrimitive(mesh.primitives[i], indexed("meshes", size_t(node.mesh)) + "." + indexed("primitives", i),
                         place, toWorld, toWorldNormal, mirrored);
    }

    void addPrimitive(const tinygltf::Primitive& prim, const std::string& where, const std::string& nodePlace,
                      const glm::mat4& toWorld, const glm::mat3& toWorldNormal, bool mirrored) {
        static const char* const kModeNames[] = {"points", "lines", "line loop", "line strip"};
        const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP) {
            warnOnce(where + ": " + kModeNames[mode] + " skipped (only triangles are imported)");
            return;
        }
        if (mode > TINYGLTF_MODE_TRIANGLE_FAN) {
            warnOnce(where + ": unknown mode " + std::to_string(mode) + " skipped");
            return;
        }
        if (prim.extensions.count("KHR_draco_mesh_compression"))
            warnOnce(where + ": Draco compression is not supported; reading the uncompressed accessors");
        if (!prim.targets.empty()) warnOnce("morph targets are ignored (the base shape is imported)");
        const auto position = prim.attributes.find("POSITION");
        if (position == prim.attributes.end()) {
            warnOnce(where + ": no POSITION attribute; skipped");
            return;
        }

        MeshGeometry geo;
        const size_t vertexCount = gltf::accessorCount(model_, position->second, file_, where + ".attributes.POSITION");
        const size_t indexCount =
            prim.indices >= 0 ? gltf::accessorCount(model_, prim.indices, file_, where + ".indices") : vertexCount;
        chargeBudget(where, vertexCount, indexCount);
        gltf::readVec3(model_, position->second, file_, geo.positions);

        // Indices (or 0..n-1), each checked against the vertex count, then triangulated.
        if (prim.indices >= 0) {
            gltf::accessorCount(model_, prim.indices, file_, where + ".indices");
            gltf::readIndices(model_, prim.indices, file_, indices_);
            for (size_t k = 0; k < indices_.size(); ++k)
                if (indices_[k] >= vertexCount)
                    throw InputError(file_, indexed("accessors", size_t(prim.indices)),
                                     "index " + std::to_string(indices_[k]) + " at element " + std::to_string(k) +
                                         " is out of range (" + std::to_string(vertexCount) + " vertices)");
        } else {
            indices_.resize(vertexCount);
            for (size_t k = 0; k < vertexCount; ++k) indices_[k] = uint32_t(k);
        }
        const size_t leftover = triangulate(mode, indices_, geo.indices);
        if (leftover > 0 && mode == TINYGLTF_MODE_TRIANGLES)
            warnOnce(where + ": " + std::to_string(leftover) + " trailing indices form no triangle; dropped");
        if (geo.indices.empty()) {
            warnOnce(where + ": no complete triangle; skipped");
            return;
        }

        // Positions: non-finite input is an error (docs/gltf-import.md), as is overflow to infinity.
        for (glm::vec3& p : geo.positions) {
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                throw InputError(file_, indexed("accessors", size_t(position->second)), "non-finite value");
            p = glm::vec3(toWorld * glm::vec4(p, 1.0f));
            // NaN fails the comparison too: one test for infinity, overflow and the coordinate bound.
            if (!(std::fabs(p.x) <= kMaxCoordinate && std::fabs(p.y) <= kMaxCoordinate &&
                  std::fabs(p.z) <= kMaxCoordinate))
                throw InputError(file_, nodePlace,
                                 "transform sends a vertex beyond the largest coordinate (1e15) or to infinity");
        }
        // A mirroring transform turns counter-clockwise triangles clockwise; swap two corners to undo it.
        if (mirrored)
            for (size_t t = 0; t + 2 < geo.indices.size(); t += 3) std::swap(geo.indices[t + 1], geo.indices[t + 2]);

        // Normals: given ones go through the normal matrix; missing, zero or non-finite ones are generated.
        size_t bad = vertexCount;
        const auto normal = prim.attributes.find("NORMAL");
        if (normal != prim.attributes.end()) {
            const size_t count = gltf::accessorCount(model_, normal->second, file_, where + ".attributes.NORMAL");
            if (count != vertexCount)
                throw InputError(file_, indexed("accessors", size_t(normal->second)),
                                 "NORMAL count " + std::to_string(count) + " differs from POSITION count " +
                                     std::to_string(vertexCount));
            gltf::readVec3(model_, normal->second, file_, geo.normals);
            bad = 0;
            for (glm::vec3& n : geo.normals) {
                n = toWorldNormal * n;
                const float len2 = glm::dot(n, n);
                if (len2 > 1e-30f && std::isfinite(len2)) {
                    n /= std::sqrt(len2);
                } else {
                    n = glm::vec3(0.0f);  // marks it for replacement below
                    ++bad;
                }
            }
        }
        if (bad > 0) {
            generateNormals(geo, generated_);
            if (geo.normals.empty()) {
                geo.normals = generated_;
            } else {
                warnOnce(where + ": " + std::to_string(bad) + " zero or non-finite normals replaced by generated ones");
                for (size_t i = 0; i < vertexCount; ++i)
                    if (geo.normals[i] == glm::vec3(0.0f)) geo.normals[i] = generated_[i];
            }
        }

        readTexcoords(prim, "TEXCOORD_0", where, vertexCount, geo.texcoords0);
        readTexcoords(prim, "TEXCOORD_1", where, vertexCount, geo.texcoords1);
        readTangents(prim, where, vertexCount, toWorld, mirrored, geo);

        if (prim.material >= 0 && size_t(prim.material) >= materials_.size())
            throw InputError(file_, where + ".material",
                             "material " + std::to_string(prim.material) + " out of range (" +
                                 std::to_string(materials_.size()) + " materials)");
        MeshPart part;
        part.material = prim.material >= 0 ? materials_[size_t(prim.material)] : defaultMaterial_;
        // A normal map (the base's, or the clear coat's) needs tangents, and so does anisotropy (its direction turns
        // from the tangent): the file's, or generated from the map's coordinate set, TEXCOORD_0 for anisotropy
        // (mesh_tangents.h).
        const TextureBinding& nt =
            part.material.normalTexture ? part.material.normalTexture : part.material.clearcoatNormalTexture;
        if ((nt || part.material.anisotropy.on()) && geo.tangents.empty()) {
            const std::vector<glm::vec2>& uvs = nt && nt.texCoord == 1 ? geo.texcoords1 : geo.texcoords0;
            if (uvs.size() == geo.positions.size())
                geo.tangents = generateTangents(geo.positions, geo.normals, uvs, geo.indices);
        }
        part.geometry = shareGeometry(std::move(geo));
        out_.parts.push_back(std::move(part));
    }

    // TEXCOORD_n: the count must match; a non-finite coordinate becomes 0 with a warning.
    void readTexcoords(const tinygltf::Primitive& prim, const std::string& name, const std::string& where,
                       size_t vertexCount, std::vector<glm::vec2>& out) {
        const auto uv = prim.attributes.find(name);
        if (uv == prim.attributes.end()) return;
        const size_t count = gltf::accessorCount(model_, uv->second, file_, where + ".attributes." + name);
        if (count != vertexCount)
            throw InputError(file_, indexed("accessors", size_t(uv->second)),
                             name + " count " + std::to_string(count) + " differs from POSITION count " +
                                 std::to_string(vertexCount));
        gltf::readVec2(model_, uv->second, file_, out);
        size_t nonFinite = 0;
        for (glm::vec2& t : out)
            if (!std::isfinite(t.x) || !std::isfinite(t.y)) t = glm::vec2(0.0f), ++nonFinite;
        if (nonFinite > 0)
            warnOnce(where + ": " + std::to_string(nonFinite) + " non-finite texture coordinates set to 0");
    }

    // TANGENT: xyz goes through the node's linear part (a tangent lies in the surface, so not the normal
    // matrix), w flips under a mirroring transform; all are dropped (and generated if a normal map needs
    // them) when one is zero or non-finite, or w is not ±1.
    void readTangents(const tinygltf::Primitive& prim, const std::string& where, size_t vertexCount,
                      const glm::mat4& toWorld, bool mirrored, MeshGeometry& geo) {
        const auto tangent = prim.attributes.find("TANGENT");
        if (tangent == prim.attributes.end()) return;
        const size_t count = gltf::accessorCount(model_, tangent->second, file_, where + ".attributes.TANGENT");
        if (count != vertexCount)
            throw InputError(file_, indexed("accessors", size_t(tangent->second)),
                             "TANGENT count " + std::to_string(count) + " differs from POSITION count " +
                                 std::to_string(vertexCount));
        gltf::readVec4(model_, tangent->second, file_, geo.tangents);
        const glm::mat3 linear(toWorld);
        for (glm::vec4& t : geo.tangents) {
            const glm::vec3 v = linear * glm::vec3(t);
            const float len2 = glm::dot(v, v);
            if (!(len2 > 1e-30f) || !std::isfinite(len2) || !(std::fabs(std::fabs(t.w) - 1.0f) < 1e-3f)) {
                warnOnce(where + ": zero, non-finite or unsigned tangents; generated ones used instead");
                geo.tangents.clear();
                return;
            }
            t = glm::vec4(v / std::sqrt(len2), (t.w < 0.0f) != mirrored ? -1.0f : 1.0f);
        }
    }

    // Counts a primitive instance against the limits before its arrays are allocated. A mesh used by many
    // nodes counts once per use, as it is expanded once per use.
    void chargeBudget(const std::string& where, size_t vertexCount, size_t indexCount) {
        triangles_ += indexCount / 3 + (indexCount >= 3 ? 2 : 0);  // strips and fans make up to count - 2
        bytes_ += uint64_t(vertexCount) * (2 * sizeof(glm::vec3) + sizeof(glm::vec2)) +
                  uint64_t(indexCount) * 3 * sizeof(uint32_t);
        if (triangles_ > limits_.maxTriangles)
            throw InputError(file_, where,
                             "the model exceeds the limit of " + std::to_string(limits_.maxTriangles) + " triangles" +
                                 limits_.maxTrianglesWhy);
        if (bytes_ > limits_.maxMeshBytes)
            throw InputError(file_, where,
                             "the model needs more than the limit of " + std::to_string(limits_.maxMeshBytes) +
                                 " bytes of geometry");
    }

    const tinygltf::Model& model_;
    const std::string& file_;
    GltfImport& out_;
    std::vector<Material> materials_;
    Material defaultMaterial_;
    const GltfLimits& limits_;
    uint64_t trianglesBefore_ = 0;
    uint64_t triangles_ = 0, bytes_ = 0;
    std::vector<char> onPath_;  // nodes on the path from the root being walked
    std::vector<char> seen_;    // nodes visited at least once
    size_t visits_ = 0;
    std::vector<float> lightIntensities_;  // raw glTF intensity of each out_.lights entry
    std::unordered_set<std::string> warned_;
    std::vector<uint32_t> indices_;     // scratch, reused across primitives
    std::vector<glm::vec3> generated_;  // scratch, reused across primitives
    gltf::TextureLoader textures_;      // decodes each image once, on a material's first use
};

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// 2. Public functions
// ---------------------------------------------------------------------------------------------------------

GltfImport importGltf(const std::string& path, const glm::mat4& transform, const GltfImportOptions& options) {
    GltfImport out;
    const gltf::LoadedModel model = gltf::loadModel(path, options, out.warnings);
    Importer(model, path, out, options.limits, options.trianglesBefore).run(glm::dmat4(transform));
    return out;
}

GltfImport importGltfBytes(const std::string& bytes, bool binary, const std::string& name, const GltfLimits& limits) {
    GltfImport out;
    checkDeclaredSizes(bytes, binary, name, limits);
    const gltf::LoadedModel model = gltf::parseModel(bytes, binary, name, "", out.warnings);
    Importer(model, name, out, limits).run(glm::dmat4(1.0));
    return out;
}

}  // namespace shadelab
