#include <gtest/gtest.h>

#include <unistd.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <utility>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/core/timing.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/world_geometry.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

TEST(Timing, MedianOfOddAndEvenCounts) {
  EXPECT_DOUBLE_EQ(summarize({5, 1, 3}).median, 3);
  EXPECT_DOUBLE_EQ(summarize({4, 1, 3, 2}).median, 2.5);
  EXPECT_EQ(summarize({}).samples, 0);
}

// A reused pid must not find an earlier run's files in its scratch folder (a stale FIFO failed
// mkfifo in CI): the first use in a process empties it, later uses keep this run's files.
TEST(ScratchDir, StartsEmptyAtItsFirstUseInAProcess) {
  namespace fs = std::filesystem;
  const std::string name = "diptych_scratch_dir_test";
  const fs::path expected = fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  fs::create_directories(expected / "old");
  std::ofstream(expected / "stale.txt") << "an earlier run";
  const fs::path dir = ::diptych::testing::scratchDir(name);
  ASSERT_EQ(dir, expected);
  EXPECT_TRUE(fs::is_directory(dir));
  EXPECT_TRUE(fs::is_empty(dir));
  std::ofstream(dir / "mine.txt") << "this run";
  EXPECT_EQ(::diptych::testing::scratchDir(name), dir);
  EXPECT_TRUE(fs::exists(dir / "mine.txt"));
}

TEST(Image, ExrRoundTripIsExactAndPngIsSrgbEncoded) {
  const auto dir = ::diptych::testing::scratchDir("diptych_test_core");
  Image img(3, 2, 3);
  for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = 0.1f * float(i) + 0.01f;
  writeImage(dir / "a.exr", img);
  const Image back = readImage(dir / "a.exr");
  ASSERT_EQ(back.width, 3);
  ASSERT_EQ(back.height, 2);
  for (std::size_t i = 0; i < img.pixels.size(); ++i)
    EXPECT_FLOAT_EQ(back.pixels[i], img.pixels[i]);

  Image grey(1, 1, 3, 0.5f);
  writeImage(dir / "g.png", grey);
  const Image png = readImage(dir / "g.png");
  EXPECT_NEAR(png.at(0, 0, 0), linearToSrgb(0.5f), 1.f / 255.f);
}

TEST(Image, MissingFileNamesTheFile) {
  try {
    readImage("/nonexistent/dir/missing.png");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos);
  }
}

TEST(Srgb, TransferFunctionRoundTrips) {
  for (float v : {0.f, 0.001f, 0.04f, 0.2f, 0.5f, 1.f})
    EXPECT_NEAR(srgbToLinear(linearToSrgb(v)), v, 1e-6f);
}

TEST(Camera, CentreRayLooksAtTargetAndReversedZMapsNearToOne) {
  Camera c;
  c.position = {0, 0, 5};
  c.target = {0, 0, 0};
  const Ray r = primaryRay(c, 64, 64, 32.f, 32.f);
  EXPECT_NEAR(r.direction.z, -1.f, 1e-6f);
  const mat4 p = reversedZProjection(c, 1.f);
  const vec4 nearPoint = p * vec4(0, 0, -c.znear, 1);
  EXPECT_NEAR(nearPoint.z / nearPoint.w, 1.f, 1e-6f);
  const vec4 farPoint = p * vec4(0, 0, -1e6f, 1);
  EXPECT_LT(farPoint.z / farPoint.w, 1e-6f);
}

