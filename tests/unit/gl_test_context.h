#pragma once
// One OSMesa context per test binary, created on first use and kept current on the test thread
// (context creation costs tens of milliseconds on llvmpipe).
#include "engine/gl/context.h"
#include "engine/gl/loader.h"

namespace diptych::gl::testing {

inline GlContext& osmesaContext() {
  static std::unique_ptr<GlContext> context = createContext(ContextKind::Osmesa, 16, 16);
  context->makeCurrent();
  return *context;
}

}  // namespace diptych::gl::testing
