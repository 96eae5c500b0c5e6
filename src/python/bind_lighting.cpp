// The lighting equations over numpy arrays: loops over shaders/lighting.glsl compiled as C++ (shading/lighting.h),
// the very text both renderers run, in float as they do. The package (python/shadelab/lighting.py) broadcasts the
// arguments; here every array arrives as n rows.
#include "python/bindings.h"
#include "scene/shading_model.h"
#include "shading/lighting.h"
#include "util/input_error.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <string>

namespace py = pybind11;

namespace shadelab::python {
namespace {

using Floats = py::array_t<float, py::array::c_style | py::array::forcecast>;

// Rows of a (n, 3) or (n,) array, checked against n.
size_t rows(const Floats& a, int columns, const char* name, py::ssize_t n = -1) {
    const bool ok = columns == 3 ? a.ndim() == 2 && a.shape(1) == 3 : a.ndim() == 1;
    if (!ok || (n >= 0 && a.shape(0) != n))
        throw py::value_error(std::string(name) + ": expected shape (n" + (columns == 3 ? ", 3)" : ")"));
    return size_t(a.shape(0));
}

shading::vec3 vecAt(const float* p, size_t i) { return shading::vec3(p[i * 3], p[i * 3 + 1], p[i * 3 + 2]); }

void store(float* out, size_t i, const shading::vec3& v) {
    out[i * 3] = v.x;
    out[i * 3 + 1] = v.y;
    out[i * 3 + 2] = v.z;
}

// A per-row scalar lobe: Phong or Blinn-Phong.
template <typename Lobe>
py::array_t<float> lobe(const Floats& N, const Floats& L, const Floats& V, const Floats& s, Lobe f) {
    const size_t n = rows(N, 3, "N");
    rows(L, 3, "L", py::ssize_t(n));
    rows(V, 3, "V", py::ssize_t(n));
    rows(s, 1, "s", py::ssize_t(n));
    py::array_t<float> out(n);
    const float *pN = N.data(), *pL = L.data(), *pV = V.data(), *ps = s.data();
    float* o = out.mutable_data();
    for (size_t i = 0; i < n; ++i) o[i] = f(vecAt(pN, i), vecAt(pL, i), vecAt(pV, i), ps[i]);
    return out;
}

}  // namespace

void bindLighting(py::module_& m) {
    m.def("_phong", [](const Floats& N, const Floats& L, const Floats& V, const Floats& s) {
        return lobe(N, L, V, s, shading::specularPhong);
    });
    m.def("_blinn_phong", [](const Floats& N, const Floats& L, const Floats& V, const Floats& s) {
        return lobe(N, L, V, s, shading::specularBlinnPhong);
    });
    m.def("_reflect_light", [](const Floats& N, const Floats& L) {
        const size_t n = rows(N, 3, "N");
        rows(L, 3, "L", py::ssize_t(n));
        py::array_t<float> out({n, size_t(3)});
        for (size_t i = 0; i < n; ++i)
            store(out.mutable_data(), i, shading::reflectLight(vecAt(N.data(), i), vecAt(L.data(), i)));
        return out;
    });
    // glTF 2.0 Appendix B's specular BRDF D·V·F (specularGGX with F0 = pbrF0), 0 where N·L <= 0 as in shadeLight.
    m.def("_pbr", [](const Floats& N, const Floats& L, const Floats& V, const Floats& baseColor, const Floats& metallic,
                     const Floats& roughness) {
        const size_t n = rows(N, 3, "N");
        const auto sn = py::ssize_t(n);
        rows(L, 3, "L", sn);
        rows(V, 3, "V", sn);
        rows(baseColor, 3, "base_color", sn);
        rows(metallic, 1, "metallic", sn);
        rows(roughness, 1, "roughness", sn);
        py::array_t<float> out({n, size_t(3)});
        for (size_t i = 0; i < n; ++i) {
            const shading::vec3 Ni = vecAt(N.data(), i), Li = vecAt(L.data(), i), Vi = vecAt(V.data(), i);
            const shading::vec3 f0 = shading::pbrF0(vecAt(baseColor.data(), i), metallic.data()[i]);
            store(out.mutable_data(), i,
                  shading::dot(Ni, Li) > 0.0f ? shading::specularGGX(Ni, Li, Vi, f0, roughness.data()[i])
                                              : shading::vec3(0.0f));
        }
        return out;
    });
    // shadeLightDisney: one light's contribution under the principled BRDF; p holds the eight parameters as rows
    // of (subsurface, specular, specularTint, anisotropic, sheen, sheenTint, clearcoat, clearcoatGloss).
    m.def("_disney", [](const Floats& N, const Floats& L, const Floats& V, const Floats& Il, const Floats& baseColor,
                        const Floats& metallic, const Floats& roughness, const std::vector<Floats>& p, bool diffuse,
                        bool specular) {
        const size_t n = rows(N, 3, "N");
        const auto sn = py::ssize_t(n);
        rows(L, 3, "L", sn);
        rows(V, 3, "V", sn);
        rows(Il, 3, "Il", sn);
        rows(baseColor, 3, "base_color", sn);
        rows(metallic, 1, "metallic", sn);
        rows(roughness, 1, "roughness", sn);
        if (p.size() != 8) throw UsageError("disney: expected 8 parameter rows");
        for (const Floats& q : p) rows(q, 1, "parameter", sn);
        py::array_t<float> out({n, size_t(3)});
        for (size_t i = 0; i < n; ++i) {
            const shading::vec4 d0(p[0].data()[i], p[1].data()[i], p[2].data()[i], p[3].data()[i]);
            const shading::vec4 d1(p[4].data()[i], p[5].data()[i], p[6].data()[i], p[7].data()[i]);
            store(out.mutable_data(), i,
                  shading::shadeLightDisney(vecAt(N.data(), i), vecAt(L.data(), i), vecAt(V.data(), i),
                                            vecAt(Il.data(), i), vecAt(baseColor.data(), i), metallic.data()[i],
                                            roughness.data()[i], d0, d1, diffuse, specular, shading::vec3(1.0f)));
        }
        return out;
    });
    // shadeLight: one light's whole contribution under any model (pbr reads md, ms, s as its diffuse colour, F0
    // and roughness, as the renderers hand them over).
    m.def("_shade", [](const Floats& N, const Floats& L, const Floats& V, const Floats& Il, const Floats& md,
                       const Floats& ms, const Floats& s, const std::string& model, bool diffuse, bool specular) {
        const std::optional<ShadingModel> named = parseShadingModel(model);
        if (!named)
            throw UsageError("model: unknown shading model '" + model + "'; expected " +
                             nameChoices(kShadingModelNames));
        if (*named == ShadingModel::Disney)
            throw UsageError("model: disney reads more than md, ms and s: use shadelab.lighting.disney()");
        const size_t n = rows(N, 3, "N");
        const auto sn = py::ssize_t(n);
        rows(L, 3, "L", sn);
        rows(V, 3, "V", sn);
        rows(Il, 3, "Il", sn);
        rows(md, 3, "md", sn);
        rows(ms, 3, "ms", sn);
        rows(s, 1, "s", sn);
        py::array_t<float> out({n, size_t(3)});
        for (size_t i = 0; i < n; ++i)
            store(out.mutable_data(), i,
                  shading::shadeLight(vecAt(N.data(), i), vecAt(L.data(), i), vecAt(V.data(), i), vecAt(Il.data(), i),
                                      vecAt(md.data(), i), vecAt(ms.data(), i), s.data()[i], modelIndex(*named),
                                      diffuse, specular));
        return out;
    });
}

}  // namespace shadelab::python
