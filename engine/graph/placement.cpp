#include "engine/graph/placement.h"

#include <fmt/format.h>
#include <algorithm>

#include "engine/graph/adaptive_pass.h"
#include "engine/graph/placeable_pass.h"

namespace diptych {
namespace {

// Whether a live pass other than `self`, placed in `domain`, reads `r`.
bool readInDomain(const CompiledGraph& g, ResourceId r, Domain domain, PassIndex self,
                  const std::vector<bool>& unplaced) {
  for (PassIndex q : g.resources[r].readers) {
    const GraphPass& reader = g.passes[q];
    if (q != self && !reader.culled && !unplaced[std::size_t(q.value)] && reader.domain == domain)
      return true;
  }
  return false;
}

}  // namespace

std::size_t placementCost(const CompiledGraph& g, PassIndex p, Domain domain,
                          const std::vector<bool>& unplaced) {
  const GraphPass& pass = g.passes[p];
  const Domain other = domain == Domain::Gl ? Domain::Cpu : Domain::Gl;
  std::size_t bytes = 0;
  std::vector<ResourceId> counted;  // a resource read twice moves once
  for (ResourceId r : pass.reads) {
    if (std::find(counted.begin(), counted.end(), r) != counted.end()) continue;
    // Free on GL (its producer is there) and dropped on the CPU (dropGlOnlyReads).
    if (std::find(pass.glOnlyReads.begin(), pass.glOnlyReads.end(), r) != pass.glOnlyReads.end())
      continue;
    counted.push_back(r);
    const GraphPass& producer = g.passes[g.resources[r].producer];
    if (producer.culled || producer.domain == domain) continue;
    if (!readInDomain(g, r, domain, p, unplaced)) bytes += g.resources[r].desc.bytes();
  }
  for (ResourceId w : pass.writes) {
    const bool output = std::find(g.outputs.begin(), g.outputs.end(), w) != g.outputs.end();
    if ((output && domain == Domain::Gl) || readInDomain(g, w, other, p, unplaced))
      bytes += g.resources[w].desc.bytes();
  }
  return bytes;
}

void placeAutoPasses(CompiledGraph& g, const std::vector<PassIndex>& order) {
  std::vector<bool> unplaced(g.passes.size(), false);
  auto placeable = [&](PassIndex p) {
    return dynamic_cast<PlaceablePass*>(g.passes[p].pass.get());
  };
  for (PassIndex p : g.passes.ids())
    unplaced[std::size_t(p.value)] =
        !g.passes[p].culled && placeable(p) && placeable(p)->autoPlaced();
  for (PassIndex p : order) {
    if (!unplaced[std::size_t(p.value)]) continue;
    const std::size_t gl = placementCost(g, p, Domain::Gl, unplaced);
    const std::size_t cpu = placementCost(g, p, Domain::Cpu, unplaced);
    GraphPass& pass = g.passes[p];
    pass.domain = gl <= cpu ? Domain::Gl : Domain::Cpu;
    placeable(p)->place(pass.domain);
    pass.placement = fmt::format("auto: {} (bytes moved between domains if on gl: {}, on cpu: {})",
                                 domainName(pass.domain), gl, cpu);
    unplaced[std::size_t(p.value)] = false;
  }
}

void dropGlOnlyReads(CompiledGraph& g) {
  for (PassIndex p : g.passes.ids()) {
    GraphPass& pass = g.passes[p];
    if (pass.domain == Domain::Gl) continue;
    for (ResourceId r : pass.glOnlyReads) {
      std::erase(pass.reads, r);
      std::erase(g.resources[r].readers, p);
    }
    pass.glOnlyReads.clear();
  }
}

namespace {

class CompiledReaders final : public ReaderQuery {
 public:
  explicit CompiledReaders(const CompiledGraph& g) : g_(g) {}
  bool readIn(ResourceId id, Domain domain) const override {
    for (PassIndex q : g_.resources[id].readers)
      if (!g_.passes[q].culled && g_.passes[q].domain == domain) return true;
    return false;
  }
  bool trianglesRead(ResourceId id) const override {
    for (PassIndex q : g_.resources[id].readers)
      if (!g_.passes[q].culled && g_.passes[q].pass->readsHitTriangles()) return true;
    return false;
  }
  bool consumed(ResourceId id) const override {
    if (std::find(g_.outputs.begin(), g_.outputs.end(), id) != g_.outputs.end()) return true;
    for (PassIndex q : g_.resources[id].readers)
      if (!g_.passes[q].culled) return true;
    return false;
  }

 private:
  const CompiledGraph& g_;
};

}  // namespace

void adaptPasses(CompiledGraph& g) {
  const CompiledReaders readers(g);
  for (PassIndex p : g.passes.ids()) {
    GraphPass& pass = g.passes[p];
    if (auto* adaptive = dynamic_cast<AdaptivePass*>(pass.pass.get()); adaptive && !pass.culled)
      pass.variant = adaptive->adapt(readers);
  }
}

}  // namespace diptych
