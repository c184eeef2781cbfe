#pragma once
// Scene::environment on the GL side for exact lookups (shaders/gl/scene_environment.glsl): the
// constant, or the lat-long image, or the six cube faces, uploaded once as they are (RGB times
// the intensity, row flips as engine/gl/transfer.h does them). The shader repeats
// sampleEnvironment()'s arithmetic with texelFetch, so a GL pass shows the background the CPU
// passes show. Unlike env_cube/env_sphere/env_equirect (reflection approximations), nothing is
// resampled.
#include "engine/gl/objects.h"
#include "engine/scene/scene.h"

namespace diptych {

class GlEnvironment {
 public:
  explicit GlEnvironment(const Environment& environment);
  // Sets uEnvironmentType/uEnvironmentColor on `program` and binds the texels to
  // UNIT_SCENE_ENVIRONMENT.
  void bind(const gl::Program& program) const;
  int type() const { return type_; }  // a program may take it as SCENE_ENVIRONMENT_TYPE

 private:
  int type_ = 0;  // ENVIRONMENT_* of scene_environment.glsl
  vec3 color_{0.f};
  gl::Texture texels_;  // RGBA32F 2D array: one lat-long layer or six faces; 1x1 for a colour
};

}  // namespace diptych
