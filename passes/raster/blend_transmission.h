#pragma once
#include <vector>

#include "engine/gl/objects.h"
#include "engine/graph/pass.h"
#include "engine/scene/world_geometry.h"
#include "passes/slots.h"

namespace diptych {

// The lecture's Z-buffer algorithm for transparent surfaces (Tema 5, "Z-buffer en superf.
// transparentes y reflectantes") as a transmission-slot producer: the opaque surfaces first
// (with depth), then the transparent ones (k_t > 0) strictly behind the pixel's first visible
// surface, each composited as I = I_m + k_t M_T I. No bending (t = -i): the radiance along the
// view ray. `sorted` draws the transparent objects back to front by the view depth of their
// bounds centres (per object, as the lecture sorts polygons); unsorted keeps scene order.
// Pixels whose first surface has k_t = 0 (or no surface) get 0. docs/forward-producers.md.
// The family of sorted_blend.h and unsorted_blend.h.
class BlendTransmissionPass : public Pass {
 public:
  explicit BlendTransmissionPass(bool sorted) : sorted_(sorted) {}
  static ParamSchema schema();
  Domain domain() const override { return Domain::Gl; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  bool sorted_;
  bool depthPrefill_ = true;
  bool textureLod_ = true;  // texture_lod (passes/raster/forward_texture_lod.h)
  SlotIo io_;
  ResourceId surface_ = kNoResource;
};

// Step one of the blend producers (shaders/blend_transmission_first.frag): into `first` (RGBA32F,
// the size of `hits`), inside `scissor` (x, y, width, height), per pixel whose first visible
// surface transmits: rgb = the mask's factor, a = that surface's distance from `eye`; elsewhere (0,
// 0, 0, -1). Reads the G-buffer's stored surface when `surface` is given. The forward passes read
// it (gl::ForwardOptions::transmissiveFirst) instead of rebuilding the surface per fragment.
// With `depth` (D32F): 1 there where the first surface does not transmit, 0 elsewhere (the
// forward passes' reversed-Z depth, pre-filled so that their early depth test rejects those
// pixels).
void renderBlendFirst(RenderWorld& world, const gl::Texture& hits, const gl::Texture* surface,
                      const vec3& eye, const gl::Texture& first, const glm::ivec4& scissor,
                      const gl::Texture* depth = nullptr);

// Mesh indices of the transparent objects (material k_t > 0), farthest first by the view
// depth (-z_view) of each object's bounds centre; ties keep scene order.
std::vector<int> transparentBackToFront(const Scene& scene, const WorldGeometry& world,
                                        const mat4& view);

}  // namespace diptych
