#include "engine/graph/graph_builder.h"

#include "engine/core/error.h"
#include "engine/core/known.h"
#include "engine/graph/recipe.h"

namespace diptych {

ResourceId GraphBuilder::resolve(const std::string& slot, Format expected, bool optional) {
  slotsRead_.insert(slot);
  auto it = spec_->inputs.find(slot);
  if (it == spec_->inputs.end()) return kNoResource;
  const std::string& source = it->second;
  const auto found = g_.findResource(source);
  const std::string place = ".inputs." + slot;
  if (!found) {
    const auto [producer, output] = splitResourceName(source, recipe_.file, spec_->place + place);
    std::vector<std::string> written;
    for (const GraphResource& r : g_.resources)
      if (r.name.rfind(producer + ".", 0) == 0) written.push_back(r.name);
    fail(place, "reads '" + source + "', which is never written (pass '" + producer +
                    "' writes: " + (written.empty() ? "nothing" : joinNames(written)) + ")");
  }
  GraphResource& res = g_.resources[*found];
  if (res.desc.format != expected)
    fail(place, "type mismatch: '" + source + "' is " + describe(res.desc) + " but pass type '" +
                    spec_->type + "' reads " + formatName(expected));
  if (res.desc.width != g_.frame.width || res.desc.height != g_.frame.height)
    fail(place, "size mismatch: '" + source + "' is " + describe(res.desc) + ", frame is " +
                    std::to_string(g_.frame.width) + "x" + std::to_string(g_.frame.height));
  // An optional input whose producer the scene left out leaves the frame with it: no default
  // fill, and the consumer runs as if it were not connected (DESIGN.md: leave out of a frame
  // whatever the scene does not need). Setup runs in producer-first order, so the producer's
  // scene culling is already decided. A required input still reads the default fill.
  if (optional && g_.passes[res.producer].culled) {
    g_.passes[pass_].inputsLeftOut.push_back(slot + " <- " + source + " (" +
                                             g_.passes[res.producer].cullReason + ")");
    return kNoResource;
  }
  res.readers.push_back(pass_);
  g_.passes[pass_].reads.push_back(*found);
  return *found;
}
ResourceId GraphBuilder::readCompanion(ResourceId of, const std::string& output, Format expected,
                                       bool glOnly) {
  if (of == kNoResource) return kNoResource;
  const GraphPass& producer = g_.passes[g_.resources[of].producer];
  const auto found = g_.findResource(producer.name + "." + output);
  if (!found) return kNoResource;
  GraphResource& res = g_.resources[*found];
  if (res.desc.format != expected)
    fail("", "reads '" + res.name + "' as " + formatName(expected) + " but it is " +
                 describe(res.desc));
  res.readers.push_back(pass_);
  g_.passes[pass_].reads.push_back(*found);
  if (glOnly) g_.passes[pass_].glOnlyReads.push_back(*found);
  return *found;
}
ResourceId GraphBuilder::write(const std::string& output, const ResourceDesc& desc, vec4 fallback) {
  const std::string name = g_.passes[pass_].name + "." + output;
  if (g_.findResource(name)) fail("", "writes '" + name + "' twice");
  if (desc.width <= 0 || desc.height <= 0 || desc.layers <= 0)
    fail("", "writes '" + name + "' with an empty size " + describe(desc));
  GraphResource res{.name = name, .desc = desc, .producer = pass_, .fallback = fallback};
  const ResourceId id = g_.resources.push_back(res);
  g_.passes[pass_].writes.push_back(id);
  return id;
}
ResourceId GraphBuilder::modify(const std::string& slot, const std::string& output,
                                Format expected) {
  const ResourceId in = read(slot, expected);
  const ResourceId out = write(output, g_.resources[in].desc, g_.resources[in].fallback);
  g_.resources[out].previous = in;
  g_.resources[out].version = g_.resources[in].version + 1;
  return out;
}
void GraphBuilder::fail(const std::string& placeSuffix, const std::string& message) const {
  throw InputError(recipe_.file, spec_->place + placeSuffix,
                   "pass '" + spec_->name + "' (" + spec_->type + "): " + message);
}

}  // namespace diptych
