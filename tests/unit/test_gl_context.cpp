#include <gtest/gtest.h>

#include "engine/core/error.h"
#include "engine/gl/debug.h"
#include "gl_test_context.h"

namespace diptych::gl {
namespace {

TEST(GlContext, OsmesaIsGl45Core) {
  GlContext& context = testing::osmesaContext();
  const ContextInfo& info = context.info();
  EXPECT_GE(info.major * 10 + info.minor, 45) << info.version;
  EXPECT_TRUE(info.coreProfile);
  EXPECT_FALSE(info.renderer.empty());
  EXPECT_EQ(context.name(), "osmesa");
  EXPECT_EQ(context.width(), 16);
  EXPECT_NE(glGetString, nullptr);
}

TEST(GlContext, ParsesKindNames) {
  EXPECT_EQ(parseContextKind("osmesa"), ContextKind::Osmesa);
  EXPECT_EQ(parseContextKind("glfw"), ContextKind::Glfw);
  EXPECT_THROW(parseContextKind("vulkan"), Error);
}

TEST(GlDebug, ErrorsAreCountedUnderTheActiveLabel) {
  testing::osmesaContext();
  const std::uint64_t before = glDebugErrorCount();
  {
    ScopedGlLabel label("deliberate-error");
    EXPECT_EQ(currentGlLabel(), "deliberate-error");
    {
      ScopedGlLabel inner("inner");
      EXPECT_EQ(currentGlLabel(), "inner");
    }
    EXPECT_EQ(currentGlLabel(), "deliberate-error");
    glEnable(0xFFFFu);  // GL_INVALID_ENUM, reported synchronously through the callback
  }
  EXPECT_EQ(currentGlLabel(), "");
  EXPECT_EQ(glDebugErrorCount(), before + 1);
  while (glGetError() != GL_NO_ERROR) {
  }
}

}  // namespace
}  // namespace diptych::gl

// LeakSanitizer (asan preset) hook: Mesa's OSMesa keeps the buffer object it allocates in
// OSMesaMakeCurrent past OSMesaDestroyContext (a few hundred bytes per process, not ours to free),
// and GLX/llvmpipe keep per-process caches. Suppress leaks whose allocation stack is inside them.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\nleak:libGLX_mesa.so\nleak:swrast_dri.so\nleak:libLLVM\n";
}
