#include "passes/rt/rt_path.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <new>
#include <vector>

#include "engine/graph/render_world.h"
#include "engine/rt/camera_rays.h"
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
  std::atomic<std::uint64_t> rays{0}, invalid{0};
  const ThinLensFrame lensFrame(frame.camera, frame.width, frame.height);
  const bool shutter = world.scene().hasMotion();
  // Paths k = 0..n-1 of row y (n <= kChunk), pixel x and pass of sampleOf(k): their camera
  // rays traced as one coherent Embree stream (CameraRays::intersectRays), then the chunk as
  // PathTracer's wavefront; each sample handed to add(k, sample) in order.
  constexpr int kChunk = int(PathTracer::kMaxPaths);
  const CameraRays camera{world.rtScene(), world.scene(), world.geometry()};
  auto traceChunk = [&](int y, int n, auto sampleOf, auto add) {
    PathRng rngs[kChunk];
    Ray rays[kChunk];
    Hit hits[kChunk];
    const Hit* found[kChunk];
    for (int k = 0; k < n; ++k) {
      const auto [x, pass] = sampleOf(k);
      const std::size_t i = std::size_t(y) * std::size_t(frame.width) + std::size_t(x);
      rngs[k] = PathRng{std::uint32_t(i), std::uint32_t(pass), std::uint32_t(seed_)};
      const vec2 jitter = rngs[k].next2();
      const vec2 lens = rngs[k].next2();
      // In place, as rt_distributed's sample rays (a store-forwarding stall when assigned).
      ::new (static_cast<void*>(&rays[k]))
          Ray(lensFrame.ray(float(x) + jitter.x, float(y) + jitter.y, lens));
      // Motion blur: each path at its own time in the shutter (drawn only where something
      // moves, so a static scene's paths keep their random sequence).
      if (shutter) rays[k].time = rngs[k].next();
    }
    const std::size_t count = std::size_t(n);
    camera.intersectRays({rays, count}, {hits, count}, {found, count}, false);
    PathSample samples[kChunk];
    tracer.radiance({rays, count}, {found, count}, {rngs, count}, spread, {samples, count});
    for (int k = 0; k < n; ++k) add(k, samples[k]);
  };
  // Welford's update of a pixel's mean and sum of squared deviations M2 by its n-th sample.
  auto welford = [](const PathSample& s, double n, glm::dvec3& mean, glm::dvec3& m2) {
    const glm::dvec3 value(s.radiance);
    const glm::dvec3 delta = value - mean;
    mean += delta / n;
    m2 += delta * (value - mean);
  };
  CpuImage& color = c.cpuWrite(color_);
  CpuImage& variance = c.cpuWrite(variance_);
  auto store = [&](int x, int y, double n, const glm::dvec3& mean, const glm::dvec3& m2) {
    const glm::dvec3 varianceOfMean = n > 1 ? m2 / ((n - 1) * n) : glm::dvec3(0.0);
    for (int ch = 0; ch < 3; ++ch) {
      color.setF(x, y, ch, float(mean[ch]));
      variance.setF(x, y, ch, float(varianceOfMean[ch]));
    }
    color.setF(x, y, 3, 1.f);
    variance.setF(x, y, 3, float(n));
  };
  int passes = 0;
  if (!(timeBudgetMs_ > 0.0)) {
    // No budget: a pixel's spp paths one after another, the accumulators in registers. The same
    // samples in the same order as pass by pass (each depends only on pixel, pass and seed);
    // no image of accumulators makes spp round trips through memory. Sample indices in 64
    // bits: width x spp can pass 2^31 (spp goes up to 2^20).
    passes = spp_;
    tbb::parallel_for(0, frame.height, [&](int y) {
      std::uint64_t rowRays = 0, rowInvalid = 0;
      glm::dvec3 mean(0.0), m2(0.0);
      const std::int64_t samples = std::int64_t(frame.width) * spp_;
      for (std::int64_t begin = 0; begin < samples; begin += kChunk) {
        traceChunk(
            y, int(std::min<std::int64_t>(kChunk, samples - begin)),
            [&](int k) {
              return std::pair{int((begin + k) / spp_), int((begin + k) % spp_)};
            },
            [&](int k, const PathSample& s) {
              const int x = int((begin + k) / spp_), pass = int((begin + k) % spp_);
              if (pass == 0) mean = m2 = glm::dvec3(0.0);
              rowRays += s.rays;
              rowInvalid += s.valid ? 0 : 1;
              welford(s, double(pass + 1), mean, m2);
              if (pass + 1 == spp_) store(x, y, double(spp_), mean, m2);
            });
      }
      rays.fetch_add(rowRays, std::memory_order_relaxed);
      invalid.fetch_add(rowInvalid, std::memory_order_relaxed);
    });
  } else {
    // Progressive: whole passes over the image until the budget is spent at the end of one.
    const std::size_t pixels = std::size_t(frame.width) * std::size_t(frame.height);
    std::vector<glm::dvec3> mean(pixels, glm::dvec3(0.0)), m2(pixels, glm::dvec3(0.0));
    while (passes < spp_) {
      tbb::parallel_for(0, frame.height, [&](int y) {
        std::uint64_t rowRays = 0, rowInvalid = 0;
        for (int begin = 0; begin < frame.width; begin += kChunk) {
          traceChunk(
              y, std::min(kChunk, frame.width - begin),
              [&](int k) {
                return std::pair{begin + k, passes};
              },
              [&](int k, const PathSample& s) {
                const std::size_t i =
                    std::size_t(y) * std::size_t(frame.width) + std::size_t(begin + k);
                rowRays += s.rays;
                rowInvalid += s.valid ? 0 : 1;
                welford(s, double(passes + 1), mean[i], m2[i]);
              });
        }
        rays.fetch_add(rowRays, std::memory_order_relaxed);
        invalid.fetch_add(rowInvalid, std::memory_order_relaxed);
      });
      ++passes;
      const double elapsedMs =
          std::chrono::duration<double, std::milli>(Clock::now() - start).count();
      if (elapsedMs >= timeBudgetMs_) break;
    }
    tbb::parallel_for(0, frame.height, [&](int y) {
      for (int x = 0; x < frame.width; ++x) {
        const std::size_t i = std::size_t(y) * std::size_t(frame.width) + std::size_t(x);
        store(x, y, double(passes), mean[i], m2[i]);
      }
    });
  }
  const double n = passes;
  const std::size_t pixels = std::size_t(frame.width) * std::size_t(frame.height);
  c.count("rays", double(rays.load()));
  c.count("samples", n * double(pixels));
  c.count("passes", n);
  c.count("invalid_samples", double(invalid.load()));
}

}  // namespace diptych
