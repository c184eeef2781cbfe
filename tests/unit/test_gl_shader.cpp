// Shader loading: includes, #line mapping of errors, cycles, and a compute dispatch.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/core/error.h"
#include "engine/gl/debug.h"
#include "engine/gl/shader.h"
#include "gl_test_context.h"
#include "tests/support/test_paths.h"

namespace diptych::gl {
namespace DIPTYCH_UNITY_ID {

namespace fs = std::filesystem;

class ShaderFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("diptych_shader_test_" +
             std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_ / "common");
  }
  void TearDown() override { fs::remove_all(root_); }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(root_ / name) << text;
  }
  fs::path root_;
};

constexpr const char* kComputeMain = R"(layout(local_size_x = 4, local_size_y = 2) in;
layout(std430, binding = 0) buffer Out { uint ids[]; };
void main() {
  uint i = gl_GlobalInvocationID.y * 8u + gl_GlobalInvocationID.x;
  ids[2u * i] = gl_GlobalInvocationID.x;
  ids[2u * i + 1u] = gl_GlobalInvocationID.y + OFFSET;
}
)";

TEST_F(ShaderFiles, IncludesAreExpandedOnceWithLineDirectives) {
  write("common/a.glsl", "#include \"common/b.glsl\"\nfloat a() { return b(); }\n");
  write("common/b.glsl", "float b() { return 1.0; }\n");
  write("main.comp", "#include \"common/a.glsl\"\n#include \"common/b.glsl\"\nvoid main() {}\n");
  const ShaderSource s = preprocessShader("main.comp", {{"FOO", "2"}}, root_);
  ASSERT_EQ(s.files.size(), 3u);
  EXPECT_EQ(s.files[1].filename(), "a.glsl");
  EXPECT_EQ(s.files[2].filename(), "b.glsl");
  EXPECT_EQ(s.text.rfind("#version 450 core\n#define FOO 2\n", 0), 0u) << s.text;
  // b.glsl appears once although included twice (once from a.glsl, once from main).
  EXPECT_EQ(s.text.find("float b()"), s.text.rfind("float b()"));
  // Line table: main's line 1 expands to a.glsl (whose line 1 expands to b.glsl), main's line 2
  // (b.glsl again) to nothing, then main's line 3.
  ASSERT_EQ(s.lines.size(), 3u);
  EXPECT_EQ(s.lines[0].file, 2);
  EXPECT_EQ(s.lines[1].file, 1);
  EXPECT_EQ(s.lines[1].line, 2);
  EXPECT_EQ(s.lines[2].file, 0);
  EXPECT_EQ(s.lines[2].line, 3);
}

TEST_F(ShaderFiles, IncludeCycleIsAnError) {
  write("common/x.glsl", "#include \"common/y.glsl\"\n");
  write("common/y.glsl", "#include \"x.glsl\"\n");
  write("main.comp", "#include \"common/x.glsl\"\nvoid main() {}\n");
  try {
    preprocessShader("main.comp", {}, root_);
    FAIL() << "expected a cycle error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cycle: main.comp -> x.glsl -> y.glsl -> x.glsl"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(ShaderFiles, MissingIncludeNamesFileAndLine) {
  write("main.comp", "\n\n#include \"common/nope.glsl\"\n");
  try {
    preprocessShader("main.comp", {}, root_);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("main.comp:3: cannot find included file"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(ShaderFiles, CompileErrorInIncludedFileNamesThatFileAndLine) {
  testing::osmesaContext();
  write("common/ok.glsl", "float ok() { return 1.0; }\n");
  write("common/bad.glsl", "// line 1\nfloat bad() {\n  return undefined_name;\n}\n");
  write("broken.comp",
        "layout(local_size_x = 1) in;\n#include \"common/ok.glsl\"\n#include "
        "\"common/bad.glsl\"\nvoid main() {}\n");
  try {
    loadProgram({"broken.comp"}, {}, root_);
    FAIL() << "expected a compile error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find((root_ / "common/bad.glsl").string() + ":3"), std::string::npos) << what;
    EXPECT_NE(what.find("undefined_name"), std::string::npos) << what;
  }
}

TEST_F(ShaderFiles, ErrorAfterAnIncludeMapsToTheIncludingFile) {
  testing::osmesaContext();
  write("common/ok.glsl", "float ok() {\n  return 1.0;\n}\n");
  write("after.comp",
        "layout(local_size_x = 1) in;\n#include \"common/ok.glsl\"\nvoid main() {\n  "
        "int x = missing;\n}\n");
  try {
    loadProgram({"after.comp"}, {}, root_);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find((root_ / "after.comp").string() + ":4"), std::string::npos)
        << e.what();
  }
}

TEST_F(ShaderFiles, ComputeShaderWritesInvocationIds) {
  testing::osmesaContext();
  const std::uint64_t errors = glDebugErrorCount();
  write("ids.comp", kComputeMain);
  const Program program = loadProgram({"ids.comp"}, {{"OFFSET", "100u"}}, root_);
  const int count = 8 * 4;  // 2 x 2 groups of 4 x 2
  Buffer out = Buffer::create(count * 2 * 4);
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  program.use();
  glDispatchCompute(2, 2, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<std::uint32_t> ids(count * 2);
  out.download(0, ids.size() * 4, ids.data());
  for (int i = 0; i < count; ++i) {
    EXPECT_EQ(ids[2 * i], std::uint32_t(i % 8)) << i;
    EXPECT_EQ(ids[2 * i + 1], std::uint32_t(i / 8 + 100)) << i;
  }
  EXPECT_EQ(glDebugErrorCount(), errors);
}

TEST(ShaderDirectory, EnvironmentOverridesTheSourceDirectory) {
  const char* previous = std::getenv("DIPTYCH_SHADER_DIR");
  const std::string saved = previous ? previous : "";
  ::setenv("DIPTYCH_SHADER_DIR", "/tmp/somewhere", 1);
  EXPECT_EQ(shaderDirectory(), fs::path("/tmp/somewhere"));
  ::unsetenv("DIPTYCH_SHADER_DIR");
  EXPECT_EQ(shaderDirectory(), fs::path(DIPTYCH_SOURCE_SHADER_DIR));
  if (previous) ::setenv("DIPTYCH_SHADER_DIR", saved.c_str(), 1);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych::gl
