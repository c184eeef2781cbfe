#pragma once
#include "engine/graph/pass.h"
#include "passes/slots.h"

namespace diptych {

// The visibility slot with no shadows at all: V_i = 1 for every light at every pixel (what the
// forward renderer assumes, docs/forward-producers.md). Its error against rt_shadows is what
// shadows contribute to the frame: the baseline every shadow technique has to beat.
class NoShadowsPass : public Pass {
 public:
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  SlotIo io_;
};

}  // namespace diptych
