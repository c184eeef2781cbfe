#include "engine/gl/context.h"

#include <cstdio>
#include <string_view>
#include <utility>

#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/gl/bindings.h"
#include "engine/gl/debug.h"
#include "engine/gl/loader.h"

namespace diptych::gl {

// Defined in osmesa_context.cpp and glfw_context.cpp (which include the native headers that
// must not meet loader.h).
std::unique_ptr<GlContext> createOsmesaContext(int width, int height);
std::unique_ptr<GlContext> createGlfwContext(int width, int height, bool visible);
// egl_context.cpp
std::unique_ptr<GlContext> createEglContext(int width, int height);
bool eglHardwareDeviceAvailable();

std::string_view contextKindName(ContextKind kind) {
  switch (kind) {
    case ContextKind::Osmesa:
      return "osmesa";
    case ContextKind::Glfw:
      return "glfw";
    case ContextKind::Egl:
      return "egl";
    case ContextKind::Auto:
      return "auto";
  }
  return "?";
}

ContextKind parseContextKind(std::string_view name) {
  for (ContextKind k :
       {ContextKind::Osmesa, ContextKind::Glfw, ContextKind::Egl, ContextKind::Auto})
    if (name == contextKindName(k)) return k;
  throw Error("unknown GL context kind '" + std::string(name) +
              "' (expected osmesa, glfw, egl or auto)");
}

ContextKind resolveContextKind(ContextKind kind) {
  if (kind != ContextKind::Auto) return kind;
  return eglHardwareDeviceAvailable() ? ContextKind::Egl : ContextKind::Osmesa;
}

GlContext::GlContext() = default;

GlContext::~GlContext() {
  installGlFunctions(nullptr);
}

void GlContext::makeCurrent() {
  makeCurrentNative();
  installGlFunctions(functions_.get());
}

namespace {
std::string glString(GLenum which) {
  const GLubyte* s = glGetString(which);
  return s ? reinterpret_cast<const char*>(s) : "";
}
}  // namespace

void GlContext::initialize() {
  const std::string contextName(name());
  functions_ = std::make_unique<GlFunctionTable>(
      loadGlFunctions([this](const char* fn) { return getProcAddress(fn); }, contextName.c_str()));
  installGlFunctions(functions_.get());

  info_.version = glString(GL_VERSION);
  info_.renderer = glString(GL_RENDERER);
  info_.vendor = glString(GL_VENDOR);
  info_.glslVersion = glString(GL_SHADING_LANGUAGE_VERSION);
  glGetIntegerv(GL_MAJOR_VERSION, &info_.major);
  glGetIntegerv(GL_MINOR_VERSION, &info_.minor);
  GLint profile = 0, flags = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
  info_.coreProfile = (profile & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
  info_.debugContext = (flags & GL_CONTEXT_FLAG_DEBUG_BIT) != 0;
  if (info_.major * 10 + info_.minor < 45 || !info_.coreProfile) {
    throw Error("OpenGL context '" + contextName + "' is '" + info_.version + "' (" +
                (info_.coreProfile ? "core" : "not core") + "); Diptych needs 4.5 core");
  }
  // The scene's data sits on texture units up to UNIT_COUNT - 1 in every stage that reads it.
  for (const auto& [limit, stage] : {std::pair{GL_MAX_TEXTURE_IMAGE_UNITS, "fragment"},
                                     std::pair{GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS, "vertex"},
                                     std::pair{GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS, "compute"}}) {
    GLint units = 0;
    glGetIntegerv(limit, &units);
    if (units < UNIT_COUNT) {
      throw Error("OpenGL context '" + contextName + "' ('" + info_.renderer + "') offers " +
                  std::to_string(units) + " texture units to the " + stage +
                  " stage; Diptych binds " + std::to_string(UNIT_COUNT) +
                  " (shaders/common/bindings.glsl)");
    }
  }
  GLint extensions = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &extensions);
  for (GLint i = 0; i < extensions; ++i) {
    const GLubyte* e = glGetStringi(GL_EXTENSIONS, GLuint(i));
    if (e && std::string_view(reinterpret_cast<const char*>(e)) == "GL_MESA_pack_invert")
      functions_->packInvert = true;
  }
  enableDebugOutput();
  log().info("GL context {}: {} | {} | GLSL {}{}", contextName, info_.renderer, info_.version,
             info_.glslVersion, info_.debugContext ? " | debug" : "");
}

std::unique_ptr<GlContext> createContext(ContextKind kind, int width, int height, bool visible) {
  if (width <= 0 || height <= 0) {
    throw Error("GL context size must be positive, got " + std::to_string(width) + "x" +
                std::to_string(height));
  }
  const ContextKind resolved = resolveContextKind(kind);
  if (kind == ContextKind::Auto)
    log().info("GL context auto: {} ({})", contextKindName(resolved),
               resolved == ContextKind::Egl ? "a hardware EGL device is present"
                                            : "no hardware EGL device; OSMesa/llvmpipe");
  switch (resolved) {
    case ContextKind::Osmesa:
      return createOsmesaContext(width, height);
    case ContextKind::Glfw:
      return createGlfwContext(width, height, visible);
    default:
      break;
  }
  if (kind != ContextKind::Auto) return createEglContext(width, height);
  try {  // auto: a GPU whose EGL setup fails still leaves a working (software) context
    return createEglContext(width, height);
  } catch (const Error& e) {
    log().warn("GL context auto: EGL failed ({}); falling back to OSMesa", e.what());
    return createOsmesaContext(width, height);
  }
}

}  // namespace diptych::gl
