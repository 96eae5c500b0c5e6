// ColorPrograms and ColorProgramCache: compiling and keeping the colour passes' programs.
#include "raster/color_programs.h"

#include "util/check.h"

#include <optional>

namespace shadelab::raster {

const gl::Program& ColorPrograms::get(Kind kind) const {
    gl::Program& p = built[size_t(kind)];
    if (p) return p;
    const bool environment = kind == MeshEnvironment || kind == SphereEnvironment || kind == PlaneMirror;
    const std::string text = colorProgramDefines(defines, 0, environment);
    const char* stem = kind == Mesh || kind == MeshEnvironment       ? "mesh"
                       : kind == Sphere || kind == SphereEnvironment ? "sphere"
                                                                     : "plane";
    p = gl::Program::build(*shaders, std::string(stem) + ".vert", std::string(stem) + ".frag", text);
    p.bindBlock("Frame", kFrameBinding);
    p.bindBlock("Shadows", kShadowBinding);
    glUseProgram(p.id());
    p.setSampler("t_shadowMaps", kShadowUnit);
    p.setSampler("t_iblCube", kIblCubeUnit);
    p.setSampler("t_iblDfg", kIblDfgUnit);
    p.setSampler("t_baseColor", kBaseColorUnit);
    p.setSampler("t_metalRough", kMetalRoughUnit);
    p.setSampler("t_normal", kNormalMapUnit);
    p.setSampler("t_occlusion", kOcclusionUnit);
    p.setSampler("t_emissive", kEmissiveUnit);
    p.setSampler("t_clearcoat", kClearcoatUnit);
    p.setSampler("t_clearcoatRoughness", kClearcoatRoughnessUnit);
    p.setSampler("t_clearcoatNormal", kClearcoatNormalUnit);
    p.setSampler("t_sheenE", kSheenLutUnit);
    if (kind == PlaneMirror) p.setSampler("t_reflection", kReflectionUnit);
    if (kind == MeshEnvironment || kind == SphereEnvironment) p.setSampler("t_environment", kEnvironmentUnit);
    glUseProgram(0);
    return p;
}

int ColorProgramCache::materialMaps(const Material& m) {
    const bool coatMaps = m.clearcoatTexture || m.clearcoatRoughnessTexture || m.clearcoatNormalTexture;
    return (m.baseColorTexture ? 1 : 0) | (m.metallicRoughnessTexture ? 2 : 0) | (m.normalTexture ? 4 : 0) |
           (m.occlusionTexture ? 8 : 0) | (m.alphaMode != AlphaMode::Opaque ? 16 : 0) | (m.emissiveTexture ? 32 : 0) |
           (coatMaps ? 128 : 0);
}

int ColorProgramCache::programBits(const Material& m, bool meshPart) const {
    const bool pbr = modelOf(m) == modelIndex(ShadingModel::Pbr);  // glTF's layers shade pbr alone
    return (meshPart ? materialMaps(m) : 0) | (pbr && m.clearcoat.factor > 0.0f ? kCoatBit : 0) |
           (pbr && usesLayeredPbr(m) ? kSpecularLayerBit : 0) | (pbr && m.sheen.on() ? kSheenBit : 0);
}

const ColorPrograms& ColorProgramCache::get(const ShaderVariant& variant, int materialMaps) {
    // mesh.frag's texture code only where a part needs it (SL_MATERIAL_MAPS).
    const std::string defines = colorProgramDefines(variant.defines(), materialMaps, false);
    if (auto it = sets_.find(defines); it != sets_.end()) return it->second;
    ColorPrograms set;
    set.shaders = &shaders_;
    set.defines = defines;
    return sets_.emplace(defines, std::move(set)).first->second;
}

const ColorPrograms& ColorProgramCache::prepare(const FrameBlock& frame, const ShadowBlock* shadows, const Scene& scene,
                                                int& maps) {
    if (sets_.size() >= kMaxSets) sets_.clear();
    sceneModel_ = frame.flags.x;
    chosen_.fill(nullptr);
    std::array<std::optional<ShaderVariant>, kModels> variants;  // each model's, made when an object has it
    const auto choose = [&](const Material& m, int bits) {
        const int model = modelOf(m);
        SHADELAB_CHECK(model >= 0 && model < kModels);  // a new ShadingModel widens kModels
        const ColorPrograms*& set = chosen_[size_t(model * kMapSets + bits)];
        if (set) return;
        std::optional<ShaderVariant>& v = variants[size_t(model)];
        if (!v) v = makeShaderVariant(frame, shadows, model);
        set = &get(*v, bits);
    };
    const Material sceneMaterial;  // no model of its own: the scene's
    choose(sceneMaterial, 0);
    maps = 0;
    for (const Sphere& s : scene.spheres) choose(s.material, programBits(s.material, false));
    for (const Plane& p : scene.planes) choose(p.material, programBits(p.material, false));
    for (const Mesh& m : scene.meshes)
        for (const MeshPart& p : m.parts) {
            const int bits = programBits(p.material, true);
            maps |= bits;
            choose(p.material, bits);
        }
    return *chosen_[size_t(sceneModel_ * kMapSets)];
}

const ColorPrograms& ColorProgramCache::of(const Material& m, bool meshPart) const {
    const ColorPrograms* set = chosen_[size_t(modelOf(m) * kMapSets + programBits(m, meshPart))];
    SHADELAB_CHECK(set != nullptr);  // prepare() saw this render's objects, and this one among them
    return *set;
}

}  // namespace shadelab::raster
