#include "passes/rt/rt_path.h"

#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <vector>

#include "engine/graph/render_world.h"
#include "engine/rt/path_tracer.h"
#include "engine/rt/ray_cone.h"

namespace diptych {

ParamSchema RtPathPass::schema() {
  return {ParamSpec::integer("spp", 16, 1, 1 << 20, "paths per pixel"),
          ParamSpec::number("time_budget_ms", 0.0, 0.0, 1e9,
                            "stop adding samples after this wall time (0: no budget)"),
          ParamSpec::integer("max_depth", 16, 1, 1024, "maximum path length in bounces"),
          ParamSpec::integer("rr_depth", 3, 1, 1024, "bounce from which Russian roulette applies"),
          ParamSpec::boolean("russian_roulette", true, "terminate paths by Russian roulette"),
          ParamSpec::integer("seed", 0, 0, 1 << 30, "random seed"),
          ParamSpec::choice("texture_lod", "level0", {"level0", "cone"},
                            "texture level at traced hits: level 0, or ray cones (RTG ch. 20) "
                            "until a smooth bounce")};
}

void RtPathPass::setup(PassBuilder& b) {
  b.needs(SceneNeed::Geometry);
  spp_ = b.params().integer("spp");
  timeBudgetMs_ = b.params().number("time_budget_ms");
  maxDepth_ = b.params().integer("max_depth");
  rrDepth_ = b.params().integer("rr_depth");
  russianRoulette_ = b.params().boolean("russian_roulette");
  seed_ = b.params().integer("seed");
  rayCones_ = b.params().string("texture_lod") == "cone";
  const ResourceDesc desc{Format::RGBA32F, b.frame().width, b.frame().height};
  color_ = b.write("color", desc, vec4(0.f, 0.f, 0.f, 1.f));
  variance_ = b.write("variance", desc, vec4(0.f));
}

void RtPathPass::execute(PassContext& c) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  RenderWorld& world = c.world();
  const FrameSettings& frame = c.frame();
  const PathTracer tracer(world.scene(), world.geometry(), world.rtScene(),
                          {maxDepth_, rrDepth_, russianRoulette_, rayCones_});
  // Each of the spp paths stands for about 1/spp of the pixel's area (as rt_distributed's strata).
  const float spread = pixelSpreadAngle(frame.camera, frame.height) / std::sqrt(float(spp_));
  // Welford accumulators, alive only for this execute: the mean and the sum of squared
  // deviations M2 per pixel and channel.
  const std::size_t pixels = std::size_t(frame.width) * std::size_t(frame.height);
  std::vector<glm::dvec3> mean(pixels, glm::dvec3(0.0)), m2(pixels, glm::dvec3(0.0));
  std::atomic<std::uint64_t> rays{0}, invalid{0};
  const ThinLensFrame lensFrame(frame.camera, frame.width, frame.height);
  int passes = 0;
  while (passes < spp_) {
    const double n = passes + 1;
    tbb::parallel_for(0, frame.height, [&](int y) {
      std::uint64_t rowRays = 0, rowInvalid = 0;
      for (int x = 0; x < frame.width; ++x) {
        const std::size_t i = std::size_t(y) * std::size_t(frame.width) + std::size_t(x);
        PathRng rng{std::uint32_t(i), std::uint32_t(passes), std::uint32_t(seed_)};
        const vec2 jitter = rng.next2();
        const vec2 lens = rng.next2();
        const Ray ray = lensFrame.ray(float(x) + jitter.x, float(y) + jitter.y, lens);
        const PathSample s = tracer.radiance(ray, rng, spread);
        rowRays += s.rays;
        rowInvalid += s.valid ? 0 : 1;
        const glm::dvec3 value(s.radiance);
        const glm::dvec3 delta = value - mean[i];
        mean[i] += delta / n;
        m2[i] += delta * (value - mean[i]);
      }
      rays.fetch_add(rowRays, std::memory_order_relaxed);
      invalid.fetch_add(rowInvalid, std::memory_order_relaxed);
    });
    ++passes;
    const double elapsedMs =
        std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    if (timeBudgetMs_ > 0.0 && elapsedMs >= timeBudgetMs_) break;
  }

  CpuImage& color = c.cpuWrite(color_);
  CpuImage& variance = c.cpuWrite(variance_);
  const double n = passes;
  tbb::parallel_for(0, frame.height, [&](int y) {
    for (int x = 0; x < frame.width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(frame.width) + std::size_t(x);
      const glm::dvec3 varianceOfMean = n > 1 ? m2[i] / ((n - 1) * n) : glm::dvec3(0.0);
      for (int ch = 0; ch < 3; ++ch) {
        color.setF(x, y, ch, float(mean[i][ch]));
        variance.setF(x, y, ch, float(varianceOfMean[ch]));
      }
      color.setF(x, y, 3, 1.f);
      variance.setF(x, y, 3, float(n));
    }
  });
  c.count("rays", double(rays.load()));
  c.count("samples", n * double(pixels));
  c.count("passes", n);
  c.count("invalid_samples", double(invalid.load()));
}

}  // namespace diptych
