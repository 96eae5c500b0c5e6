// The classic OpenGL material table (brass, chrome, jade, pearl, plastics, rubbers, ...) as Phong
// coefficients ma/md/ms/s. Data only; viewer_state.h applies a preset to an object.
#pragma once

#include "scene/material.h"

#include <string>
#include <vector>

namespace shadelab::app {

struct MaterialPreset {
    const char* name;
    glm::vec3 ma, md, ms;  // GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR as they are in the table
    float s;               // GL_SHININESS: the table's value × 128
};

const std::vector<MaterialPreset>& materialPresets();

// nullptr when no preset has that name (exact match, as listed).
const MaterialPreset* findMaterialPreset(const std::string& name);

// The preset's ma, md, ms and s replace the material's; kr, kt and ior are kept.
Material withPreset(Material m, const MaterialPreset& p);

}  // namespace shadelab::app
