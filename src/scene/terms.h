// The lecture's term switches (design.md §1) as a struct of flags (Terms), the enum that names one of them
// (Term), and its one name table: the words of a scene file's "terms" keys, `--terms` and viewer scripts.
#pragma once

#include "util/name_table.h"

namespace shadelab {

// A switched-off term contributes nothing.
struct Terms {
    bool ambient = true;
    bool diffuse = true;
    bool specular = true;
    bool shadows = true;      // both renderers (the rasterizer through shadow maps)
    bool reflections = true;  // both renderers; includes refraction, which only the tracer draws
};

enum class Term { Ambient, Diffuse, Specular, Shadows, Reflections };

inline constexpr EnumName<Term> kTermNames[] = {
    {Term::Ambient, "ambient"}, {Term::Diffuse, "diffuse"},         {Term::Specular, "specular"},
    {Term::Shadows, "shadows"}, {Term::Reflections, "reflections"},
};

inline const char* toString(Term t) { return nameOf(kTermNames, t); }
inline std::optional<Term> parseTerm(std::string_view name) { return lookupName(kTermNames, name); }

// The flag of term `t` in `terms`.
template <typename T>  // Terms or const Terms
auto& termFlag(T& terms, Term t) {
    switch (t) {
        case Term::Ambient: return terms.ambient;
        case Term::Diffuse: return terms.diffuse;
        case Term::Specular: return terms.specular;
        case Term::Shadows: return terms.shadows;
        case Term::Reflections: return terms.reflections;
    }
    return terms.ambient;
}
inline bool termEnabled(const Terms& terms, Term t) { return termFlag(terms, t); }

}  // namespace shadelab
