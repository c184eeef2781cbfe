#pragma once
// Runs a compiled graph frame after frame: allocates pooled storage once, executes every node
// in order, checks that passes touch only what they declared, and times every node (CPU clock
// for all, GL timer queries for GL work and transfers, read after the frame without stalling).
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/timing.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/gl_backend.h"

namespace diptych {

struct NodeTiming {
  std::vector<double> cpuMs;  // wall time on the CPU, one sample per frame
  // CPU time of all the process's threads over the node (CLOCK_PROCESS_CPUTIME_ID), per frame.
  std::vector<double> processCpuMs;
  std::vector<double> gpuMs;  // GL nodes and transfers only: the node's own GL_TIME_ELAPSED
  // GL nodes and transfers only: the time spent, before this node's clocks started, waiting
  // for GL work that earlier nodes issued (their time is in their gpuMs), per frame.
  std::vector<double> glWaitMs;
  // The CPU time of all threads over that wait: on llvmpipe the rasterizer threads run the
  // earlier nodes' GL work in it, so CPU-time totals of a frame must add it (docs/frame-graph.md).
  std::vector<double> glWaitCpuMs;
  // GL nodes and transfers only: the wait, after the node returned, until its own GL work was
  // complete (measured before the next GL node starts, or at the end of the frame), and the CPU
  // time of all threads over it. On llvmpipe that CPU time is the node's rasterization run by
  // the rasterizer threads, so processCpuMs + glCompletionCpuMs is the node's whole CPU cost;
  // on a hardware GPU it is near zero (the CPU sleeps while the GPU works).
  std::vector<double> glCompletionMs;
  std::vector<double> glCompletionCpuMs;
  // GL nodes and transfers only: the wall time from the node's return to the start of that
  // wait, in which the CPU nodes scheduled after it ran beside its GL work (0 when the next
  // node is GL work itself, and for a readback, whose work is done when it returns). The
  // export names those nodes (`overlapped_by`).
  std::vector<double> glOverlapMs;
  // One-time work the world recorded while the node ran (growth of RenderWorld::oneTimeMs:
  // a BVH build, an upload, a program compiled), per frame.
  std::vector<double> oneTimeMs;
  std::map<std::string, double> counters;  // last frame's counters (e.g. rays)
};

// When the executor waits for the GL work of a frame (docs/frame-graph.md, Timing).
enum class GlSync {
  // Before every GL node and transfer, for the GL work issued before it (glFinish): that
  // work's CPU time is charged to the node that issued it (gl_completion_cpu_ms). On a
  // software rasterizer the "GPU" is the CPU, and without this its work would sit in the CPU
  // time of whichever node happened to synchronise.
  PerNode,
  // Only at the end of the frame: the CPU issues the next GL node while the GPU runs the
  // previous one, as an engine does; a node's GL time is its timer query alone, and a readback
  // waits for the GL work before it inside its own time.
  PerFrame,
  // PerNode on a software rasterizer (llvmpipe, softpipe, SWR: GL_RENDERER), else PerFrame.
  Auto,
};
std::optional<GlSync> parseGlSync(const std::string& name);  // "node", "frame", "auto"
const char* glSyncName(GlSync sync);                         // "node" or "frame"

class GraphExecutor {
 public:
  // `world` is handed to passes. GL storage is created on world.glContext() when the graph has
  // GL work (which then needs a context); a CPU-only graph never touches OpenGL. `sync` is
  // resolved here (Auto: by the context's renderer); glSync() says what it became and why.
  GraphExecutor(const CompiledGraph& graph, RenderWorld& world, GlSync sync = GlSync::Auto);
  ~GraphExecutor();
  GraphExecutor(const GraphExecutor&) = delete;
  GraphExecutor& operator=(const GraphExecutor&) = delete;

  void runFrame();
  void clearTimings();  // drop warm-up samples

