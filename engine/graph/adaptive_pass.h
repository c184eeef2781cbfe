#pragma once
// A pass whose work depends on who reads its outputs (the G-buffer: exact (u, v) only when a GL
// pass reads its hits, passes/raster/gbuffer.h). After culling and placement, compile calls
// adapt() once with the frame's final readers; the pass records its choice for execute() and
// returns one line saying what it chose and why, kept in GraphPass::variant (the graph export's
// "variant", the table of `render --timings`). docs/frame-graph.md, "Adaptive passes".
#include <string>

#include "engine/graph/pass.h"

namespace diptych {

// What adapt() may ask of the compiled frame.
class ReaderQuery {
 public:
  virtual ~ReaderQuery() = default;
  // Whether a live pass placed in `domain` reads `id` (a CPU reader of a GL resource gets a
  // readback, never the texture).
  virtual bool readIn(ResourceId id, Domain domain) const = 0;
  // Whether any live pass reads `id`, or the frame outputs it.
  virtual bool consumed(ResourceId id) const = 0;
  // Whether a live pass that reads `id` reads the triangles its texels name
  // (Pass::readsHitTriangles).
  virtual bool trianglesRead(ResourceId id) const = 0;
};

class AdaptivePass : public Pass {
 public:
  virtual std::string adapt(const ReaderQuery& readers) = 0;
};

}  // namespace diptych
