// One name per concept (docs/frame-graph.md, "Passes"): pass type `foo_bar` is class FooBarPass
// (letter case aside) declared in passes/<folder>/foo_bar.h, and a pass's shaders are named after
// it (shaders/<pass>[_<part>].<stage>). Read from the source tree, so a new type that breaks the
// convention fails here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace fs = std::filesystem;

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

fs::path passesDir() {
  return fs::canonical(fs::path(DIPTYCH_SAMPLES_DIR) / ".." / "passes");
}

std::string readText(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The type without underscores, lower case, + "pass": "env_cube" -> "envcubepass". Class names
// compare case-insensitively, so that acronyms may stay capitals (gbuffer: GBufferPass).
std::string classKey(const std::string& name) {
  std::string out;
  for (char c : name)
    if (c != '_') out += char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool declaresClassFor(const std::string& header, const std::string& type) {
  const std::regex decl(R"(class (\w+Pass) )");
  for (std::sregex_iterator m(header.begin(), header.end(), decl), end; m != end; ++m)
    if (classKey((*m)[1]) == classKey(type) + "pass") return true;
  return false;
}

TEST(PassNaming, EveryTypeIsItsClassInItsHeader) {
  for (const PassTypeInfo& t : builtinPasses().all()) {
    std::vector<fs::path> headers;
    for (const auto& e : fs::recursive_directory_iterator(passesDir()))
      if (e.path().filename() == t.name + ".h") headers.push_back(e.path());
    ASSERT_EQ(headers.size(), 1u) << "pass type '" << t.name << "' needs one passes/*/" << t.name
                                  << ".h";
    EXPECT_TRUE(declaresClassFor(readText(headers[0]), t.name))
        << headers[0] << " does not declare the class of pass type '" << t.name << "'";
  }
}

TEST(PassNaming, ShadersAreNamedAfterThePassThatLoadsThem) {
  const std::regex program(R"(loadProgram\(\{([^}]*)\})");
  const std::regex stage(R"re("([a-z_0-9]+)\.(vert|frag|comp|geom)")re");
  int checked = 0;
  for (const auto& e : fs::recursive_directory_iterator(passesDir())) {
    if (e.path().extension() != ".cpp") continue;
    const std::string text = readText(e.path()), file = e.path().stem().string();
    for (std::sregex_iterator p(text.begin(), text.end(), program), end; p != end; ++p) {
      const std::string list = (*p)[1];
      for (std::sregex_iterator s(list.begin(), list.end(), stage); s != end; ++s) {
        const std::string shader = (*s)[1];
        if (shader == "fullscreen") continue;  // the shared full-screen triangle
        // Some pass header `h` in the folder: the shader is h[_part], the loader h[_part].cpp.
        bool named = false;
        for (const auto& h : fs::directory_iterator(e.path().parent_path())) {
          if (h.path().extension() != ".h") continue;
          const std::string pass = h.path().stem().string();
          auto under = [&](const std::string& n) { return n == pass || n.starts_with(pass + "_"); };
          named = named || (under(shader) && under(file));
        }
        EXPECT_TRUE(named) << e.path() << " loads " << shader << " not named after its pass";
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 6);
}
}  // namespace DIPTYCH_UNITY_ID
