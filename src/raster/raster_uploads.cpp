// RasterRenderer's uploads: the scene's meshes (vertex attributes, rebased indices and their material maps)
// into its GL buffers, and the frame uniform block. The passes that read them are raster_passes.cpp's.
#include "raster/raster_renderer.h"

#include "raster/frame_block.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <set>
#include <vector>

namespace shadelab::raster {

void RasterRenderer::uploadMeshes(const Scene& scene) {
    geometry_.ranges.clear();
    ++geometry_.generation;
    size_t vertexCount = 0, indexCount = 0;
    for (const Mesh& m : scene.meshes)
        for (const MeshPart& p : m.parts) {
            vertexCount += p.geometry->positions.size();
            indexCount += p.geometry->indices.size();
        }
    if (!geometry_.meshVao) {
        geometry_.meshVao = gl::VertexArray::create();
        geometry_.meshVbo = gl::Buffer::create();
        geometry_.meshIbo = gl::Buffer::create();
    }
    glBindVertexArray(geometry_.meshVao.id());
    glBindBuffer(GL_ARRAY_BUFFER, geometry_.meshVbo.id());
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, geometry_.meshIbo.id());
    if (vertexCount == 0) {
        glBindVertexArray(0);
        return;
    }
    // Positions, normals, then TEXCOORD_0, TEXCOORD_1 and tangents where any part has them (planar arrays; zeros
    // for the parts without), and one index buffer rebased per part. An array no part has is left out: its
    // attribute reads the constant 0 instead (a model without textures, as most CAD models are, uploads 24
    // bytes a vertex instead of 56).
    bool anyUv0 = false, anyUv1 = false, anyTangents = false;
    for (const Mesh& m : scene.meshes)
        for (const MeshPart& p : m.parts) {
            const size_t n = p.geometry->positions.size();
            anyUv0 = anyUv0 || (n > 0 && p.geometry->texcoords0.size() == n);
            anyUv1 = anyUv1 || (n > 0 && p.geometry->texcoords1.size() == n);
            anyTangents = anyTangents || (n > 0 && p.geometry->tangents.size() == n);
        }
    const size_t uvOffset = vertexCount * 2 * sizeof(glm::vec3);
    const size_t uv1Offset = uvOffset + (anyUv0 ? vertexCount * sizeof(glm::vec2) : 0);
    const size_t tangentOffset = uv1Offset + (anyUv1 ? vertexCount * sizeof(glm::vec2) : 0);
    const size_t vertexBytes = tangentOffset + (anyTangents ? vertexCount * sizeof(glm::vec4) : 0);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertexBytes), nullptr, GL_STATIC_DRAW);
    std::vector<glm::vec2> zeros;
    std::vector<glm::vec4> zeros4;
    std::set<const Texture*> textures;
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indexCount * sizeof(uint32_t)), nullptr, GL_STATIC_DRAW);
    size_t vBase = 0, iBase = 0;
    std::vector<uint32_t> rebased;
    for (size_t mi = 0; mi < scene.meshes.size(); ++mi) {
        const Mesh& m = scene.meshes[mi];
        for (size_t pi = 0; pi < m.parts.size(); ++pi) {
            const MeshGeometry& g = *m.parts[pi].geometry;
            const size_t n = g.positions.size();
            size_t bytes = n * sizeof(glm::vec3);
            glBufferSubData(GL_ARRAY_BUFFER, GLintptr(vBase * sizeof(glm::vec3)), GLsizeiptr(bytes),
                            g.positions.data());
            glBufferSubData(GL_ARRAY_BUFFER, GLintptr((vertexCount + vBase) * sizeof(glm::vec3)), GLsizeiptr(bytes),
                            g.normals.data());
            auto uvs = [&](const std::vector<glm::vec2>& uv, size_t offset) {
                const bool has = uv.size() == n;
                if (!has) zeros.assign(n, glm::vec2(0.0f));
                glBufferSubData(GL_ARRAY_BUFFER, GLintptr(offset + vBase * sizeof(glm::vec2)),
                                GLsizeiptr(n * sizeof(glm::vec2)), has ? uv.data() : zeros.data());
            };
            if (anyUv0) uvs(g.texcoords0, uvOffset);
            if (anyUv1) uvs(g.texcoords1, uv1Offset);
            if (anyTangents) {
                const bool hasTangents = g.tangents.size() == n;
                if (!hasTangents) zeros4.assign(n, glm::vec4(0.0f));
                glBufferSubData(GL_ARRAY_BUFFER, GLintptr(tangentOffset + vBase * sizeof(glm::vec4)),
                                GLsizeiptr(n * sizeof(glm::vec4)), hasTangents ? g.tangents.data() : zeros4.data());
            }
            const Material& mat = m.parts[pi].material;
            for (const TextureBinding* b : {&mat.baseColorTexture, &mat.metallicRoughnessTexture, &mat.normalTexture,
                                            &mat.occlusionTexture, &mat.emissiveTexture})
                if (b->texture && textures.insert(b->texture.get()).second) textures_.texture(b->texture);
            rebased.resize(g.indices.size());
            for (size_t k = 0; k < g.indices.size(); ++k) rebased[k] = g.indices[k] + uint32_t(vBase);
            glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, GLintptr(iBase * sizeof(uint32_t)),
                            GLsizeiptr(rebased.size() * sizeof(uint32_t)), rebased.data());
            geometry_.ranges.push_back({mi, pi, iBase, g.indices.size(), g.bounds.lo, g.bounds.hi});
            vBase += g.positions.size();
            iBase += g.indices.size();
        }
    }
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3),
                          reinterpret_cast<const void*>(vertexCount * sizeof(glm::vec3)));
    // An attribute without an array reads the context's constant value, set here to the zeros it stands for
    // (the default would give a tangent w = 1).
    const auto array = [](GLuint location, bool present, GLint size, size_t stride, size_t offset) {
        if (present) {
            glEnableVertexAttribArray(location);
            glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, GLsizei(stride),
                                  reinterpret_cast<const void*>(offset));
        } else {
            glDisableVertexAttribArray(location);
            glVertexAttrib4f(location, 0.0f, 0.0f, 0.0f, 0.0f);
        }
    };
    array(2, anyUv0, 2, sizeof(glm::vec2), uvOffset);
    array(3, anyUv1, 2, sizeof(glm::vec2), uv1Offset);
    array(4, anyTangents, 4, sizeof(glm::vec4), tangentOffset);
    glBindVertexArray(0);
    textures_.prune(textures);
    gl::checkError("RasterRenderer::uploadMeshes");
}

void RasterRenderer::uploadFrame(const FrameBlock& frame) const {
    glBindBuffer(GL_UNIFORM_BUFFER, frameUbo_.id());
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(FrameBlock), &frame);
    glBindBufferBase(GL_UNIFORM_BUFFER, kFrameBinding, frameUbo_.id());
}

}  // namespace shadelab::raster
