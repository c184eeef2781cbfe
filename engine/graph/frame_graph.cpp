#include "engine/graph/frame_graph.h"

#include <algorithm>
#include <functional>
#include <set>

#include "engine/core/check.h"
#include "engine/core/error.h"
#include "engine/core/known.h"
#include "engine/graph/graph_builder.h"
#include "engine/graph/placement.h"

namespace diptych {

const char* nodeKindName(NodeKind kind) {
  switch (kind) {
    case NodeKind::Pass:
      return "pass";
    case NodeKind::Readback:
      return "readback";
    case NodeKind::Upload:
      return "upload";
    case NodeKind::Default:
      return "default";
  }
  return "?";
}

std::optional<ResourceId> CompiledGraph::findResource(const std::string& name) const {
  for (ResourceId id : resources.ids())
    if (resources[id].name == name) return id;
  return std::nullopt;
}

int CompiledGraph::storage(ResourceId resource, Domain domain) const {
  const auto it = storageOf.find({resource, domain});
  DIPTYCH_CHECK(it != storageOf.end(), "no " + std::string(domainName(domain)) +
                                           " storage for resource " + to_string(resource));
  return it->second;
}

std::size_t CompiledGraph::bytesWithoutReuse() const {
  std::size_t total = 0;
  for (const GraphStorage& s : storages) total += s.desc.bytes();
  return total;
}

std::size_t CompiledGraph::bytesWithReuse() const {
  std::size_t total = 0;
  for (const PoolSlot& p : pool) total += p.desc.bytes();
  return total;
}

bool CompiledGraph::usesGl() const {
  for (const GraphNode& n : nodes)
    if (n.issuesGlWork()) return true;
  return false;
}

namespace {

// Orders recipe passes so that producers come before consumers; reports a cycle by its path.
// Pass k of the recipe is CompiledGraph::passes[PassIndex(k)].
std::vector<PassIndex> setupOrder(const Recipe& recipe) {
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < recipe.passes.size(); ++i) index[recipe.passes[i].name] = int(i);
  std::vector<std::vector<std::pair<int, std::string>>> deps(recipe.passes.size());
  for (std::size_t i = 0; i < recipe.passes.size(); ++i) {
    for (const auto& [slot, source] : recipe.passes[i].inputs) {
      const std::string place = recipe.passes[i].place + ".inputs." + slot;
      const auto [producer, output] = splitResourceName(source, recipe.file, place);
      auto it = index.find(producer);
      if (it == index.end())
        throw InputError(recipe.file, place,
                         "pass '" + recipe.passes[i].name + "' reads '" + source +
                             "', but no pass is named '" + producer + "'");
      deps[i].push_back({it->second, source});
    }
  }
  std::vector<PassIndex> order;
  std::vector<int> state(recipe.passes.size(), 0);  // 0 new, 1 on stack, 2 done
  std::vector<int> stack;
  std::function<void(int)> visit = [&](int p) {
    if (state[p] == 2) return;
    if (state[p] == 1) {
      std::string path;
      auto from = std::find(stack.begin(), stack.end(), p);
      for (auto it = from; it != stack.end(); ++it) path += recipe.passes[*it].name + " -> ";
      throw InputError(recipe.file, recipe.passes[p].place,
                       "cycle in the frame graph: " + path + recipe.passes[p].name);
    }
    state[p] = 1;
    stack.push_back(p);
    for (const auto& [producer, source] : deps[p]) visit(producer);
    stack.pop_back();
    state[p] = 2;
    order.push_back(PassIndex(p));
  };
  for (std::size_t i = 0; i < recipe.passes.size(); ++i) visit(int(i));
  return order;
}

// Marks passes no requested output needs; scene-culled passes do not pull in their inputs.
void cullUnrequested(CompiledGraph& g) {
  std::set<PassIndex> live;
  std::vector<PassIndex> work;
  for (ResourceId out : g.outputs) work.push_back(g.resources[out].producer);
  while (!work.empty()) {
    const PassIndex p = work.back();
    work.pop_back();
    if (live.count(p) || g.passes[p].culled) continue;
    live.insert(p);
    for (ResourceId r : g.passes[p].reads) work.push_back(g.resources[r].producer);
  }
  for (PassIndex p : g.passes.ids()) {
    if (!live.count(p) && !g.passes[p].culled) {
      g.passes[p].culled = true;
      g.passes[p].cullReason = "output not requested";
    }
  }
}

// The order live passes run in: dependency order, and among the passes whose inputs are all
// produced, GL passes first (then setup order). GL work is submitted without waiting for it, so
// a GL pass issued before independent CPU passes runs while they do (on a GPU, in parallel;
// on llvmpipe, on its rasterizer threads); issued after them, it would find the CPU idle
// waiting for it. This is list scheduling with the longest-latency work first.
std::vector<PassIndex> issueOrder(const CompiledGraph& g, const std::vector<PassIndex>& order) {
  std::vector<PassIndex> pending, issued;
  for (PassIndex p : order)
    if (!g.passes[p].culled) pending.push_back(p);
  std::set<PassIndex> done;
  auto ready = [&](PassIndex p) {
    for (ResourceId r : g.passes[p].reads) {
      const PassIndex producer = g.resources[r].producer;
      if (!g.passes[producer].culled && !done.count(producer)) return false;
    }
    return true;
  };
  while (!pending.empty()) {
    // `order` is topological, so its first pending pass is always ready.
    auto next = std::find_if(pending.begin(), pending.end(), [&](PassIndex p) {
      return g.passes[p].domain == Domain::Gl && ready(p);
    });
    if (next == pending.end()) next = pending.begin();
    issued.push_back(*next);
    done.insert(*next);
    pending.erase(next);
  }
  return issued;
}

// Emits the schedule: live passes in issue order, transfers and defaults just before the first
// node that needs them, and a readback at the end for every requested output that lives on the
// GPU. Except: before a GL pass is issued, the readbacks that the CPU passes whose producers have
// all run already need are done first. The executor waits for all earlier GL work before a
// transfer (executor.cpp), so such a readback placed after the GL pass, before its first CPU
// reader, would wait for that pass too, and the CPU passes could not run beside its GL work.
void schedule(CompiledGraph& g, const std::vector<PassIndex>& order) {
  auto storageFor = [&](ResourceId r, Domain d) {
    auto key = std::make_pair(r, d);
    auto it = g.storageOf.find(key);
    if (it != g.storageOf.end()) return it->second;
    g.storages.push_back({.resource = r, .domain = d, .desc = g.resources[r].desc});
    return g.storageOf[key] = int(g.storages.size() - 1);
  };
  auto producerLive = [&](ResourceId r) { return !g.passes[g.resources[r].producer].culled; };
  // Makes resource r available in domain d, scheduling a transfer or default fill if needed.
  std::function<int(ResourceId, Domain)> ensure = [&](ResourceId r, Domain d) -> int {
    auto existing = g.storageOf.find({r, d});
    if (existing != g.storageOf.end()) return existing->second;
    GraphNode node;
    node.resource = r;
    node.domain = d;
    if (!producerLive(r)) {
      node.kind = NodeKind::Default;
      node.name = "default:" + g.resources[r].name;
    } else {
      const Domain home = g.passes[g.resources[r].producer].domain;
      node.kind = d == Domain::Cpu ? NodeKind::Readback : NodeKind::Upload;
      node.name = std::string(nodeKindName(node.kind)) + ":" + g.resources[r].name;
      node.storagesRead.push_back(g.storage(r, home));
    }
    const int s = storageFor(r, d);
    node.storagesWritten.push_back(s);
    g.nodes.push_back(node);
    return s;
  };
  const std::vector<PassIndex> issued = issueOrder(g, order);
  std::set<PassIndex> done;
  auto producerDone = [&](ResourceId r) {
    const PassIndex producer = g.resources[r].producer;
    return g.passes[producer].culled || done.count(producer) > 0;
  };
  for (std::size_t i = 0; i < issued.size(); ++i) {
    const PassIndex p = issued[i];
    GraphPass& pass = g.passes[p];
    for (std::size_t later = i + 1; pass.domain == Domain::Gl && later < issued.size(); ++later) {
      const GraphPass& cpuPass = g.passes[issued[later]];
      if (cpuPass.domain != Domain::Cpu ||
          !std::all_of(cpuPass.reads.begin(), cpuPass.reads.end(), producerDone))
        continue;
      for (ResourceId r : cpuPass.reads)
        if (producerLive(r) && g.passes[g.resources[r].producer].domain == Domain::Gl)
          ensure(r, Domain::Cpu);
    }
    GraphNode node{.kind = NodeKind::Pass, .name = pass.name, .domain = pass.domain, .pass = p};
    for (ResourceId r : pass.reads) node.storagesRead.push_back(ensure(r, pass.domain));
    for (ResourceId w : pass.writes) {
      const ResourceId prev = g.resources[w].previous;
      if (prev != kNoResource) {
        // In-place version: shares the storage of the input it modifies.
        const int s = g.storage(prev, pass.domain);
        g.storageOf[{w, pass.domain}] = s;
        node.storagesWritten.push_back(s);
      } else {
        node.storagesWritten.push_back(storageFor(w, pass.domain));
      }
    }
    g.nodes.push_back(node);
    done.insert(p);
  }
  for (ResourceId out : g.outputs) {
    const std::size_t before = g.nodes.size();
    ensure(out, Domain::Cpu);
    if (g.nodes.size() > before) g.nodes.back().forOutputOnly = true;
  }
}

// A resource modified in place must have no other reader: it would see the new contents.
void checkInPlaceWrites(const CompiledGraph& g, const Recipe& recipe) {
  for (const GraphResource& r : g.resources) {
    if (r.previous == kNoResource) continue;
    const GraphResource& in = g.resources[r.previous];
    if (in.readers.size() > 1)
      throw InputError(recipe.file, "",
                       "'" + in.name + "' is modified in place by pass '" +
                           g.passes[r.producer].name + "' but is also read by another pass");
  }
}

void computeLifetimesAndPool(CompiledGraph& g) {
  for (GraphStorage& s : g.storages) s.firstNode = int(g.nodes.size()), s.lastNode = -1;
  for (std::size_t n = 0; n < g.nodes.size(); ++n) {
    for (int s : g.nodes[n].storagesWritten) {
      g.storages[s].firstNode = std::min(g.storages[s].firstNode, int(n));
      g.storages[s].lastNode = std::max(g.storages[s].lastNode, int(n));
    }
    for (int s : g.nodes[n].storagesRead)
      g.storages[s].lastNode = std::max(g.storages[s].lastNode, int(n));
  }
  for (ResourceId out : g.outputs)
    g.storages[g.storage(out, Domain::Cpu)].lastNode = int(g.nodes.size());
  // Greedy interval assignment in order of first use: reuse a slot of the same domain and
  // description whose previous tenant is dead before this one is born.
  std::vector<int> byStart(g.storages.size());
  for (std::size_t i = 0; i < byStart.size(); ++i) byStart[i] = int(i);
  std::sort(byStart.begin(), byStart.end(),
            [&](int a, int b) { return g.storages[a].firstNode < g.storages[b].firstNode; });
  std::vector<int> slotFreeAfter;  // index PoolSlotId::value
  for (int s : byStart) {
    GraphStorage& st = g.storages[s];
    for (PoolSlotId slot : g.pool.ids()) {
      if (g.pool[slot].domain == st.domain && g.pool[slot].desc == st.desc &&
          slotFreeAfter[std::size_t(slot.value)] < st.firstNode) {
        st.poolSlot = slot;
        break;
      }
    }
    if (!st.poolSlot.valid()) {
      st.poolSlot = g.pool.push_back({st.domain, st.desc});
      slotFreeAfter.push_back(-1);
    }
    slotFreeAfter[std::size_t(st.poolSlot.value)] = st.lastNode;
  }
}

// Old spellings of renamed outputs (PassRegistry::addRenamedOutput) are errors giving the new.
void rejectRenamed(const Recipe& recipe, const PassRegistry& registry) {
  std::map<std::string, std::string> typeOf;
  for (const RecipePass& p : recipe.passes) typeOf[p.name] = p.type;
  auto renamedAt = [&](const std::string& source) -> const RenamedOutput* {
    const auto dot = source.find('.');
    if (dot == std::string::npos) return nullptr;
    const auto type = typeOf.find(source.substr(0, dot));
    if (type == typeOf.end()) return nullptr;
    const std::string output = source.substr(dot + 1);
    for (const RenamedOutput& r : registry.renamedOutputs())
      if (r.passType == type->second && (output == r.old || output == r.renamed)) return &r;
    return nullptr;
  };
  for (const RecipePass& p : recipe.passes)
    for (const auto& [input, source] : p.inputs) {
      const RenamedOutput* r = renamedAt(source);
      if (!r) continue;
      const std::string producer = source.substr(0, source.find('.'));
      if (source == producer + "." + r->old)
        throw InputError(recipe.file, p.place + ".inputs." + input,
                         "'" + source + "' is now called '" + producer + "." + r->renamed + "'");
      if (input == r->old)
        throw InputError(recipe.file, p.place + ".inputs." + input,
                         "the input '" + r->old + "' is now called '" + r->renamed + "'");
    }
  for (const std::string& output : recipe.outputs)
    if (const RenamedOutput* r = renamedAt(output); r && output.ends_with("." + r->old))
      throw InputError(recipe.file, "outputs",
                       "'" + output + "' is now called '" +
                           output.substr(0, output.size() - r->old.size()) + r->renamed + "'");
}

}  // namespace

