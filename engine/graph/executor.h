#pragma once
// Runs a compiled graph frame after frame: allocates pooled storage once, executes every node
// in order, checks that passes touch only what they declared, and times every node (CPU clock
// for all, GL timer queries for GL work and transfers).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/graph/frame_graph.h"

namespace diptych {

// What the executor needs from OpenGL; implemented in engine/graph/gl_backend.cpp.
class GlBackend {
 public:
  virtual ~GlBackend() = default;
  virtual unsigned createTexture(const ResourceDesc& desc) = 0;
  virtual void destroyTexture(unsigned texture) = 0;
  virtual void readback(unsigned texture, Surface& into) = 0;
  virtual void upload(const Surface& from, unsigned texture) = 0;
  virtual void fill(unsigned texture, const ResourceDesc& desc, const vec4& value) = 0;
  virtual void beginTimer(const std::string& label) = 0;
  virtual double endTimerMs() = 0;  // GPU time since beginTimer (waits for the result)
};

struct NodeTiming {
  std::vector<double> cpuMs;               // wall time on the CPU, one sample per frame
  std::vector<double> gpuMs;               // GL nodes and transfers only
  std::map<std::string, double> counters;  // last frame's counters (e.g. rays)
};

class GraphExecutor {
 public:
  // `gl` may be null when the graph has no GL node; `world` is handed to passes.
  GraphExecutor(const CompiledGraph& graph, RenderWorld& world, GlBackend* gl);
  ~GraphExecutor();
  GraphExecutor(const GraphExecutor&) = delete;
  GraphExecutor& operator=(const GraphExecutor&) = delete;

  void runFrame();
  void clearTimings();  // drop warm-up samples
  const std::vector<NodeTiming>& timings() const { return timings_; }
  const Surface& output(const std::string& resourceName) const;

 private:
  friend class ExecutionContext;
  const CompiledGraph& graph_;
  RenderWorld& world_;
  GlBackend* gl_;
  std::vector<Surface> cpuSlots_;
  std::vector<unsigned> glSlots_;
  std::vector<NodeTiming> timings_;
};

}  // namespace diptych
