#pragma once
// A pass that runs in either domain (shade). When setup() leaves its domain to the compiler
// (autoPlaced() true), compile picks one by the placement rule (engine/graph/placement.h,
// docs/frame-graph.md "Placement") and calls place() before scheduling; domain() is read
// after setup() and after place().
#include "engine/graph/pass.h"

namespace diptych {

class PlaceablePass : public Pass {
 public:
  virtual bool autoPlaced() const = 0;
  virtual void place(Domain domain) = 0;
};

}  // namespace diptych