  // What runMeasured did besides its frames.
  struct MeasuredRun {
    double firstFrameMs = 0;  // wall time of the first frame (every node, its GL work included)
    std::map<std::string, double> oneTimeMs;  // RenderWorld::oneTimeMs added during the run
    bool repeatedAFrame = false;              // see runMeasured
    // The first frame against a steady one. Beside the one-time work the world records
    // (firstFrameOneTimeMs), a first frame pays for what no one times: a GL driver compiling
    // each program at its first draw (llvmpipe JITs a shader variant per state there, seconds
    // each with Mesa's shader cache cold, while glLinkProgram took milliseconds), first-touch
    // pages of new buffers, cold caches. firstFrameUnrecordedMs() is that remainder; per node,
    // firstUseMs is the node's own time in the first frame (CPU clock plus its GL completion)
    // less the one-time work it recorded, less its median over the measured frames.
    double firstFrameOneTimeMs = 0;
    double steadyFrameMs = 0;        // median wall time of the measured frames
    std::vector<double> firstUseMs;  // per graph node
    double firstFrameUnrecordedMs() const {
      return firstFrameMs - firstFrameOneTimeMs - steadyFrameMs;
    }
  };
  // Runs `warmup` frames, drops their timings, then `frames` measured ones. A measured frame in
  // which a pass did one-time work for the world (RenderWorld::oneTimeMs grew: a static shadow
  // map, a prefiltered environment; with no warm-up the first frame does) is not a steady
  // frame: its samples are dropped and the measured frames start again, once, so that work is
  // reported apart and never inside a frame median. `onFrame(done, total)` after each frame.
  MeasuredRun runMeasured(int warmup, int frames,
                          const std::function<void(int, int)>& onFrame = nullptr);
  // Reads any GL timer results not read yet (they are read every kQueryBatch frames and here).
  const std::vector<NodeTiming>& timings() const;
  // Wall time of each measured frame, from its first node to its last.
  const std::vector<double>& frameMs() const { return frameMs_; }
  const CpuImage& output(const std::string& resourceName) const;
  GlSync glSync() const { return sync_; }
  // "node (auto: software rasterizer llvmpipe ...)", "frame (asked)": for reports.
  const std::string& glSyncReason() const { return syncReason_; }
  // GlSync::PerFrame: the wait at the end of each measured frame for its GL work, and the CPU
  // time of all threads over it (on llvmpipe, rasterization).
  const std::vector<double>& frameGlWaitMs() const { return frameGlWaitMs_; }
  const std::vector<double>& frameGlWaitCpuMs() const { return frameGlWaitCpuMs_; }

 private:
  friend class ExecutionContext;
  const CompiledGraph& graph_;
  RenderWorld& world_;
  std::unique_ptr<GlBackend> gl_;
  IdVector<PoolSlotId, CpuImage> cpuSlots_;  // empty in GL slots
  IdVector<PoolSlotId, int> glSlots_;        // GlBackend handles; -1 in CPU slots
  // A GL_TIME_ELAPSED query not read yet: its node, query slot and the wall time of its frame
  // (a bound that drops llvmpipe's garbage first-scene values).
  struct PendingQuery {
    std::size_t node, slot;
    double frameMs;
  };
  void readQueries() const;
  mutable std::vector<NodeTiming> timings_;
  mutable std::vector<PendingQuery> pending_;
  std::vector<double> frameMs_;
  std::vector<double> frameGlWaitMs_, frameGlWaitCpuMs_;
  GlSync sync_ = GlSync::PerNode;
  std::string syncReason_;
  // The GL node or transfer whose GL work was issued since the executor last waited for the
  // GL (the wait is charged to it as its completion); none after a wait.
  std::optional<std::size_t> glIssuedBy_;
  Stopwatch glIssuedClock_;  // since glIssuedBy_ returned
  void waitForGl(double* waitMs, double* waitCpuMs);
};

}  // namespace diptych
