#pragma once
// Placement of passes that run in either domain (PlaceablePass, e.g. `shade` with
// domain=auto). The rule (docs/frame-graph.md, "Placement"): a pass runs in the domain that
// moves fewer bytes between GL and the CPU, counting
//   - each input produced in the other domain, unless another pass already needs it in this
//     domain (the transfer exists anyway) or its producer was culled (a default is filled
//     in place);
//   - each output that a pass in the other domain reads, and, for GL, each of its outputs that
//     is requested (outputs are read back to the CPU at the end of the frame).
// Other requested outputs do not count: asking to inspect a signal (compare's per-slot metrics,
// `render --output`) must not change where the frame runs.
// A tie goes to GL: the frame then stays on the GPU and its one readback comes last.
// Passes are placed in dependency order, so a placed producer counts with its chosen domain.
#include <vector>

#include "engine/graph/frame_graph.h"

namespace diptych {

// Bytes between domains if live pass `p` ran in `domain`, by the rule above.
std::size_t placementCost(const CompiledGraph& g, PassIndex p, Domain domain,
                          const std::vector<bool>& unplaced);

// Calls place() on every live auto-placed pass, in `order`, and records the choice and the
// compared bytes in GraphPass::placement.
void placeAutoPasses(CompiledGraph& g, const std::vector<PassIndex>& order);

// Calls adapt() on every live AdaptivePass (adaptive_pass.h) with the frame's final readers, and
// records its statement in GraphPass::variant. Runs after placement and dropGlOnlyReads.
void adaptPasses(CompiledGraph& g);

// Removes the glOnly companion reads (readCompanion, companion.h) of every pass that runs on the
// CPU, so that they insert no readback and keep no resource alive.
void dropGlOnlyReads(CompiledGraph& g);

}  // namespace diptych
