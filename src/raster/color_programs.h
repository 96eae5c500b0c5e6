// The rasterizer's colour-pass programs: ColorPrograms, one shader variant's set (mesh, sphere and plane, each
// plain or with its environment lookup), each compiled at its first use; and ColorProgramCache, which keeps the
// sets by their defines and picks, for each object, the set of its material's shading model (a material may
// name its own) with only the texture code of its own maps (llvmpipe executes every branch of the union's
// code, and all of it triples a mesh program's compile time).
#pragma once

#include "gl/program.h"
#include "raster/frame_block.h"
#include "raster/shader_variant.h"
#include "raster/shadow_block.h"
#include "scene/scene.h"

#include <array>
#include <cstddef>
#include <map>
#include <string>

namespace shadelab::raster {

struct ColorPrograms {
    // Environment kinds add kr ⊙ env(R) from the object's cube, and the plane mirror kr ⊙ the planar
    // reflection pass (SL_ENVIRONMENT).
    enum Kind { Mesh, Sphere, Plane, MeshEnvironment, SphereEnvironment, PlaneMirror, kKinds };
    const gl::ShaderLibrary* shaders = nullptr;
    std::string defines;
    mutable std::array<gl::Program, kKinds> built;
    // Compiles on first use; leaves no program in use (callers bind what they draw with).
    const gl::Program& get(Kind kind) const;
};

class ColorProgramCache {
public:
    static constexpr size_t kMaxSets = 32;  // a long viewer session drops them all beyond this

    explicit ColorProgramCache(const gl::ShaderLibrary& shaders) : shaders_(shaders) {}

    // The set for `variant` with the texture code of `materialMaps` (programBits: mesh.frag's SL_MATERIAL_MAPS
    // bits and the layers' bits, 0 for none). The reference stays valid until the next prepare().
    const ColorPrograms& get(const ShaderVariant& variant, int materialMaps = 0);
    // One render's sets: one per (model, map set) the scene's objects use, for of(). Drops every set first when
    // there are too many to keep, so no reference it hands out is invalidated during the render. Returns the
    // untextured set of the scene's own model; `maps`: every part's bits together.
    const ColorPrograms& prepare(const FrameBlock& frame, const ShadowBlock* shadows, const Scene& scene, int& maps);
    // The set prepare() chose for an object's material (a mesh part's: with the texture code of its maps).
    const ColorPrograms& of(const Material& m, bool meshPart = false) const;
    // The model prepare() shades `m` with (shading::SL_MODEL_*).
    int modelOf(const Material& m) const { return m.model ? modelIndex(*m.model) : sceneModel_; }
    // mesh.frag's SL_MATERIAL_MAPS bits for one material: bit k for map k (emissive 32), 16 for alpha, and
    // 128 for any of the clear coat's maps.
    static int materialMaps(const Material& m);
    // The bits a program for `m` is chosen by: a mesh part's materialMaps, and for a material shaded with pbr
    // kCoatBit for a clear coat (SL_CLEARCOAT) and kSpecularLayerBit for glTF's specular layer or an index other
    // than 1.5 (SL_SPECULAR_LAYER), kSheenBit for glTF's sheen (SL_SHEEN). Valid after prepare() has taken the
    // scene's model.
    int programBits(const Material& m, bool meshPart) const;
    static constexpr int kCoatBit = 64, kSpecularLayerBit = 256, kSheenBit = 512;

private:
    const gl::ShaderLibrary& shaders_;
    std::map<std::string, ColorPrograms> sets_;
    static constexpr int kModels = 4;      // shading::SL_MODEL_*
    static constexpr int kMapSets = 1024;  // programBits values
    // This render's sets by model × kMapSets + map bits (null: no object has them).
    std::array<const ColorPrograms*, kModels * kMapSets> chosen_{};
    int sceneModel_ = 0;
};

}  // namespace shadelab::raster
