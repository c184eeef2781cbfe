#pragma once
#include "passes/raster/blend_transmission.h"

namespace diptych {

// sorted_blend: the lecture's Z-buffer transparency, transparent objects back to front.
class SortedBlendPass : public BlendTransmissionPass {
 public:
  SortedBlendPass() : BlendTransmissionPass(true) {}
};

}  // namespace diptych
