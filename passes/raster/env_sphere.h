#pragma once
#include "passes/raster/env_reflection.h"

namespace diptych {

// env_sphere: GL_SPHERE_MAP-style sphere map in the camera's eye frame.
class EnvSpherePass : public EnvReflectionPass {
 public:
  EnvSpherePass() : EnvReflectionPass(EnvMapKind::Sphere) {}
  static ParamSchema schema() { return EnvReflectionPass::schema(EnvMapKind::Sphere); }
};

}  // namespace diptych
