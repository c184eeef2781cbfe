#pragma once
#include "passes/raster/blend_transmission.h"

namespace diptych {

// unsorted_blend: Z-buffer transparency in scene order (the error sorting removes).
class UnsortedBlendPass : public BlendTransmissionPass {
 public:
  UnsortedBlendPass() : BlendTransmissionPass(false) {}
};

}  // namespace diptych
