// RedrawPlan: which part of the last raster image a new draw must redo (the viewer's partial redraw).
// A draw is keyed by everything its colour pass reads except the materials, and by each drawn object's
// material; when only materials changed, only the objects whose material changed are redrawn. Pure: no GL.
#pragma once

#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <type_traits>
#include <vector>

namespace shadelab::raster {

// A byte string that values are appended to, bit for bit (so -0.0 and 0.0, or two NaNs, differ: a key that
// differs only redraws more).
class KeyBytes {
public:
    template <typename T>
    KeyBytes& add(const T& value) {
        static_assert(std::is_trivially_copyable<T>::value, "KeyBytes::add takes plain values");
        const size_t at = bytes_.size();
        bytes_.resize(at + sizeof(T));
        std::memcpy(&bytes_[at], &value, sizeof(T));
        return *this;
    }
    KeyBytes& addString(const std::string& s) {
        add(s.size());
        bytes_.append(s);
        return *this;
    }
    bool operator==(const KeyBytes& o) const { return bytes_ == o.bytes_; }
    bool operator!=(const KeyBytes& o) const { return bytes_ != o.bytes_; }

private:
    std::string bytes_;
};

// What the colour passes read of one object's material (raster_passes.cpp setMaterial), and of a plane its
// checker. Fields the rasterizer ignores (kt, ior) are included: a change there redraws the object, exactly.
KeyBytes materialKey(const Material& m);
KeyBytes planeMaterialKey(const Plane& p);

// Everything of the scene the colour passes read except materials: camera, model, terms, ambient,
// background, raster settings, environment, lights, and every object's geometry (mesh parts by their shared
// geometry). Titles, notes and names are left out.
KeyBytes sceneKeyWithoutMaterials(const Scene& scene);

// One draw: the shared key (the scene's, plus whatever the renderer adds: frame block, program variant,
// sizes) and, per drawn object in draw order (mesh parts, spheres, planes), its coverage id and material key.
struct DrawKey {
    KeyBytes shared;
    std::vector<uint32_t> ids;
    std::vector<KeyBytes> materials;
};

// The scene's part of a DrawKey: sceneKeyWithoutMaterials, and the objects in the rasterizer's draw order.
DrawKey drawKey(const Scene& scene);

struct RedrawPlan {
    bool full = true;           // redraw everything
    std::vector<uint32_t> ids;  // otherwise: the coverage ids whose pixels to redraw (empty: nothing changed)
};

// Compares the key of the image in the target (null: none, or not reusable) with the next draw's. A partial
// plan needs the same shared key and the same objects; it lists each coverage id with a changed material,
// once, in draw order. More than `maxIds` changed ids give a full plan.
RedrawPlan planRedraw(const DrawKey* last, const DrawKey& next, size_t maxIds);

// Pixels [x0, x1) x [y0, y1) of a viewport, in GL window coordinates (y up).
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
};
PixelRect unite(const PixelRect& a, const PixelRect& b);

// A rectangle of the width x height viewport holding every pixel that geometry inside the box [lo, hi] can
// cover under the perspective viewProj: the bounds of the box clipped by the near plane, projected, plus two
// pixels of margin. Empty when the box lies wholly on the near plane's far side from the view.
PixelRect boxPixelRect(const glm::mat4& viewProj, const glm::vec3& lo, const glm::vec3& hi, int width, int height);

// Adds `id` to a partial plan (objects whose environment cube was re-rendered); past `maxIds` the plan turns full.
void addToPlan(RedrawPlan& plan, uint32_t id, size_t maxIds);

}  // namespace shadelab::raster
