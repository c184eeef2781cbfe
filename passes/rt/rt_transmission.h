#pragma once
#include "passes/rt/rt_secondary.h"

namespace diptych {

// rt_transmission: recursive refraction rays (Snell, total internal reflection); the same params.
class RtTransmissionPass : public RtSecondaryPass {
 public:
  RtTransmissionPass() : RtSecondaryPass(Kind::Transmission) {}
};

}  // namespace diptych
