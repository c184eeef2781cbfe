#include <gtest/gtest.h>

#include "engine/core/error.h"
#include "engine/gl/debug.h"
#include "gl_test_context.h"

namespace diptych::gl {
namespace DIPTYCH_UNITY_ID {

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
  EXPECT_EQ(parseContextKind("egl"), ContextKind::Egl);
  EXPECT_EQ(parseContextKind("auto"), ContextKind::Auto);
  EXPECT_THROW(parseContextKind("vulkan"), Error);
  const ContextKind resolved = resolveContextKind(ContextKind::Auto);
  EXPECT_TRUE(resolved == ContextKind::Osmesa || resolved == ContextKind::Egl);
}

// EGL headless: on this machine Mesa's surfaceless platform (llvmpipe); on a GPU machine the
// device platform. Either way a 4.5 core context that runs GL, beside the OSMesa one.
TEST(GlContext, EglIsGl45CoreAndCoexistsWithOsmesa) {
  auto egl = createContext(ContextKind::Egl, 32, 32);
  const ContextInfo& info = egl->info();
  EXPECT_EQ(egl->name(), "egl");
  EXPECT_GE(info.major * 10 + info.minor, 45) << info.version;
  EXPECT_TRUE(info.coreProfile);
  EXPECT_FALSE(info.renderer.empty());
  GLuint texture = 0;  // real work on it: a texture round trip
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, GL_R32F, 2, 2);
  const float in[4] = {1.f, 2.f, 3.f, 4.f};
  glTextureSubImage2D(texture, 0, 0, 0, 2, 2, GL_RED, GL_FLOAT, in);
  float out[4] = {};
  glGetTextureSubImage(texture, 0, 0, 0, 0, 2, 2, 1, GL_RED, GL_FLOAT, sizeof out, out);
  glDeleteTextures(1, &texture);
  EXPECT_EQ(out[3], 4.f);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  egl.reset();
  GlContext& osmesa = testing::osmesaContext();  // the other context is still usable
  EXPECT_EQ(osmesa.name(), "osmesa");
  EXPECT_NE(glGetString(GL_RENDERER), nullptr);
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

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych::gl

// LeakSanitizer (asan preset) hook: Mesa's OSMesa keeps the buffer object it allocates in
// OSMesaMakeCurrent past OSMesaDestroyContext (a few hundred bytes per process, not ours to free),
// and GLX/llvmpipe keep per-process caches. Suppress leaks whose allocation stack is inside them.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\nleak:libGLX_mesa.so\nleak:swrast_dri.so\nleak:libLLVM\n";
}
