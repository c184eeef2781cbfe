#include "passes/cpu/no_shadows.h"

namespace diptych {

void NoShadowsPass::setup(PassBuilder& b) {
  io_ = slotIo(b, "visibility");
}

void NoShadowsPass::execute(PassContext& c) {
  c.cpuWrite(io_.signal).fill(vec4(1.f));
}

}  // namespace diptych
