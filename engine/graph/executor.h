#pragma once
// Runs a compiled graph frame after frame: allocates pooled storage once, executes every node
// in order, checks that passes touch only what they declared, and times every node (CPU clock
// for all, GL timer queries for GL work and transfers, read after the frame without stalling).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/graph/frame_graph.h"
#include "engine/graph/gl_backend.h"

namespace diptych {

struct NodeTiming {
  std::vector<double> cpuMs;               // wall time on the CPU, one sample per frame
  std::vector<double> gpuMs;               // GL nodes and transfers only
  std::map<std::string, double> counters;  // last frame's counters (e.g. rays)
};

class GraphExecutor {
 public:
  // `world` is handed to passes. GL storage is created on world.glContext() when the graph has
  // GL work (which then needs a context); a CPU-only graph never touches OpenGL.
  GraphExecutor(const CompiledGraph& graph, RenderWorld& world);
  ~GraphExecutor();
  GraphExecutor(const GraphExecutor&) = delete;
  GraphExecutor& operator=(const GraphExecutor&) = delete;

  void runFrame();
  void clearTimings();  // drop warm-up samples
  const std::vector<NodeTiming>& timings() const { return timings_; }
  const CpuImage& output(const std::string& resourceName) const;

 private:
  friend class ExecutionContext;
  const CompiledGraph& graph_;
  RenderWorld& world_;
  std::unique_ptr<GlBackend> gl_;
  IdVector<PoolSlotId, CpuImage> cpuSlots_;  // empty in GL slots
  IdVector<PoolSlotId, int> glSlots_;        // GlBackend handles; -1 in CPU slots
  std::vector<NodeTiming> timings_;
};

}  // namespace diptych
