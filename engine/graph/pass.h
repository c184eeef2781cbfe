#pragma once
// A frame-graph pass: setup() declares what it reads, writes and needs from the scene;
// execute() does the work in its domain (GL on the context, or CPU with Embree/TBB).
// A pass type is a class deriving from Pass (with a static schema() when it has parameters)
// plus one entry in passes/registry.cpp; a technique-slot producer also names its slot there
// and declares its G-buffer input and signal output with slotIo() (passes/slots.h).
// docs/architecture.md, "Adding a producer", walks through one.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/graph/cpu_image.h"
#include "engine/graph/ids.h"
#include "engine/graph/params.h"
#include "engine/graph/resource.h"
#include "engine/graph/scene_needs.h"
#include "engine/scene/scene.h"

namespace diptych {

class RenderWorld;  // engine/graph/render_world.h: scene, world geometry, Embree and GL caches
namespace gl {
class Texture;
}

struct FrameSettings {
  int width = 640, height = 480;
  Camera camera;
};

class PassBuilder {
 public:
  virtual ~PassBuilder() = default;
  // Reads the resource connected to input `slot` in the recipe. Errors name the pass and slot
  // when the slot is unconnected, the producer never writes it, or the format differs.
  [[nodiscard]] virtual ResourceId read(const std::string& slot, Format expected) = 0;
  // Like read(), but an unconnected slot yields kNoResource instead of an error, and so does a
  // slot whose producer the scene culled (the input leaves the frame; no default fill): the
  // pass must treat kNoResource as its input's fallback.
  [[nodiscard]] virtual ResourceId readOptional(const std::string& slot, Format expected) = 0;
  // Declares a new resource "<pass>.<output>". `fallback` is what consumers read when this pass
  // is culled because the scene lacks something it needs.
  [[nodiscard]] virtual ResourceId write(const std::string& output, const ResourceDesc& desc,
                                         vec4 fallback) = 0;
  // Writes a new version of an input in place ("versioned on write"); same storage, new handle.
  [[nodiscard]] virtual ResourceId modify(const std::string& slot, const std::string& output,
                                          Format expected) = 0;
  virtual void needs(SceneNeed need) = 0;
  // Reads the output `output` of the pass that wrote `of`, without a recipe connection
  // (companion.h says when and why); kNoResource outside the frame graph's compiler.
  [[nodiscard]] virtual ResourceId readCompanion(ResourceId /*of*/, const std::string& /*output*/,
                                                 Format /*expected*/, bool /*glOnly*/) {
    return kNoResource;
  }

  virtual const Scene& scene() const = 0;
  virtual const FrameSettings& frame() const = 0;
  virtual const PassParams& params() const = 0;
};

class PassContext {
 public:
  virtual ~PassContext() = default;
  virtual const CpuImage& cpuRead(ResourceId id) = 0;
  virtual CpuImage& cpuWrite(ResourceId id) = 0;
  virtual const gl::Texture& glTexture(ResourceId id) = 0;  // GL-domain passes, read or write
  virtual const ResourceDesc& desc(ResourceId id) const = 0;
  virtual RenderWorld& world() = 0;
  virtual const FrameSettings& frame() const = 0;
  // Work counters a pass reports (e.g. "rays"); summed into the timing table and exports.
  virtual void count(const std::string& counter, double amount) = 0;
  // Whether a live pass reads `id` or the frame outputs it (companion.h); true outside the frame
  // graph's executor, which is the safe answer: the output is written.
  virtual bool consumed(ResourceId /*id*/) const { return true; }
};

class Pass {
 public:
  virtual ~Pass() = default;
  virtual Domain domain() const = 0;
  virtual void setup(PassBuilder& builder) = 0;
  virtual void execute(PassContext& context) = 0;
  // Whether this pass reads the triangle a G-buffer hits texel names (the tessellation itself),
  // not only the surface point it stands for: the G-buffer then draws analytic spheres as
  // triangles, never as ray-cast impostors (passes/raster/gbuffer.h). Only wag_shadows does.
  virtual bool readsHitTriangles() const { return false; }
};

}  // namespace diptych
