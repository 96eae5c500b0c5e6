// MeshTextures: the GL copies of the scene's shared Textures (scene/texture.h), uploaded on first use with
// every level of the texture's own 8-bit mip chain, each code as its half-float linear value (RGBA16F,
// shading/texel_decode.h), so mesh.frag's texelFetch reads exactly the floats the tracer decodes. Keyed by the shared
// object; a texture no longer in the scene is dropped by prune().
#pragma once

#include "gl/objects.h"
#include "scene/texture.h"

#include <map>
#include <memory>
#include <set>
#include <vector>

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
    std::vector<uint16_t> halves_;  // the level being uploaded, as half floats (kept: no fresh pages per texture)
};

}  // namespace shadelab::raster
