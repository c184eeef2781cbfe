#pragma once
#include "passes/rt/rt_secondary.h"

namespace diptych {

// rt_reflection: recursive reflection rays; params: RtSecondaryPass::schema().
class RtReflectionPass : public RtSecondaryPass {
 public:
  RtReflectionPass() : RtSecondaryPass(Kind::Reflection) {}
};

}  // namespace diptych
