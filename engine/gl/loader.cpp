#include "engine/gl/loader.h"

#include <string>

#include "engine/core/error.h"

namespace diptych::gl {

#define DIPTYCH_GL_FUNCTION(type, name) thread_local type name = nullptr;
#include "engine/gl/gl_functions.inl"
#undef DIPTYCH_GL_FUNCTION

GlFunctionTable loadGlFunctions(const ProcAddressFn& getProcAddress, const char* contextName) {
  GlFunctionTable table;
  std::string missing;
#define DIPTYCH_GL_FUNCTION(type, name)                       \
  table.name = reinterpret_cast<type>(getProcAddress(#name)); \
  if (!table.name) missing += (missing.empty() ? "" : ", ") + std::string(#name);
#include "engine/gl/gl_functions.inl"
#undef DIPTYCH_GL_FUNCTION
  if (!missing.empty()) {
    throw Error(std::string("OpenGL context '") + contextName +
                "' does not provide required functions: " + missing);
  }
  return table;
}

namespace {
thread_local const GlFunctionTable* installed = nullptr;
}

const GlFunctionTable* installedGlFunctions() {
  return installed;
}

void installGlFunctions(const GlFunctionTable* table) {
  installed = table;
  static const GlFunctionTable empty;
  const GlFunctionTable& t = table ? *table : empty;
#define DIPTYCH_GL_FUNCTION(type, name) name = t.name;
#include "engine/gl/gl_functions.inl"
#undef DIPTYCH_GL_FUNCTION
}

}  // namespace diptych::gl
