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
    // Positions, normals, TEXCOORD_0, TEXCOORD_1 and tangents (five planar arrays; zeros for parts without
    // texture coordinates or tangents), and one index buffer rebased per part.
    const size_t uvOffset = vertexCount * 2 * sizeof(glm::vec3);
    const size_t uv1Offset = uvOffset + vertexCount * sizeof(glm::vec2);
    const size_t tangentOffset = uv1Offset + vertexCount * sizeof(glm::vec2);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(tangentOffset + vertexCount * sizeof(glm::vec4)), nullptr, GL_STATIC_DRAW);
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
            uvs(g.texcoords0, uvOffset);
            uvs(g.texcoords1, uv1Offset);
            const bool hasTangents = g.tangents.size() == n;
            if (!hasTangents) zeros4.assign(n, glm::vec4(0.0f));
            glBufferSubData(GL_ARRAY_BUFFER, GLintptr(tangentOffset + vBase * sizeof(glm::vec4)),
                            GLsizeiptr(n * sizeof(glm::vec4)), hasTangents ? g.tangents.data() : zeros4.data());
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
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(glm::vec2), reinterpret_cast<const void*>(uvOffset));
    glEnableVertexAttribArray(3);
    glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, sizeof(glm::vec2), reinterpret_cast<const void*>(uv1Offset));
    glEnableVertexAttribArray(4);
    glVertexAttribPointer(4, 4, GL_FLOAT, GL_FALSE, sizeof(glm::vec4), reinterpret_cast<const void*>(tangentOffset));
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