// rowDirections is the vectorised form of ray() for a row's pixel centres; every per-pixel loop
// that uses it relies on the two agreeing bit for bit (the hybrid's exact hits against the
// reference's primary rays). Widths below, at and across its 64-pixel chunks; odd cameras.
TEST(Camera, RowDirectionsAreTheRaysOfThePixelCentresBitForBit) {
  const Camera cameras[] = {[] {
                              Camera c;
                              c.position = {0, 0, 5};
                              c.target = {0, 0, 0};
                              return c;
                            }(),
                            [] {
                              Camera c;
                              c.position = {3.7f, -1.25f, 0.3f};
                              c.target = {-2.f, 0.5f, 7.f};
                              c.up = {0.2f, 1.f, -0.1f};
                              c.verticalFov = 1.9f;
                              return c;
                            }(),
                            [] {
                              Camera c;
                              c.position = {1e4f, 2e3f, -5e3f};
                              c.target = {1e4f + 1.f, 2e3f, -5e3f - 1e-3f};
                              c.verticalFov = 0.01f;
                              return c;
                            }()};
  for (const Camera& c : cameras) {
    for (const auto& [w, h] : {std::pair{1, 1}, {63, 7}, {64, 3}, {129, 97}, {640, 480}}) {
      const PinholeFrame frame(c, w, h);
      std::vector<vec3> row(static_cast<std::size_t>(w));
      for (int y = 0; y < h; ++y) {
        frame.rowDirections(y, row);
        for (int x = 0; x < w; ++x) {
          const Ray r = frame.ray(float(x) + 0.5f, float(y) + 0.5f);
          ASSERT_EQ(r.origin, frame.position());
          for (int k = 0; k < 3; ++k)
            ASSERT_EQ(std::bit_cast<std::uint32_t>(row[std::size_t(x)][k]),
                      std::bit_cast<std::uint32_t>(r.direction[k]))
                << w << "x" << h << " pixel (" << x << ", " << y << ") component " << k;
        }
      }
    }
  }
}

TEST(WorldGeometry, MirroredInstanceKeepsOutwardGeometricNormal) {
  Scene s;
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.indices = {0, 1, 2};
  s.meshes.push_back(m);
  s.instances.push_back({"plain", 0, mat4(1.f)});
  s.instances.push_back({"mirrored", 0, glm::scale(mat4(1.f), vec3(-1, 1, 1))});
  const WorldGeometry w = flattenScene(s);
  ASSERT_EQ(w.meshes.size(), 2u);
  EXPECT_FALSE(w.meshes[0].mirrored);
  EXPECT_TRUE(w.meshes[1].mirrored);
  // Mirroring x and flipping winding keeps the face pointing along +z.
  EXPECT_NEAR(geometricNormal(w.meshes[0], 0).z, 1.f, 1e-6f);
  EXPECT_NEAR(geometricNormal(w.meshes[1], 0).z, 1.f, 1e-6f);
  EXPECT_NEAR(interpolatePosition(w.meshes[1], 0, 1.f / 3, 1.f / 3).x, -1.f / 3, 1e-6f);
}

// flattenScene stores each triangle's normal once (WorldMesh::faceNormals); geometricNormal
// returns it, and it must be the normal computed from the positions, bit for bit: the same
// shading as before, for mirrored instances and degenerate triangles too.
TEST(WorldGeometry, StoredFaceNormalsAreTheComputedOnesBitForBit) {
  Scene s;
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0.3f, 0}, {0.2f, 1, 0.7f}, {3, 3, 3}, {1e-20f, 0, 0}};
  m.indices = {0, 1, 2, 1, 3, 2, 0, 4, 4, 3, 3, 3};  // the last two degenerate
  s.meshes.push_back(m);
  s.instances.push_back({"plain", 0, glm::rotate(mat4(1.f), 0.7f, vec3(1, 2, 3))});
  s.instances.push_back({"mirrored", 0, glm::scale(mat4(1.f), vec3(-2, 1, 0.5f))});
  const WorldGeometry w = flattenScene(s);
  for (const WorldMesh& mesh : w.meshes) {
    ASSERT_EQ(mesh.faceNormals.size(), 4u);
    WorldMesh byHand = mesh;
    byHand.faceNormals.clear();  // geometricNormal computes it from the positions
    for (std::uint32_t t = 0; t < 4; ++t) {
      const vec3 stored = geometricNormal(mesh, t), computed = geometricNormal(byHand, t);
      EXPECT_EQ(stored, mesh.faceNormals[t]);
      EXPECT_EQ(std::memcmp(&stored, &computed, sizeof(vec3)), 0) << "triangle " << t;
    }
    EXPECT_EQ(geometricNormal(byHand, 3), vec3(0.f, 1.f, 0.f));  // degenerate: the fallback
  }
}

}  // namespace DIPTYCH_UNITY_ID
