#pragma once
#include "passes/raster/env_reflection.h"

namespace diptych {

// env_equirect: lat-long panorama, the scene's image or the environment resampled.
class EnvEquirectPass : public EnvReflectionPass {
 public:
  EnvEquirectPass() : EnvReflectionPass(EnvMapKind::Equirect) {}
  static ParamSchema schema() { return EnvReflectionPass::schema(EnvMapKind::Equirect); }
};

}  // namespace diptych
