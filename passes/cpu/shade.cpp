#include "passes/cpu/shade.h"

#include <tbb/parallel_for.h>

#include "engine/graph/render_world.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/environment.h"
#include "engine/shading/shading.h"
#include "passes/common/exact_hits.h"
#include "passes/raster/gbuffer_surface.h"
#include "passes/raster/gl_shade.h"
#include "passes/slots.h"

namespace diptych {
namespace {

// The texture_filtering slot's C and coverage replace shade's own level-0 lookup (a = -1: none
// there). Not for materials whose metallic-roughness texture re-maps C per texel: the signal is
// C = colour x texture, which that mapping does not take as input (docs/textures.md).
void applyAlbedo(SurfacePoint& sp, const Scene& scene, const CpuImage& albedo, int x, int y) {
  const float a = albedo.f(x, y, 3);
  if (a < 0.f || scene.material(sp.material).metallicRoughnessTexture >= 0) return;
  sp.resolved.color = vec3(albedo.f(x, y, 0), albedo.f(x, y, 1), albedo.f(x, y, 2));
  sp.resolved.baseColor = sp.resolved.color;  // the glTF model's C
  sp.resolved.alpha = a;
}

}  // namespace

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
  lightVisibility_ = b.readOptional("light_visibility", Format::R32F);
  reflection_ = b.readOptional("reflection", Format::RGBA32F);
  transmission_ = b.readOptional("transmission", Format::RGBA32F);
  albedo_ = b.readOptional("albedo", Format::RGBA32F);
  color_ = b.write("color", {Format::RGBA32F, w, h}, vec4(0.f, 0.f, 0.f, 1.f));
}

void ShadePass::execute(PassContext& c) {
  if (domain_ == Domain::Gl)
    return shadeOnGl(
        c, {hits_, lightVisibility_, reflection_, transmission_, albedo_, color_, surface_});
  RenderWorld& world = c.world();
  const Scene& scene = world.scene();
  const FrameSettings& frame = c.frame();
  const CpuImage& hits = c.cpuRead(hits_);
  const CpuImage* visibility =
      lightVisibility_ == kNoResource ? nullptr : &c.cpuRead(lightVisibility_);
  const CpuImage* reflection = reflection_ == kNoResource ? nullptr : &c.cpuRead(reflection_);
  const CpuImage* transmission = transmission_ == kNoResource ? nullptr : &c.cpuRead(transmission_);
  const CpuImage* albedo = albedo_ == kNoResource ? nullptr : &c.cpuRead(albedo_);
  CpuImage& out = c.cpuWrite(color_);

  std::vector<shading::ShadingLight> lights;
  for (const Light& l : scene.lights) lights.push_back(shading::toShadingLight(l));
  const int visibilityLayers = visibility ? visibility->desc.layers : 0;
  auto rgb = [](const CpuImage* s, int x, int y) {
    return s ? vec3(s->f(x, y, 0), s->f(x, y, 1), s->f(x, y, 2)) : vec3(0.f);
  };

  // The camera frame once per image (PinholeFrame::ray == primaryRay bit for bit).
  const PinholeFrame pinhole(frame.camera, frame.width, frame.height);
  const ExactHitBuffer& exact = exactHits(world, hits, frame.camera);
  tbb::parallel_for(0, frame.height, [&](int y) {
    for (int x = 0; x < frame.width; ++x) {
      const Ray eye = pinhole.ray(x + 0.5f, y + 0.5f);
      const auto hit = exact.at(x, y);
      vec3 radiance;
      if (!hit) {
        radiance = sampleEnvironment(scene.environment, eye.direction);
      } else {
        SurfacePoint sp = makeSurfacePoint(scene, world.geometry(), *hit, eye.direction);
        if (albedo) applyAlbedo(sp, scene, *albedo, x, y);
        const vec3 v = -eye.direction;
        radiance = shading::emittedAndAmbient(sp.resolved, scene.ambient);
        for (std::size_t i = 0; i < lights.size(); ++i) {
          const float vis = int(i) < visibilityLayers ? visibility->f(x, y, 0, int(i)) : 1.f;
          const shading::LightSample s = shading::sampleLight(lights[i], sp.position);
          radiance += shading::lightContribution(sp.resolved, sp.shadingNormal, v, s, vis);
        }
        // The reflection signal's alpha says whether it is a mirror ray or a prefiltered lobe.
        const float reflectionAlpha = reflection ? reflection->f(x, y, 3) : 0.f;
        radiance +=
            shading::secondaryTermsOf(sp.resolved, sp.shadingNormal, v, rgb(reflection, x, y),
                                      reflectionAlpha, rgb(transmission, x, y));
      }
      for (int ch = 0; ch < 3; ++ch) out.setF(x, y, ch, radiance[ch]);
      out.setF(x, y, 3, 1.f);
    }
  });
}

}  // namespace diptych
