#include "engine/gl/shader.h"

#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <utility>

#include "engine/core/error.h"

namespace diptych::gl {

namespace fs = std::filesystem;

fs::path shaderDirectory() {
  if (const char* dir = std::getenv("DIPTYCH_SHADER_DIR"); dir && *dir) return dir;
  return DIPTYCH_SOURCE_SHADER_DIR;
}

namespace {

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot read shader file " + path.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class Preprocessor {
 public:
  Preprocessor(fs::path root, ShaderSource& out) : root_(std::move(root)), out_(out) {}

  void expand(const fs::path& file) {
    const fs::path canonical = fs::weakly_canonical(file);
    for (const fs::path& open : stack_) {
      if (open == canonical) throw Error("shader include cycle: " + chain(canonical));
    }
    if (!done_.insert(canonical).second) return;  // once per stage
    const int id = int(out_.files.size());
    out_.files.push_back(file);
    stack_.push_back(canonical);

    static const std::regex includeLine(R"(^\s*#\s*include\s+"([^"]+)\"\s*(//.*)?$)");
    static const std::regex versionLine(R"(^\s*#\s*version\b.*$)");
    std::istringstream in(readFile(file));
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
      ++number;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      std::smatch m;
      if (std::regex_match(line, m, includeLine)) {
        expand(resolve(file, m[1].str(), number));  // replaces the directive line
        continue;
      }
      // The loader owns #version; a file's own is blanked, keeping the line count.
      out_.text += std::regex_match(line, versionLine) ? std::string() : line;
      out_.text += "\n";
      out_.lines.push_back({id, number});
    }
    stack_.pop_back();
  }

 private:
  fs::path resolve(const fs::path& from, const std::string& name, int line) const {
    for (const fs::path& candidate : {from.parent_path() / name, root_ / name}) {
      if (fs::is_regular_file(candidate)) return candidate;
    }
    throw Error(from.string() + ":" + std::to_string(line) + ": cannot find included file \"" +
                name + "\" (searched beside it and in " + root_.string() + ")");
  }

  std::string chain(const fs::path& again) const {
    std::string s;
    for (const fs::path& p : stack_) s += p.filename().string() + " -> ";
    return s + again.filename().string() + " (" + again.string() + ")";
  }

  fs::path root_;
  ShaderSource& out_;
  std::vector<fs::path> stack_;
  std::set<fs::path> done_;
};

GLenum stageOf(const fs::path& file) {
  const std::string ext = file.extension().string();
  if (ext == ".vert") return GL_VERTEX_SHADER;
  if (ext == ".frag") return GL_FRAGMENT_SHADER;
  if (ext == ".comp") return GL_COMPUTE_SHADER;
  if (ext == ".geom") return GL_GEOMETRY_SHADER;
  throw Error("unknown shader stage for " + file.string() + " (use .vert, .frag, .comp, .geom)");
}

std::string shaderLog(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(std::size_t(std::max(length, 1)), '\0');
  glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
  log.resize(std::strlen(log.c_str()));
  return log;
}

std::string programLog(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(std::size_t(std::max(length, 1)), '\0');
  glGetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
  log.resize(std::strlen(log.c_str()));
  return log;
}

}  // namespace

ShaderSource preprocessShader(const fs::path& file, const std::vector<ShaderDefine>& defines,
                              const fs::path& root) {
  ShaderSource out;
  out.text = "#version 450 core\n";
  for (const ShaderDefine& d : defines) out.text += "#define " + d.name + " " + d.value + "\n";
  // From here on, line L of source string 0 is out.lines[L - 1] (GLSL 4.50 §3.3: after
  // "#line L" the next line is line L).
  out.text += "#line 1 0\n";
  Preprocessor(root, out).expand(file.is_absolute() ? file : root / file);
  return out;
}

std::string mapShaderLog(const std::string& log, const ShaderSource& source) {
  // Mesa: "0:12(5): error: ..."; NVIDIA: "0(12) : error ..."; both start a line.
  static const std::regex location(R"((^|\n)(\d+)(?::(\d+)\(\d+\)|\((\d+)\)))");
  std::string out;
  auto begin = log.cbegin();
  for (std::sregex_iterator it(log.begin(), log.end(), location), end; it != end; ++it) {
    const std::smatch& m = *it;
    out.append(begin, m[0].first);
    out += m[1].str();
    const std::size_t line = std::stoul(m[3].matched ? m[3].str() : m[4].str());
    if (line >= 1 && line <= source.lines.size()) {
      const ShaderSource::Line& origin = source.lines[line - 1];
      out += source.files[std::size_t(origin.file)].string() + ":" + std::to_string(origin.line);
    } else {
      out += m[0].str().substr(m[1].length());  // outside the table (e.g. a define): as given
    }
    begin = m[0].second;
  }
  out.append(begin, log.cend());
  return out;
}

namespace {
thread_local std::vector<ShaderDefine> tScopedDefines;  // ScopedShaderDefines
}  // namespace

ScopedShaderDefines::ScopedShaderDefines(std::vector<ShaderDefine> defines)
    : previous_(std::exchange(tScopedDefines, std::move(defines))) {}

ScopedShaderDefines::~ScopedShaderDefines() {
  tScopedDefines = std::move(previous_);
}

Program loadProgram(const std::vector<fs::path>& stages,
                    const std::vector<ShaderDefine>& ownDefines, const fs::path& root) {
  std::vector<ShaderDefine> defines = ownDefines;
  defines.insert(defines.end(), tScopedDefines.begin(), tScopedDefines.end());
  Program program(glCreateProgram());
  std::vector<GLuint> shaders;
  auto cleanup = [&] {
    for (GLuint s : shaders) {
      glDetachShader(program.id(), s);
      glDeleteShader(s);
    }
  };
  std::string names;
  try {
    for (const fs::path& stage : stages) {
      names += (names.empty() ? "" : " + ") + stage.filename().string();
      const GLenum kind = stageOf(stage);
      const ShaderSource source = preprocessShader(stage, defines, root);
      const GLuint shader = glCreateShader(kind);
      shaders.push_back(shader);
      glAttachShader(program.id(), shader);
      const char* text = source.text.c_str();
      glShaderSource(shader, 1, &text, nullptr);
      glCompileShader(shader);
      GLint ok = 0;
      glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
      if (!ok) {
        throw Error("cannot compile shader " + source.files.front().string() + ":\n" +
                    mapShaderLog(shaderLog(shader), source));
      }
    }
  } catch (...) {
    cleanup();
    throw;
  }
  glLinkProgram(program.id());
  GLint ok = 0;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  const std::string log = ok ? std::string() : programLog(program.id());
  cleanup();
  if (!ok) throw Error("cannot link program " + names + ":\n" + log);
  return program;
}

}  // namespace diptych::gl
