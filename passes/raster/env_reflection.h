#pragma once
// Reflection-slot producers that look the environment up along r = reflect(-v, n_shading) at
// every reflective G-buffer pixel (docs/environment-maps.md). They approximate L_refl by the
// environment at infinity: no local geometry, no self-reflection, no parallax.
//   env_cube      GL cube map (seamless), the scene's faces or the environment resampled
//   env_sphere    GL_SPHERE_MAP-style sphere map in the camera's eye frame
//   env_equirect  lat-long panorama, the scene's image or the environment resampled
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
  int resolution_ = 0;  // texels of a resampled map (cube face side, sphere side, lat-long height)
  SlotIo io_;
};

class EnvCubePass : public EnvReflectionPass {
 public:
  EnvCubePass() : EnvReflectionPass(EnvMapKind::Cube) {}
  static ParamSchema schema() { return EnvReflectionPass::schema(EnvMapKind::Cube); }
};
class EnvSpherePass : public EnvReflectionPass {
 public:
  EnvSpherePass() : EnvReflectionPass(EnvMapKind::Sphere) {}
  static ParamSchema schema() { return EnvReflectionPass::schema(EnvMapKind::Sphere); }
};
class EnvEquirectPass : public EnvReflectionPass {
 public:
  EnvEquirectPass() : EnvReflectionPass(EnvMapKind::Equirect) {}
  static ParamSchema schema() { return EnvReflectionPass::schema(EnvMapKind::Equirect); }
};

}  // namespace diptych
