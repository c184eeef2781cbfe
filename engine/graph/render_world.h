#pragma once
// Per-scene state shared by the passes of a frame: the scene, its world-space triangles, and
// the Embree scene and GL buffers built from them on first use (so a frame that needs no ray
// tracing never builds a BVH, and a CPU-only frame never touches OpenGL).
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <typeindex>

#include "engine/core/timing.h"
#include "engine/rt/rt_device.h"
#include "engine/rt/rt_scene.h"
#include "engine/scene/scene.h"
#include "engine/scene/world_geometry.h"

namespace diptych {

namespace gl {
class GlContext;
struct GlSceneBuffers;
struct GlShadingBuffers;
struct ForwardScene;
}  // namespace gl

class RenderWorld {
 public:
  // `context` may be null for CPU-only frames; it must outlive this object.
  explicit RenderWorld(const Scene& scene, gl::GlContext* context = nullptr);
  ~RenderWorld();
  const Scene& scene() const { return scene_; }
  const WorldGeometry& geometry() const { return world_; }
  // Embree BVH, built on the first call; safe to call from several threads at once (the
  // first builds it, the others wait), e.g. from inside a TBB loop.
  const RtScene& rtScene();
  const gl::GlSceneBuffers& glScene();  // uploaded on first call; needs a context
  // Materials, lights, instances and alpha masks, uploaded on first call; with `textures`, also
  // every scene texture with its mip chain, uploaded on the first call that asks. Only the
  // G-buffer asks without: the hybrid frame's visibility buffer reads no texture, so it never
  // pays their upload (DamagedHelmet: 1.2-1.4 s and 427 MB of RGBA32F levels on llvmpipe).
  const gl::GlShadingBuffers& glShading(bool textures = true);
  gl::GlContext& glContext();  // throws Error when there is none
  // The scene with its GL buffers, what gl::ForwardRenderer draws (uploads on first call).
  gl::ForwardScene forwardScene();

  // Work done once per world, not per frame, in ms: the world's own first-use builds (kBvhBuild,
  // kGlSceneUpload, kGlShadingUpload, kGlTextureUpload, kGlSetup) and what passes build once
  // ("env_cube prefilter", "shadow_map build"). Reports show it beside the per-frame medians, never
  // inside them: GraphExecutor::runMeasured measures again a frame in which it grew.
  std::map<std::string, double> oneTimeMs;
  static constexpr const char* kBvhBuild = "embree device and BVH build";
  static constexpr const char* kGlSceneUpload = "gl scene upload";
  // Materials, lights, instances, alpha masks (gl::uploadShading).
  static constexpr const char* kGlShadingUpload = "gl shading upload";
  // Every scene texture with its mip chain (gl::uploadTextures).
  static constexpr const char* kGlTextureUpload = "gl texture upload";
  // glCached objects: programs compiled, framebuffers and renderers created.
  static constexpr const char* kGlSetup = "gl programs and targets";
  // Adds to oneTimeMs[what]; safe from any thread (rtScene() may first run inside a TBB loop).
  // Every writer goes through it.
  void addOneTime(const std::string& what, double ms);
  double oneTimeTotalMs() const;  // the sum of oneTimeMs, read under the same lock

  // One T per world (a compiled program, a framebuffer...), built on first use with the context
  // current and destroyed with it current. Passes keep GL state here, never in themselves,
  // because a compiled graph may outlive the context it ran on.
  // Its construction is timed as kGlSetup.
  template <class T>
  T& glCached() {
    auto& slot = glCache_[std::type_index(typeid(T))];
    if (!slot) {
      const Stopwatch clock;
      makeContextCurrent();
      slot = std::make_shared<T>();
      addOneTime(kGlSetup, clock.milliseconds());
    }
    return *static_cast<T*>(slot.get());
  }

  // Frames begun on this world (GraphExecutor::runFrame). Per-frame products (cpuCached) compare
  // it, so that each frame pays for its own as it would with a moving camera: a product kept
  // across frames of a still camera would leave its cost out of every timed frame.
  void beginFrame() { ++frameSerial_; }
  std::uint64_t frameSerial() const { return frameSerial_; }

  // One T per world for CPU products the passes of a frame share (the exact-hit buffer,
  // passes/common/exact_hits.h): built empty on first use; T decides when its contents are stale.
  template <class T>
  T& cpuCached() {
    const std::lock_guard lock(cpuCacheMutex_);
    auto& slot = cpuCache_[std::type_index(typeid(T))];
    if (!slot) slot = std::make_shared<T>();
    return *static_cast<T*>(slot.get());
  }

 private:
  void makeContextCurrent();
  std::uint64_t frameSerial_ = 0;
  const Scene& scene_;
  WorldGeometry world_;
  gl::GlContext* context_ = nullptr;
  std::unique_ptr<RtDevice> device_;
  std::unique_ptr<RtScene> rt_;
  std::once_flag rtOnce_;
  std::unique_ptr<gl::GlSceneBuffers> glScene_;
  std::unique_ptr<gl::GlShadingBuffers> glShading_;
  bool glTexturesUploaded_ = false;
  std::map<std::type_index, std::shared_ptr<void>> glCache_;
  std::map<std::type_index, std::shared_ptr<void>> cpuCache_;
  std::mutex cpuCacheMutex_;
  mutable std::mutex oneTimeMutex_;
};

}  // namespace diptych
