// ShaderVariant: the compile-time specialisation of the colour passes. llvmpipe runs every side of a
// branch, uniform or not, so a program that decides per fragment between Phong and Blinn-Phong, between
// ortho, perspective and cube shadow maps, and whether a plane can block a light, pays for all of them.
// The colour programs are therefore compiled per variant: the model, the term switches, the first
// kMaxShadowedLights lights' types and shadow techniques, and the planes that can block each of them are
// #defines. A scene edit that changes one of these compiles a new variant once (RasterRenderer caches
// them); material, colour, position and camera edits do not. Lights past kMaxShadowedLights are shaded by
// a generic loop, unshadowed, as before.
#pragma once

#include "raster/raster_limits.h"

#include <array>
#include <string>

namespace shadelab::raster {

struct FrameBlock;
struct ShadowBlock;

struct ShaderVariant {
    bool shadows = false;  // SL_SHADOWS: the shadow lookups exist at all
    int model = 0;         // shading::SL_MODEL_*
    int terms = 0;         // TermBits
    int lights = 0;        // specialised lights: min(light count, kMaxShadowedLights)
    bool moreLights = false;
    std::array<bool, kMaxShadowedLights> point{};       // point or spot light (else directional)
    std::array<bool, kMaxShadowedLights> attenuated{};  // attenuation not (1, 0, 0), a range or a spot's cone
    std::array<int, kMaxShadowedLights> shadowKind{};   // ShadowKind of each light's map
    std::array<int, kMaxShadowedLights> planeMask{};    // planes (bits) that can block each light
    std::array<int, kMaxShadowedLights> firstLayer{};   // its first shadow-map layer
    int planes = 0;                                     // planes uploaded to the Shadows block
    bool pcf = false;
    int ibl = 0;                      // SL_IBL: IblMode lighting pbr surfaces (0 unless pbr with ambient on)
    bool energyCompensation = false;  // SL_ENERGY_COMPENSATION: pbr lobes scaled by energyCompensation()

    // The #define prelude that selects this variant in shaders/surface.glsl and shadow.glsl; also the
    // variant's cache key.
    std::string defines() const;
};

// The text RasterRenderer puts after the prelude of one colour program: `variantDefines`, then mesh.frag's
// SL_MATERIAL_MAPS (`materialMaps` bits but 64, 256 and 512, none for 0), SL_CLEARCOAT (bit 64), SL_SPECULAR_LAYER
// (bit 256) and SL_SHEEN (bit 512), then, for the environment and
// plane-mirror programs, SL_ENVIRONMENT 1. Tests compile exactly these.
std::string colorProgramDefines(const std::string& variantDefines, int materialMaps, bool environment);

// The variant for one draw. `shadows` is null when the frame has no shadow pass. `model` (shading::SL_MODEL_*)
// is the objects' model when a material names its own; -1: the frame's (the scene's).
ShaderVariant makeShaderVariant(const FrameBlock& frame, const ShadowBlock* shadows, int model = -1);

}  // namespace shadelab::raster
