// Scene objects: analytic spheres and planes, and triangle meshes imported from glTF. Plain data.
#pragma once

#include "scene/material.h"
#include "scene/mesh_geometry.h"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shadelab {

struct Sphere {
    std::string name;
    glm::vec3 center{0.0f};  // world units
    float radius = 1.0f;     // world units, > 0
    Material material;
};

// A plane's checker pattern: tiles alternate between material.md and md2.
struct Checker {
    glm::vec3 md2{0.1f};  // second diffuse colour, linear RGB
    float size = 1.0f;    // tile edge, world units, > 0
};

// The plane {x : dot(normal, x) = offset}.
struct Plane {
    std::string name;
    glm::vec3 normal{0.0f, 1.0f, 0.0f};  // unit normal (normalised on load)
    float offset = 0.0f;                 // signed distance from the origin along normal, world units
    Material material;
    std::optional<Checker> checker;
};

// Triangles with one material, in world space (the mesh transform already applied). The geometry is shared
// with every copy of the scene; the material is the part's own.
struct MeshPart {
    std::shared_ptr<const MeshGeometry> geometry;  // never null once imported
    Material material;

    size_t triangleCount() const { return geometry ? geometry->triangleCount() : 0; }
};

// A glTF file placed in the scene. `source`, `transform` and `material` are what the scene file stores;
// `parts` is filled by the importer and is never serialised.
struct Mesh {
    std::string name;
    std::string source;         // glTF/GLB path, relative to the scene file's folder
    glm::mat4 transform{1.0f};  // model → world, applied on top of the glTF node hierarchy
    MaterialOverride material;  // fields set here replace the imported values
    std::vector<MeshPart> parts;

    size_t triangleCount() const {
        size_t n = 0;
        for (const MeshPart& p : parts) n += p.triangleCount();
        return n;
    }
};

}  // namespace shadelab
