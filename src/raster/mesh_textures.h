// MeshTextures: the GL copies of the scene's shared Textures (scene/texture.h), uploaded as the scene's meshes
// are (or on first use) with every level of the texture's own 8-bit mip chain, as GL_SRGB8_ALPHA8 (colour
// maps) or GL_RGBA8, so that mesh.frag's texelFetch decodes the very codes the tracer decodes. Keyed by the shared
// object; a texture no longer in the scene is dropped by prune().
#pragma once

#include "gl/objects.h"
#include "scene/texture.h"

#include <map>
#include <memory>
#include <set>

namespace shadelab::raster {

class MeshTextures {
public:
    // The GL texture name for `texture`, uploading it the first time it is asked for.
    GLuint texture(const std::shared_ptr<const Texture>& texture);
    // Drops every texture not in `keep`.
    void prune(const std::set<const Texture*>& keep);
    size_t size() const { return uploaded_.size(); }

private:
    struct Entry {
        std::shared_ptr<const Texture> owner;  // keeps the key's address from being reused while uploaded
        gl::Texture gl;
    };
    std::map<const Texture*, Entry> uploaded_;
};

}  // namespace shadelab::raster
