#include "engine/graph/executor.h"

#include <algorithm>
#include <ctime>
#include <optional>

#include "engine/core/error.h"
#include "engine/core/timing.h"
#include "engine/gl/context.h"
#include "engine/gl/debug.h"
#include "engine/graph/companion.h"
#include "engine/graph/render_world.h"

namespace diptych {
namespace {

// CPU time of every thread of the process (CLOCK_PROCESS_CPUTIME_ID), in ms. Nodes run one at
// a time, so over a CPU node the difference is that node's work on all cores; unlike its wall
// time it hardly grows when other processes load the machine (docs/benchmarks.md, Method).
double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

}  // namespace

// The PassContext of one pass node: resolves handles to pooled storage and refuses any
// resource the pass did not declare in setup.
class ExecutionContext final : public PassContext {
 public:
  ExecutionContext(GraphExecutor& ex, const GraphPass& pass, NodeTiming& timing)
      : ex_(ex), pass_(pass), timing_(timing) {}

  const CpuImage& cpuRead(ResourceId id) override { return cpuSlot(id, false); }
  CpuImage& cpuWrite(ResourceId id) override { return cpuSlot(id, true); }
  const gl::Texture& glTexture(ResourceId id) override {
    return ex_.gl_->texture(ex_.glSlots_[slotOf(id, Domain::Gl, true)]);
  }
  const ResourceDesc& desc(ResourceId id) const override {
    check(id, false);
    return ex_.graph_.resources[id].desc;
  }
  bool consumed(ResourceId id) const override {
    check(id, false);
    const CompiledGraph& g = ex_.graph_;
    if (std::find(g.outputs.begin(), g.outputs.end(), id) != g.outputs.end()) return true;
    for (PassIndex q : g.resources[id].readers)
      if (!g.passes[q].culled) return true;
    return false;
  }
  RenderWorld& world() override { return ex_.world_; }
  const FrameSettings& frame() const override { return ex_.graph_.frame; }
  void count(const std::string& counter, double amount) override {
    timing_.counters[counter] += amount;
  }

 private:
  void check(ResourceId id, bool writing) const {
    const bool valid = ex_.graph_.resources.contains(id);
    const auto& w = pass_.writes;
    const auto& r = pass_.reads;
    const bool declared = valid && (std::find(w.begin(), w.end(), id) != w.end() ||
                                    (!writing && std::find(r.begin(), r.end(), id) != r.end()));
    if (!declared)
      throw Error("pass '" + pass_.name + "' " + (writing ? "wrote" : "read") + " resource '" +
                  (valid ? ex_.graph_.resources[id].name : to_string(id)) +
                  "' without declaring it in setup");
  }
  PoolSlotId slotOf(ResourceId id, Domain domain, bool writing) const {
    const auto& r = pass_.reads;
    check(id, writing && std::find(r.begin(), r.end(), id) == r.end());
    if (pass_.domain != domain)
      throw Error("pass '" + pass_.name + "' runs in the " + domainName(pass_.domain) +
                  " domain but asked for the " + domainName(domain) + " copy of '" +
                  ex_.graph_.resources[id].name + "'");
    return ex_.graph_.storages[ex_.graph_.storage(id, domain)].poolSlot;
  }
  CpuImage& cpuSlot(ResourceId id, bool writing) {
    return ex_.cpuSlots_[slotOf(id, Domain::Cpu, writing)];
  }

