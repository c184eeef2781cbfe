#pragma once
// The frame graph compiler: builds passes from a recipe, validates the connections, culls what
// the scene or the requested outputs do not need (each with a reason), orders the rest,
// inserts transfer and default nodes, computes resource lifetimes and assigns pooled storage.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/graph/pass.h"
#include "engine/graph/recipe.h"
#include "engine/graph/registry.h"

namespace diptych {

struct GraphResource {
  std::string name;  // "pass.output"
  ResourceDesc desc;
  PassIndex producer;
  ResourceId previous = kNoResource;  // the input this version modified in place, if any
  int version = 0;
  vec4 fallback{0.f};
  std::vector<PassIndex> readers;  // declared reads
};

struct GraphPass {
  std::string name, type;
  std::unique_ptr<Pass> pass;
  Domain domain = Domain::Cpu;
  std::vector<ResourceId> reads, writes;
  std::vector<ResourceId> glOnlyReads;  // readCompanion(..., glOnly): dropped when on the CPU
  std::vector<SceneNeed> needs;
  bool culled = false;
  std::string cullReason;  // "scene has no transmissive materials", "output not requested"
  std::string placement;   // auto-placed passes: the rule's choice and the bytes it compared
  std::string variant;     // adaptive passes (adaptive_pass.h): what they chose from their readers
  // Optional inputs dropped because their producer was culled for the scene:
  // "albedo <- texture_filtering.albedo (scene has no textured materials)".
  std::vector<std::string> inputsLeftOut;
};

enum class NodeKind { Pass, Readback, Upload, Default };
const char* nodeKindName(NodeKind kind);

// One step of the compiled schedule.
struct GraphNode {
  NodeKind kind = NodeKind::Pass;
  std::string name;  // pass name, or "readback:gbuffer.hits", "default:shadows.visibility"
  Domain domain = Domain::Cpu;
  PassIndex pass;                     // NodeKind::Pass
  ResourceId resource = kNoResource;  // transfers and defaults: what they move or fill
  std::vector<int> storagesRead, storagesWritten;
  // A readback (or default fill) that no pass needs: it exists only because the resource was
  // requested as an output (e.g. compare's per-slot signals).
  bool forOutputOnly = false;
  // GL passes, transfers and GL fills submit GL work, which completes after the node returns.
  bool issuesGlWork() const {
    return domain == Domain::Gl || kind == NodeKind::Readback || kind == NodeKind::Upload;
  }
};

// A physical allocation of one resource in one domain (in-place versions share it).
struct GraphStorage {
  ResourceId resource = kNoResource;  // first version stored here
  Domain domain = Domain::Cpu;
  ResourceDesc desc;
  int firstNode = 0, lastNode = 0;  // lifetime, as schedule indices, inclusive
  PoolSlotId poolSlot;
};

struct PoolSlot {
  Domain domain = Domain::Cpu;
  ResourceDesc desc;
};

class CompiledGraph {
 public:
  std::string recipeFile;
  FrameSettings frame;
  IdVector<PassIndex, GraphPass> passes;
  IdVector<ResourceId, GraphResource> resources;
  std::vector<GraphNode> nodes;  // execution order
  std::vector<GraphStorage> storages;
  IdVector<PoolSlotId, PoolSlot> pool;
  std::vector<ResourceId> outputs;
  std::map<std::pair<ResourceId, Domain>, int> storageOf;

  std::optional<ResourceId> findResource(const std::string& name) const;
  // The storage of `resource` in `domain` (an index into storages); the compiler made one for
  // every resource a node touches, so a missing one is an internal error (DIPTYCH_CHECK).
  int storage(ResourceId resource, Domain domain) const;
  std::size_t bytesWithoutReuse() const;
  std::size_t bytesWithReuse() const;
  bool usesGl() const;
};

// Compiles `recipe` for `scene`. `requestedOutputs` overrides the recipe's outputs when not
// empty. Throws InputError naming the recipe file, pass and resource for every defect.
CompiledGraph compileGraph(const Recipe& recipe, const PassRegistry& registry, const Scene& scene,
                           const FrameSettings& frame,
                           const std::vector<std::string>& requestedOutputs = {});

}  // namespace diptych
