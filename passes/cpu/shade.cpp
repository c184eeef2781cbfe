#include "passes/cpu/shade.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <new>
#include <vector>

#include "engine/graph/companion.h"
#include "engine/graph/render_world.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/environment.h"
#include "engine/shading/shading.h"
#include "passes/common/exact_hits.h"
#include "passes/raster/gbuffer_surface.h"
#include "passes/raster/gl_shade.h"
#include "passes/slots.h"

namespace diptych {

ParamSchema ShadePass::schema() {
  return {ParamSpec::choice("domain", "auto", {"auto", "gl", "cpu"},
                            "where shade runs; auto: where its inputs live (docs/frame-graph.md)")};
}

void ShadePass::setup(PassBuilder& b) {
  const std::string domain = b.params().string("domain");
  auto_ = domain == "auto";
  domain_ = domain == "gl" ? Domain::Gl : Domain::Cpu;
  const int w = b.frame().width, h = b.frame().height;
  hits_ = b.read(kHits, Format::RGBA32UI);
  surface_ = readSurface(b, hits_);  // GL only: dropped when placed on the CPU
  // GL only too: the G-buffer's depth splits GL shade into background and surfaces (gl_shade.h).
  depth_ = readCompanion(b, hits_, "depth", Format::D32F, true);
  lightVisibility_ = b.readOptional("light_visibility", Format::R32F);
  reflection_ = b.readOptional("reflection", Format::RGBA32F);
  transmission_ = b.readOptional("transmission", Format::RGBA32F);
  albedo_ = b.readOptional("albedo", Format::RGBA32F);
  color_ = b.write("color", {Format::RGBA32F, w, h}, vec4(0.f, 0.f, 0.f, 1.f));
}

void ShadePass::execute(PassContext& c) {
  if (domain_ == Domain::Gl)
    return shadeOnGl(c, {hits_, lightVisibility_, reflection_, transmission_, albedo_, color_,
                         surface_, depth_});
  RenderWorld& world = c.world();
  const Scene& scene = world.scene();
  const FrameSettings& frame = c.frame();
  const CpuImage* visibility =
      lightVisibility_ == kNoResource ? nullptr : &c.cpuRead(lightVisibility_);
  const CpuImage* reflection = reflection_ == kNoResource ? nullptr : &c.cpuRead(reflection_);
  const CpuImage* transmission = transmission_ == kNoResource ? nullptr : &c.cpuRead(transmission_);
  const CpuImage* albedo = albedo_ == kNoResource ? nullptr : &c.cpuRead(albedo_);
  CpuImage& out = c.cpuWrite(color_);

  std::vector<shading::ShadingLight> lights;
  for (const Light& l : scene.lights) lights.push_back(shading::toShadingLight(l));
  const int visibilityLayers = visibility ? visibility->desc.layers : 0;

  // The camera frame once per image (PinholeFrame::ray == primaryRay bit for bit).
  const PinholeFrame pinhole(frame.camera, frame.width, frame.height);
  const ExactHitBuffer& exact = exactHits(c, hits_);
  const int outChannels = out.channels();
  tbb::parallel_for(0, frame.height, [&](int y) {
    // Row addresses once per row (issue 14: per-texel accessors were a tenth of this loop).
    const CpuFloatRow reflectionRow(reflection, y), transmissionRow(transmission, y);
    const CpuFloatRow albedoRow(albedo, y);
    std::uint32_t* outRow = out.row(y);
    // Light i's visibility row (layer i, R32F: pixel x is word x), for the lights it covers.
    thread_local std::vector<const std::uint32_t*> visibilityRows;
    visibilityRows.resize(std::size_t(std::min<int>(visibilityLayers, int(lights.size()))));
    for (std::size_t i = 0; i < visibilityRows.size(); ++i)
      visibilityRows[i] = visibility->row(y, int(i));
    // Two sweeps per row: first every surface point, then the shading. In one sweep the shading
    // copied each point's material (passed by value, shading.glsl) right after makeSurfacePoint
    // wrote it, and those loads stalled on the not yet retired stores (store-to-load forwarding
    // fails across store widths): about a third of this loop's time (perf, issue 14). The
    // scratch is per thread: nothing in a row's body spawns TBB work, so no thread interleaves
    // rows.
    thread_local std::vector<SurfacePoint> points;
    thread_local std::vector<vec3> eyes;
    thread_local std::vector<char> covered;
    points.resize(std::size_t(frame.width));
    eyes.resize(std::size_t(frame.width));
    covered.resize(std::size_t(frame.width));
    pinhole.rowDirections(y, eyes);
    const SurfaceHit* hit = exact.row(y);  // instance -1: background (no optional per pixel)
    for (int x = 0; x < frame.width; ++x) {
      covered[x] = hit[x].instance >= 0;
      if (!covered[x]) continue;
      // Built in place (the prvalue initialises the slot: C++17 guaranteed elision); assigned,
      // the ~250-byte point went through a stack temporary and was copied (perf, issue 14).
      // SurfacePoint is trivially destructible, so the slot's old value needs no destructor.
      // A mirror's or a glass's point was made by rt_reflection or rt_transmission this frame
      // (ExactHitBuffer::point): copied, ~30 instructions against makeSurfacePoint's ~540.
      if (const SurfacePoint* kept = exact.keptPoint(x, y))
        ::new (&points[x]) SurfacePoint(*kept);
      else
        ::new (&points[x]) SurfacePoint(makeSurfacePoint(scene, world.geometry(), hit[x], eyes[x]));
      // The texture_filtering signal replaces shade's own level-0 lookup (a < 0: none there).
      if (albedoRow) applyTextureSignal(points[x], scene, vec4(albedoRow.rgb(x), albedoRow(x, 3)));
    }
    for (int x = 0; x < frame.width; ++x) {
      vec3 radiance;
      if (!covered[x]) {
        radiance = sampleEnvironment(scene.environment, eyes[x]);
      } else {
        const SurfacePoint& sp = points[x];
        const vec3 v = -eyes[x];
        radiance = shading::emittedAndAmbient(sp.resolved, scene.ambient);
        for (std::size_t i = 0; i < lights.size(); ++i) {
          const float vis = i < visibilityRows.size()
                                ? std::bit_cast<float>(visibilityRows[i][std::size_t(x)])
                                : 1.f;
          const shading::LightSample s = shading::sampleLight(lights[i], sp.position);
          radiance += shading::lightContribution(sp.resolved, sp.shadingNormal, v, s, vis);
        }
        // The reflection signal's alpha says whether it is a mirror ray or a prefiltered lobe.
        radiance +=
            shading::secondaryTermsOf(sp.resolved, sp.shadingNormal, v, reflectionRow.rgb(x),
                                      reflectionRow(x, 3), transmissionRow.rgb(x));
      }
      std::uint32_t* texel = outRow + std::size_t(x) * std::size_t(outChannels);
      for (int ch = 0; ch < 3; ++ch) texel[ch] = std::bit_cast<std::uint32_t>(radiance[ch]);
      texel[3] = std::bit_cast<std::uint32_t>(1.f);
    }
  });
}

}  // namespace diptych