  GraphExecutor& ex_;
  const GraphPass& pass_;
  NodeTiming& timing_;
};

std::optional<GlSync> parseGlSync(const std::string& name) {
  if (name == "node") return GlSync::PerNode;
  if (name == "frame") return GlSync::PerFrame;
  if (name == "auto") return GlSync::Auto;
  return std::nullopt;
}

const char* glSyncName(GlSync sync) {
  return sync == GlSync::PerFrame ? "frame" : sync == GlSync::PerNode ? "node" : "auto";
}

namespace {

// Mesa's software rasterizers, by GL_RENDERER ("llvmpipe (LLVM 15.0.6, 256 bits)").
bool softwareRenderer(const std::string& renderer) {
  for (const char* name : {"llvmpipe", "softpipe", "SWR", "Software Rasterizer"})
    if (renderer.find(name) != std::string::npos) return true;
  return false;
}

}  // namespace

GraphExecutor::GraphExecutor(const CompiledGraph& graph, RenderWorld& world, GlSync sync)
    : graph_(graph), world_(world), timings_(graph.nodes.size()), sync_(sync) {
  if (graph.usesGl()) {
    world_.glContext().makeCurrent();
    gl_ = std::make_unique<GlBackend>();
  }
  syncReason_ = std::string(glSyncName(sync)) + " (asked)";
  if (sync == GlSync::Auto) {
    const std::string renderer = gl_ ? world_.glContext().info().renderer : std::string();
    const bool software = !gl_ || softwareRenderer(renderer);
    sync_ = software ? GlSync::PerNode : GlSync::PerFrame;
    syncReason_ = std::string(glSyncName(sync_)) + " (auto: " +
                  (!gl_ ? std::string("no GL work")
                        : (software ? "software rasterizer " : "hardware renderer ") + renderer) +
                  ")";
  }
  for (const PoolSlot& slot : graph.pool) {
    const bool cpu = slot.domain == Domain::Cpu;
    cpuSlots_.push_back(cpu ? CpuImage(slot.desc) : CpuImage());
    glSlots_.push_back(cpu ? -1 : gl_->createTexture(slot.desc));
  }
}

GraphExecutor::~GraphExecutor() {
  // Pooled GL textures must be destroyed while their context is current.
  if (gl_) world_.glContext().makeCurrent();
}

void GraphExecutor::clearTimings() {
  readQueries();  // warm-up queries belong to the warm-up: read them before dropping them
  for (NodeTiming& t : timings_) t = NodeTiming{};
  frameMs_.clear();
  frameGlWaitMs_.clear();
  frameGlWaitCpuMs_.clear();
}

namespace {

// A node's own time in frame f: its CPU clock plus, under GlSync::PerNode, the wait for its
// own GL work to complete (the rasterization on llvmpipe).
double ownMs(const NodeTiming& t, std::size_t f) {
  return t.cpuMs[f] + (f < t.glCompletionMs.size() ? t.glCompletionMs[f] : 0.0);
}

}  // namespace

GraphExecutor::MeasuredRun GraphExecutor::runMeasured(
    int warmup, int frames, const std::function<void(int, int)>& onFrame) {
  MeasuredRun run;
  const std::map<std::string, double> before = world_.oneTimeMs;
  std::vector<double> firstOwnMs(timings_.size());
  int total = warmup + frames;
  for (int f = 0; f < total; ++f) {
    if (f == warmup) clearTimings();
    const std::map<std::string, double> frameBefore = world_.oneTimeMs;
    runFrame();
    if (f == 0) {  // the first frame's samples are each vector's last (none cleared since)
      run.firstFrameMs = frameMs_.back();
      for (std::size_t n = 0; n < timings_.size(); ++n) {
        const NodeTiming& t = timings_[n];
        firstOwnMs[n] = ownMs(t, t.cpuMs.size() - 1) - t.oneTimeMs.back();
        run.firstFrameOneTimeMs += t.oneTimeMs.back();
      }
    }
    if (f >= warmup && world_.oneTimeMs != frameBefore && !run.repeatedAFrame) {
      run.repeatedAFrame = true;
      clearTimings();
      total = f + 1 + frames;
    }
    if (onFrame) onFrame(f + 1, total);
  }
  run.steadyFrameMs = summarize(frameMs_).median;
  for (std::size_t n = 0; n < timings_.size(); ++n) {
    std::vector<double> own;
    for (std::size_t f = 0; f < timings_[n].cpuMs.size(); ++f) own.push_back(ownMs(timings_[n], f));
    run.firstUseMs.push_back(firstOwnMs[n] - summarize(own).median);
  }
  for (const auto& [what, ms] : world_.oneTimeMs) {
    const auto it = before.find(what);
    const double paid = ms - (it == before.end() ? 0.0 : it->second);
    if (paid > 0) run.oneTimeMs[what] = paid;
  }
  return run;
}

const std::vector<NodeTiming>& GraphExecutor::timings() const {
  readQueries();
  return timings_;
}

// Frames between reads of the pending GL timer results: the frames' readbacks have waited for
// the GL work long before, so the read does not stall; it only bounds the number of queries.
constexpr std::size_t kQueryBatch = 16;

void GraphExecutor::readQueries() const {
  // A node's GL time lies inside its frame, so it cannot exceed the frame's wall clock:
  // llvmpipe returns a garbage value (an absolute timestamp) for a query started before its
  // first scene, which this bound drops. Query names belong to the executor's context, which
  // need not be current when the timings are asked for.
  if (pending_.empty()) return;
  world_.glContext().makeCurrent();
  for (const PendingQuery& q : pending_) {
    const double ms = gl_->timerMs(q.slot);
    if (ms >= 0.0 && ms <= q.frameMs) timings_[q.node].gpuMs.push_back(ms);
  }
  pending_.clear();
}

// Waits for the GL work issued since the last wait; its wall and CPU time go to the node that
// issued it (glCompletion*) and, when asked, to the caller (the next node's glWait*).
void GraphExecutor::waitForGl(double* waitMs, double* waitCpuMs) {
  if (!glIssuedBy_) return;
  timings_[*glIssuedBy_].glOverlapMs.push_back(glIssuedClock_.milliseconds());
  Stopwatch wait;
  const double cpuStart = processCpuMs();
  gl_->finish();
  const double ms = wait.milliseconds(), cpu = processCpuMs() - cpuStart;
  timings_[*glIssuedBy_].glCompletionMs.push_back(ms);
  timings_[*glIssuedBy_].glCompletionCpuMs.push_back(cpu);
  glIssuedBy_.reset();
  if (waitMs) *waitMs = ms;
  if (waitCpuMs) *waitCpuMs = cpu;
}

void GraphExecutor::runFrame() {
  // Attribution (docs/frame-graph.md, Timing): a GL node's GL work is its own GL_TIME_ELAPSED
  // query, read after the measured frames (no node waits on a query). With GlSync::PerNode,
  // before a GL node or transfer starts its clocks, the executor waits for the GL work earlier
  // nodes issued and records that wait apart (glWaitMs, and its CPU time glWaitCpuMs; charged
  // to the issuing node as glCompletion*): without it, llvmpipe's compute dispatches and every
  // readback, which synchronise, carried the earlier passes' GL work in their CPU time. CPU
  // nodes do not wait, so GL work still overlaps them. With PerFrame, one wait at the end.
  Stopwatch frameClock;
  world_.beginFrame();
  std::vector<PendingQuery> frameQueries;
  bool glFramePending = false;  // GL work issued in this frame (GlSync::PerFrame)
  for (std::size_t n = 0; n < graph_.nodes.size(); ++n) {
    const GraphNode& node = graph_.nodes[n];
    NodeTiming& timing = timings_[n];
    timing.counters.clear();
    const bool glWork = node.issuesGlWork();
    std::optional<gl::ScopedGlLabel> label;
    if (glWork) {
      if (sync_ == GlSync::PerNode) {
        double waitMs = 0, waitCpuMs = 0;
        waitForGl(&waitMs, &waitCpuMs);
        timing.glWaitMs.push_back(waitMs);
        timing.glWaitCpuMs.push_back(waitCpuMs);
      }
      label.emplace(node.name);
      const std::size_t slot = pending_.size() + frameQueries.size();
      gl_->beginTimer(slot);
      frameQueries.push_back({n, slot, 0.0});
    }
    Stopwatch clock;
    const double cpuStart = processCpuMs();
    const double oneTimeBefore = world_.oneTimeTotalMs();
    auto slotOf = [&](int storage) { return graph_.storages[storage].poolSlot; };
    switch (node.kind) {
      case NodeKind::Pass: {
        ExecutionContext context(*this, graph_.passes[node.pass], timing);
        graph_.passes[node.pass].pass->execute(context);
        break;
      }
      case NodeKind::Readback:
        gl_->readback(glSlots_[slotOf(node.storagesRead[0])],
                      cpuSlots_[slotOf(node.storagesWritten[0])]);
        break;
      case NodeKind::Upload:
        gl_->upload(cpuSlots_[slotOf(node.storagesRead[0])],
                    glSlots_[slotOf(node.storagesWritten[0])]);
        break;
      case NodeKind::Default: {
        const GraphResource& res = graph_.resources[node.resource];
        const PoolSlotId slot = slotOf(node.storagesWritten[0]);
        if (node.domain == Domain::Cpu)
          cpuSlots_[slot].fill(res.fallback);
        else
          gl_->fill(glSlots_[slot], res.fallback);
        break;
      }
    }
    if (glWork) {
      gl_->endTimer();
      if (sync_ == GlSync::PerNode) {
        glIssuedBy_ = n;
        glIssuedClock_.restart();
      }
      glFramePending = true;
    }
    timing.cpuMs.push_back(clock.milliseconds());
    timing.processCpuMs.push_back(processCpuMs() - cpuStart);
    timing.oneTimeMs.push_back(world_.oneTimeTotalMs() - oneTimeBefore);
    // A readback returns with its work done (it copies into client memory): nothing of it is
    // pending beside the CPU nodes after it. Outside its clocks, like every completion.
    if (node.kind == NodeKind::Readback) waitForGl(nullptr, nullptr);
  }
  // The frame's GL work completes inside it: per node, charged to the last GL node; per frame,
  // as the frame's own wait.
  waitForGl(nullptr, nullptr);
  if (sync_ == GlSync::PerFrame && glFramePending) {
    Stopwatch wait;
    const double cpuStart = processCpuMs();
    gl_->finish();
    frameGlWaitMs_.push_back(wait.milliseconds());
    frameGlWaitCpuMs_.push_back(processCpuMs() - cpuStart);
  }
  frameMs_.push_back(frameClock.milliseconds());
  for (PendingQuery& q : frameQueries) q.frameMs = frameMs_.back();
  pending_.insert(pending_.end(), frameQueries.begin(), frameQueries.end());
  if (!pending_.empty() && pending_.size() >= kQueryBatch * frameQueries.size()) readQueries();
}

const CpuImage& GraphExecutor::output(const std::string& name) const {
  const auto id = graph_.findResource(name);
  if (!id || std::find(graph_.outputs.begin(), graph_.outputs.end(), *id) == graph_.outputs.end())
    throw Error("'" + name + "' is not a requested output of this graph");
  return cpuSlots_[graph_.storages[graph_.storage(*id, Domain::Cpu)].poolSlot];
}

}  // namespace diptych
