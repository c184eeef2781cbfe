// EGL headless context: the device platform (EGL_EXT_platform_device) on a GPU with its driver,
// Mesa's surfaceless platform (EGL_MESA_platform_surfaceless, llvmpipe) otherwise. Like
// osmesa_context.cpp this file includes native headers and makes no GL calls itself.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/gl/context.h"

namespace diptych::gl {
namespace {

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const std::size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)); p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

template <class F>
F eglProc(const char* name) {
  return reinterpret_cast<F>(eglGetProcAddress(name));
}

// EGL devices (EGL_EXT_device_enumeration); empty where the extension is missing.
std::vector<EGLDeviceEXT> eglDevices() {
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!hasExtension(clientExtensions, "EGL_EXT_device_enumeration")) return {};
  auto query = eglProc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  if (!query) return {};
  EGLint count = 0;
  if (!query(0, nullptr, &count) || count <= 0) return {};
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  if (!query(count, devices.data(), &count)) return {};
  devices.resize(std::size_t(count));
  return devices;
}

// A device is hardware unless Mesa marks it as its software rasterizer (EGL_MESA_device_software).
bool isHardware(EGLDeviceEXT device) {
  auto queryString = eglProc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  if (!queryString) return false;
  return !hasExtension(queryString(device, EGL_EXTENSIONS), "EGL_MESA_device_software");
}

EGLDeviceEXT firstHardwareDevice() {
  for (EGLDeviceEXT d : eglDevices())
    if (isHardware(d)) return d;
  return EGL_NO_DEVICE_EXT;
}

class EglContext final : public GlContext {
 public:
  EglContext(int width, int height) : width_(width), height_(height) {
    auto getPlatformDisplay = eglProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    if (!getPlatformDisplay)
      throw Error("EGL: eglGetPlatformDisplayEXT is missing (no EGL_EXT_platform_base)");
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (EGLDeviceEXT device = firstHardwareDevice();
        device != EGL_NO_DEVICE_EXT && hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
      display_ = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
      platform_ = "device";
    }
    if (display_ == EGL_NO_DISPLAY) {
      if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
        throw Error("EGL: neither a hardware EGL device nor EGL_MESA_platform_surfaceless");
      display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      platform_ = "surfaceless";
    }
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor))
      throw Error("EGL: cannot initialize the " + platform_ + " display (error " + errorCode() +
                  ")");
    if (!hasExtension(eglQueryString(display_, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
      throw Error("EGL: the " + platform_ + " display lacks EGL_KHR_surfaceless_context");
    if (!eglBindAPI(EGL_OPENGL_API)) throw Error("EGL: eglBindAPI(EGL_OPENGL_API) failed");
    // No surface is ever made current (Diptych renders into its own framebuffer objects), but
    // eglChooseConfig defaults EGL_SURFACE_TYPE to EGL_WINDOW_BIT, which headless platforms
    // lack; ask for pbuffer support, which both the device and surfaceless platforms have.
    const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                                       EGL_PBUFFER_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    if (!eglChooseConfig(display_, configAttributes, &config, 1, &configs) || configs < 1)
      throw Error("EGL: no OpenGL-renderable config on the " + platform_ + " display");
    const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                        4,
                                        EGL_CONTEXT_MINOR_VERSION,
                                        5,
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                        EGL_NONE};
    context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, contextAttributes);
    if (context_ == EGL_NO_CONTEXT)
      throw Error("EGL: cannot create an OpenGL 4.5 core context on the " + platform_ +
                  " display (error " + errorCode() + ")");
    try {
      makeCurrentNative();
      initialize();
    } catch (...) {
      release();  // the destructor does not run for a constructor that throws
      throw;
    }
    log().info("EGL {}.{} on the {} platform", major, minor, platform_);
  }
  ~EglContext() override { release(); }

  void release() {
    if (display_ != EGL_NO_DISPLAY) {
      eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
      context_ = EGL_NO_CONTEXT;
      // No eglTerminate: displays are per-process singletons in EGL, and terminating Mesa's
      // unloads its DRI driver, whose process-lifetime allocations LeakSanitizer could then no
      // longer attribute to a module (the same trap as tests/lsan_suppressions.txt describes).
    }
  }

  void* getProcAddress(const char* name) const override {
    return reinterpret_cast<void*>(eglGetProcAddress(name));
  }
  int width() const override { return width_; }
  int height() const override { return height_; }
  std::string_view name() const override { return "egl"; }
  std::string_view platform() const { return platform_; }

 protected:
  void makeCurrentNative() override {
    if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw Error("EGL: eglMakeCurrent failed (error " + errorCode() + ")");
  }

 private:
  static std::string errorCode() {
    char text[16];
    std::snprintf(text, sizeof text, "0x%04x", unsigned(eglGetError()));
    return text;
  }
  int width_, height_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::string platform_;
};

}  // namespace

bool eglHardwareDeviceAvailable() {
  return firstHardwareDevice() != EGL_NO_DEVICE_EXT;
}

std::unique_ptr<GlContext> createEglContext(int width, int height) {
  return std::make_unique<EglContext>(width, height);
}

}  // namespace diptych::gl
