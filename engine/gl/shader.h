#pragma once
// GLSL loading with #include. A stage file (.vert, .frag, .comp) is read from the shader
// directory, `#include "path"` lines are expanded recursively (each file at most once per stage,
// like #pragma once; an include cycle is an error naming the chain), and `#version 450 core`,
// the defines and a `#line 1 0` are prepended. Compile errors are rethrown as Error with the
// driver's "0:L" locations replaced by "file:line" of the original files.
//
// Why one line table instead of a `#line L S` per include: Mesa reports some errors (e.g. an
// undeclared identifier) with source string 0 whatever #line said, so source-string numbers
// cannot be trusted; the global line number in string 0 always is.
#include <filesystem>
#include <string>
#include <vector>

#include "engine/gl/objects.h"

namespace diptych::gl {

// $DIPTYCH_SHADER_DIR when set, else the source tree's shaders/ (DIPTYCH_SOURCE_SHADER_DIR).
std::filesystem::path shaderDirectory();

struct ShaderDefine {
  std::string name;
  std::string value;  // may be empty: "#define NAME"
};

// The expanded text of one stage and its include table: line L of the text after the
// `#line 1 0` directive is line lines[L-1].line of files[lines[L-1].file]; files[0] is the stage.
struct ShaderSource {
  struct Line {
    int file;
    int line;
  };
  std::string text;
  std::vector<std::filesystem::path> files;
  std::vector<Line> lines;
};

// `#include "p"` is looked up beside the including file first, then under `root`.
ShaderSource preprocessShader(const std::filesystem::path& file,
                              const std::vector<ShaderDefine>& defines = {},
                              const std::filesystem::path& root = shaderDirectory());

// Rewrites "S:L(C)" (Mesa) and "S(L)" (NVIDIA, AMD) locations in a driver log to "file:line".
std::string mapShaderLog(const std::string& log, const ShaderSource& source);

// Defines that every program compiled on this thread gets, after its own, while one of these is
// alive (nested: the innermost's replace the outer ones). GraphExecutor::runFrame sets the
// scene's feature defines with it, e.g. DIPTYCH_NO_BUMP when no material has a bump map: llvmpipe
// executes both sides of every branch, so code the scene cannot reach is compiled out rather
// than branched over. Programs compiled outside a frame keep all code (correct, only slower).
class ScopedShaderDefines {
 public:
  explicit ScopedShaderDefines(std::vector<ShaderDefine> defines);
  ~ScopedShaderDefines();
  ScopedShaderDefines(const ScopedShaderDefines&) = delete;
  ScopedShaderDefines& operator=(const ScopedShaderDefines&) = delete;

 private:
  std::vector<ShaderDefine> previous_;
};

// Stage files are relative to `root` (or absolute): loadProgram({"gbuffer.vert",
// "gbuffer.frag"}). The stage is taken from the extension (.vert, .frag, .comp, .geom).
Program loadProgram(const std::vector<std::filesystem::path>& stages,
                    const std::vector<ShaderDefine>& defines = {},
                    const std::filesystem::path& root = shaderDirectory());

}  // namespace diptych::gl
