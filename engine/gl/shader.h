#pragma once
// GLSL loading with #include. A stage file (.vert, .frag, .comp) is read from the shader
// directory, `#include "path"` lines are expanded recursively (each file at most once per stage,
// like #pragma once; an include cycle is an error naming the chain), `#line L S` directives keep
// every line attributed to its file, and `#version 450 core` plus the defines are prepended.
// Compile and link errors are rethrown as Error with the driver's "S:L" locations replaced by
// "file:line" of the original files.
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

// The expanded text of one stage and its include table: GLSL source-string number i in #line
// directives (and therefore in driver logs) is files[i]; files[0] is the stage file.
struct ShaderSource {
  std::string text;
  std::vector<std::filesystem::path> files;
};

// `#include "p"` is looked up beside the including file first, then under `root`.
ShaderSource preprocessShader(const std::filesystem::path& file,
                              const std::vector<ShaderDefine>& defines = {},
                              const std::filesystem::path& root = shaderDirectory());

// Rewrites "S:L(C)" (Mesa) and "S(L)" (NVIDIA, AMD) locations in a driver log to "file:L".
std::string mapShaderLog(const std::string& log, const ShaderSource& source);

// Stage files are relative to `root` (or absolute): loadProgram({"gbuffer.vert",
// "gbuffer.frag"}). The stage is taken from the extension (.vert, .frag, .comp, .geom).
Program loadProgram(const std::vector<std::filesystem::path>& stages,
                    const std::vector<ShaderDefine>& defines = {},
                    const std::filesystem::path& root = shaderDirectory());

}  // namespace diptych::gl
