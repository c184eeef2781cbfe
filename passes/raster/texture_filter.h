#pragma once
// Raster producers of the texture_filtering slot (docs/textures.md): per G-buffer pixel, the
// base colour C (material colour x colour texture, linear) and coverage, the colour texture read
// through one filter. The pixel's uv footprint comes from ray differentials: the rays through
// the neighbouring pixel centres meet the hit triangle's plane, and their barycentric uv minus
// the pixel's own give du/dx, dv/dx, du/dy, dv/dy, the derivatives a rasterizer's 2x2 quads
// take of the perspective-correct uv inside a triangle.
//   texture_nearest.h      level 0, nearest texel (no mipmaps)
//   texture_bilinear.h     level 0, bilinear (no mipmaps)
//   texture_distance.h     the lecture's mip level from log2 of the eye distance, trilinear
//   texture_trilinear.h    GL's derivative-based lambda (8.14.1), trilinear
//   texture_anisotropic.h  EXT_texture_filter_anisotropic probes along the footprint's long axis
//   texture_sampler.h      the texture's own glTF sampler (min/mag filter, mipmap mode) at GL's
//                          derivative-based level: what glTF asks a renderer to do
#include "engine/graph/pass.h"
#include "passes/slots.h"

namespace diptych {

enum class TextureFilterKind { Nearest, Bilinear, Distance, Trilinear, Anisotropic, Sampler };

class TextureFilterPass : public Pass {
 public:
  explicit TextureFilterPass(TextureFilterKind kind) : kind_(kind) {}
  static ParamSchema schema(TextureFilterKind kind);
  Domain domain() const override { return Domain::Gl; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  TextureFilterKind kind_;
  int maxAnisotropy_ = 16;
  SlotIo io_;
};

}  // namespace diptych
