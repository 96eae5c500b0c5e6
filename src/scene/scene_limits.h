// The largest magnitudes a scene's numbers may have. A float is finite up to 3.4e38, and the renderers
// square coordinates (|p|², r², distances²) and sum radiance times BRDF values (a sharp lobe peaks near 1e4,
// a mirror-like GGX lobe higher) over lights, samples and bounces. Within these bounds every such derived
// quantity stays finite by construction; beyond them a value from a file is refused (scene JSON) or held at
// the bound (glTF, .hdr: formats whose legal values reach further), so that no image goes black from an
// overflow (docs/scene-format.md, "Limits").
#pragma once

namespace shadelab {

inline constexpr float kMaxCoordinate = 1e15f;           // world units: positions, centres, radii, plane offsets
inline constexpr float kMaxRadiance = 1e15f;             // light colours, emission, ambient, background, an .hdr texel
inline constexpr float kMaxEnvironmentIntensity = 1e6f;  // the environment's radiance scale

}  // namespace shadelab
