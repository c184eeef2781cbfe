#pragma once
// Reflection-slot producers that look the environment up along r = reflect(-v, n_shading) at
// every reflective G-buffer pixel (docs/environment-maps.md). They approximate L_refl by the
// environment at infinity: no local geometry, no self-reflection, no parallax.
//   env_cube.h      GL cube map (seamless), the scene's faces or the environment resampled
//   env_sphere.h    GL_SPHERE_MAP-style sphere map in the camera's eye frame
//   env_equirect.h  lat-long panorama, the scene's image or the environment resampled
#include "engine/graph/pass.h"
#include "passes/slots.h"

namespace diptych {

enum class EnvMapKind { Cube, Sphere, Equirect };

class EnvReflectionPass : public Pass {
 public:
  explicit EnvReflectionPass(EnvMapKind kind) : kind_(kind) {}
  static ParamSchema schema(EnvMapKind kind);
  Domain domain() const override { return Domain::Gl; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

 private:
  EnvMapKind kind_;
  int resolution_ = 0;
  bool prefilter_ =
      false;  // GGX-prefiltered levels (env_prefilter.h), when a glTF lobe wants them  // texels of
              // a resampled map (cube face side, sphere side, lat-long height)
  SlotIo io_;
  ResourceId surface_ = kNoResource;
};

}  // namespace diptych
