// setPbrLayers: the layers' parameters from a material and its textured surface point.
#include "trace/pbr_layers.h"

#include "shading/sheen_lut.h"

namespace shadelab::trace {

void setPbrLayers(shading::SurfaceParams& p, const Surface& s, const glm::vec3& V) {
    const Material& m = *s.material;
    if (s.coat.x > 0.0f) {  // the coat's factor and roughness times its maps' texels (SurfaceSetup::at)
        p.coat = s.coat;
        p.coatN = s.coatN;
    }
    if (usesLayeredPbr(m)) {
        // shadeLightPbrSpecular reads the base colour and metallic here (textured, the checker's, a texel's); its
        // F0 for the environment and the energy compensation is pbrSpecularF0's.
        p.layered = true;
        p.specLayer = m.specular.packed(m.ior);
        p.aniso = glm::vec4(shading::anisotropyDirection(s.N, s.tangent, m.anisotropy.packed()), m.anisotropy.strength);
        p.baseColor = s.baseColor;
        p.metallic = s.metallic;
        p.ms = shading::pbrSpecularF0(s.baseColor, s.metallic, p.specLayer);
    }
    if (m.transmission.on()) {  // the diffuse colour split between the diffuse lobe and the transmitted one
        p.transmission = transmissionPacked(m);
        p.transmitColor = p.md * m.transmission.factor;
        p.transmitTint = transmissionTint(m);
        p.md = p.md * (1.0f - m.transmission.factor);
    }
    if (m.sheen.on()) {  // its albedo toward the viewer once here, toward each light in shadeLightPbrLayers
        shading::SheenLookup table{&shading::sheenLut()};
        p.sheen = m.sheen.packed();
        p.sheenTable = table.lut;
        p.sheenEV = table.at(table.sheenCos(s.N, V), m.sheen.roughness);
    }
}

}  // namespace shadelab::trace
