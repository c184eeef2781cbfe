#pragma once
// Hand-listed OpenGL 4.5 loader. Every GL call in Diptych goes through a pointer fetched from the
// current context's own get-proc-address (OSMesaGetProcAddress or glfwGetProcAddress), never
// through a linked symbol: libOSMesa and libGL export the same names, and a linked call could
// land in the library of the other context. The list lives in gl_functions.inl (one line per
// function).
//
// Each context loads its own GlFunctionTable once; GlContext::makeCurrent() installs that table
// into the thread-local pointers below, because a GL context is current per thread and the
// pointers of two contexts (OSMesa, GLX) are not interchangeable.
#if defined(__gl_h_) || defined(GL_GLEXT_PROTOTYPES)
#error "engine/gl/loader.h must not be combined with <GL/gl.h> or GL_GLEXT_PROTOTYPES"
#endif
#include <GL/glcorearb.h>

#include <functional>

namespace diptych::gl {

struct GlFunctionTable {
#define DIPTYCH_GL_FUNCTION(type, name) type name = nullptr;
#include "engine/gl/gl_functions.inl"
#undef DIPTYCH_GL_FUNCTION
  // GL_MESA_pack_invert (every Mesa driver, llvmpipe included): the context packs images
  // top row first on request (GL_PACK_INVERT_MESA), so a readback needs no row flip on the CPU
  // (engine/gl/transfer.cpp). Set by GlContext::initialize, per context like the functions.
  bool packInvert = false;
};

using ProcAddressFn = std::function<void*(const char* name)>;

// Resolves every listed function; throws Error naming all that are missing.
GlFunctionTable loadGlFunctions(const ProcAddressFn& getProcAddress, const char* contextName);

// Makes `table` the calling thread's GL functions (nullptr clears them).
void installGlFunctions(const GlFunctionTable* table);
// The table last installed on the calling thread (nullptr when none).
const GlFunctionTable* installedGlFunctions();

// The calling thread's GL functions, e.g. gl::glClear(...). Inside namespace diptych::gl they
// are found unqualified and hide any ::gl* prototype.
#define DIPTYCH_GL_FUNCTION(type, name) extern thread_local type name;
#include "engine/gl/gl_functions.inl"
#undef DIPTYCH_GL_FUNCTION

}  // namespace diptych::gl