CompiledGraph compileGraph(const Recipe& recipe, const PassRegistry& registry, const Scene& scene,
                           const FrameSettings& frame,
                           const std::vector<std::string>& requestedOutputs) {
  CompiledGraph g;
  g.recipeFile = recipe.file;
  g.frame = frame;
  rejectRenamed(recipe, registry);
  const std::vector<PassIndex> order = setupOrder(recipe);

  for (const RecipePass& spec : recipe.passes) {
    const PassTypeInfo* info = registry.find(spec.type);
    if (!info)
      throw InputError(recipe.file, spec.place + ".type",
                       unknownName("pass type", spec.type, registry.names()));
    GraphPass pass{.name = spec.name, .type = spec.type, .pass = info->create()};
    pass.domain = pass.pass->domain();
    g.passes.push_back(std::move(pass));
  }

  GraphBuilder builder(g, recipe, scene);
  for (PassIndex p : order) {
    const RecipePass& spec = recipe.passes[std::size_t(p.value)];
    const PassParams params(spec.params, registry.find(spec.type)->params, spec.type, recipe.file,
                            spec.place + ".params");
    builder.bind(p, &spec, &params);
    g.passes[p].pass->setup(builder);
    g.passes[p].domain = g.passes[p].pass->domain();  // a parameter may choose it
    params.checkAllRead();
    for (const auto& [slot, source] : spec.inputs)
      if (!builder.slotsRead().count(slot))
        builder.fail(".inputs." + slot, "'" + slot + "' is not an input of this pass type");
    for (SceneNeed need : g.passes[p].needs) {
      if (!sceneSatisfies(scene, need)) {
        g.passes[p].culled = true;
        g.passes[p].cullReason = missingReason(need);
        break;
      }
    }
  }
  checkInPlaceWrites(g, recipe);

  const std::vector<std::string>& wanted =
      requestedOutputs.empty() ? recipe.outputs : requestedOutputs;
  for (const std::string& name : wanted) {
    const auto id = g.findResource(name);
    if (!id) {
      std::vector<std::string> written;
      for (const GraphResource& r : g.resources) written.push_back(r.name);
      throw InputError(
          recipe.file, "outputs",
          "output '" + name + "' is never written (written: " + joinNames(written) + ")");
    }
    g.outputs.push_back(*id);
  }
  cullUnrequested(g);
  placeAutoPasses(g, order);
  dropGlOnlyReads(g);
  adaptPasses(g);
  schedule(g, order);
  computeLifetimesAndPool(g);
  return g;
}

}  // namespace diptych
