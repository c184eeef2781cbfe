#pragma once
// The frame graph's OpenGL side: pooled textures, readback/upload transfer nodes, default
// fills and GL_TIME_ELAPSED timing. Needs a current context (engine/gl/context.h).
#include <memory>
#include <string>
#include <vector>

#include "engine/gl/objects.h"
#include "engine/graph/cpu_image.h"

namespace diptych {

class GlBackend {
 public:
  GlBackend();
  ~GlBackend();
  // A texture for `desc` (2D, or a 2D array when layers > 1); returns its handle.
  int createTexture(const ResourceDesc& desc);
  const gl::Texture& texture(int handle) const { return textures_[checked(handle)]; }
  void readback(int handle, CpuImage& into);
  void upload(const CpuImage& from, int handle);
  void fill(int handle, const vec4& value);
  // GL_TIME_ELAPSED query number `slot` (created on first use; the executor gives each node of
  // each frame its own until the results are read) around
  // the node's GL commands. Neither call waits for the GL: the result is read by timerMs.
  void beginTimer(std::size_t slot);
  void endTimer();  // and glFlush: submits the node's commands without waiting
  // The result of query `slot`. Read after the measured frames (or every few frames), when
  // their readbacks have already waited for the GL work, so nothing stalls a frame.
  double timerMs(std::size_t slot) const;
  // Waits until every GL command issued so far has completed (glFinish).
  void finish();

 private:
  std::size_t checked(int handle) const;  // DIPTYCH_CHECK: a handle createTexture returned
  std::vector<gl::Texture> textures_;
  std::vector<ResourceDesc> descs_;
  std::vector<gl::TimerQuery> timers_;
};

gl::TextureFormat toGlFormat(Format format);

}  // namespace diptych
