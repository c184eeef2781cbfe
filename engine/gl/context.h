#pragma once
// OpenGL contexts. OSMesa (llvmpipe, headless) is the default; EGL is headless on a GPU (device
// platform) or on Mesa (surfaceless); a GLFW window is the alternative for interactive viewers.
// Every context is OpenGL 4.5 core, verified at creation, with debug output routed to
// diptych::log() (see debug.h).
#include <memory>
#include <string>
#include <string_view>

namespace diptych::gl {

struct GlFunctionTable;

// Auto: EGL when a hardware EGL device exists, else OSMesa (createContext logs which).
enum class ContextKind { Osmesa, Glfw, Egl, Auto };

std::string_view contextKindName(ContextKind kind);
ContextKind parseContextKind(std::string_view name);  // "osmesa" | "glfw" | "egl" | "auto"; throws
// The kind `Auto` resolves to on this machine (Osmesa or Egl); other kinds are returned as given.
ContextKind resolveContextKind(ContextKind kind);

// What the driver reported at creation.
struct ContextInfo {
  std::string version, renderer, vendor, glslVersion;
  int major = 0, minor = 0;
  bool coreProfile = false;
  bool debugContext = false;
};

class GlContext {
 public:
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;
  virtual ~GlContext();

  // Makes this context current on the calling thread and installs its GL function pointers.
  void makeCurrent();
  virtual void* getProcAddress(const char* name) const = 0;
  // Size of the default framebuffer (OSMesa: the small owned buffer; GLFW: the window).
  virtual int width() const = 0;
  virtual int height() const = 0;
  virtual std::string_view name() const = 0;  // for logs: "osmesa", "glfw", "egl"
  virtual void swapBuffers() {}
  const ContextInfo& info() const { return info_; }

 protected:
  GlContext();
  virtual void makeCurrentNative() = 0;
  // Called by a subclass constructor once its native context is current: loads functions,
  // verifies GL >= 4.5 core, enables debug output, logs GL_RENDERER. Throws Error.
  void initialize();

 private:
  std::unique_ptr<GlFunctionTable> functions_;
  ContextInfo info_;
};

// Creates a context of `kind` and makes it current. `width` x `height` is the default
// framebuffer (rendering normally goes to FBOs; for GLFW this is the window size).
// `visible` applies to GLFW only. Throws Error with the reason (e.g. no DISPLAY for GLFW).
std::unique_ptr<GlContext> createContext(ContextKind kind, int width, int height,
                                         bool visible = false);

}  // namespace diptych::gl
