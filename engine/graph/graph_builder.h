#pragma once
// The PassBuilder the frame-graph compiler binds to each pass in turn while it runs the passes'
// setup (frame_graph.cpp, compileGraph): it resolves recipe connections into resources, checks
// formats and sizes, and records reads and writes on the CompiledGraph. Internal to engine/graph.
#include <set>
#include <string>

#include "engine/graph/frame_graph.h"

namespace diptych {

class GraphBuilder final : public PassBuilder {
 public:
  GraphBuilder(CompiledGraph& g, const Recipe& r, const Scene& s) : g_(g), recipe_(r), scene_(s) {}

  void bind(PassIndex passIndex, const RecipePass* spec, const PassParams* params) {
    pass_ = passIndex;
    spec_ = spec;
    params_ = params;
    slotsRead_.clear();
  }
  const std::set<std::string>& slotsRead() const { return slotsRead_; }

  ResourceId read(const std::string& slot, Format expected) override {
    const ResourceId id = resolve(slot, expected, false);
    if (id == kNoResource) fail(".inputs." + slot, "input '" + slot + "' is not connected");
    return id;
  }

  ResourceId readOptional(const std::string& slot, Format expected) override {
    return resolve(slot, expected, true);
  }

  ResourceId readCompanion(ResourceId of, const std::string& output, Format expected,
                           bool glOnly) override;

  ResourceId write(const std::string& output, const ResourceDesc& desc, vec4 fallback) override;

  ResourceId modify(const std::string& slot, const std::string& output, Format expected) override;

  void needs(SceneNeed need) override { g_.passes[pass_].needs.push_back(need); }
  const Scene& scene() const override { return scene_; }
  const FrameSettings& frame() const override { return g_.frame; }
  const PassParams& params() const override { return *params_; }

  [[noreturn]] void fail(const std::string& placeSuffix, const std::string& message) const;

 private:
  ResourceId resolve(const std::string& slot, Format expected, bool optional);

  CompiledGraph& g_;
  const Recipe& recipe_;
  const Scene& scene_;
  PassIndex pass_;
  const RecipePass* spec_ = nullptr;
  const PassParams* params_ = nullptr;
  std::set<std::string> slotsRead_;
};

}  // namespace diptych
