#pragma once
// The exact producer of the texture_filtering slot (docs/textures.md): the mean base colour C
// and coverage over each pixel's footprint, from N x N stratified sub-pixel primary rays traced
// with Embree, each reading level 0 of the colour texture (its magnification filter) at the
// point it hits. Sub-rays that miss the scene are left out of the mean; a pixel whose centre
// misses (no G-buffer hit) gets -1, and shade then uses its own lookup. N = 1 traces the pixel
// centre only: the reference's own lookup (the built-in hybrid recipe uses it so that the
// all-exact hybrid stays equal to the Whitted reference).
#include "engine/graph/pass.h"
#include "passes/slots.h"

namespace diptych {

class TextureSupersamplePass : public Pass {
 public:
  static ParamSchema schema();
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  int samples_ = 4;  // N
  SlotIo io_;
};

}  // namespace diptych
