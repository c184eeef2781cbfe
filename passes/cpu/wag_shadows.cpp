#include "passes/cpu/wag_shadows.h"

#include <tbb/parallel_for.h>

#include <bit>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/timing.h"
#include "engine/graph/render_world.h"
#include "engine/scene/lit_polygons.h"
#include "passes/common/hits_texel.h"

namespace diptych {
namespace {

// The lit polygons of a world's lights, built once (update "static").
struct WagShadowsCache {
  std::vector<std::unique_ptr<LitPolygons>> lights;
  bool built = false;
};

std::vector<std::unique_ptr<LitPolygons>> buildLitPolygons(const RenderWorld& world) {
  const WorldGeometry& geometry = world.geometry();
  std::vector<bool> casts(geometry.meshes.size());
  for (std::size_t m = 0; m < casts.size(); ++m)
    casts[m] = world.scene().material(geometry.meshes[m].material).castsShadows;
  std::vector<std::unique_ptr<LitPolygons>> out;
  for (const Light& light : world.scene().lights)
    out.push_back(std::make_unique<LitPolygons>(geometry, casts, light));
  return out;
}

}  // namespace

ParamSchema WagShadowsPass::schema() {
  return {ParamSpec::choice("update", "static", {"static", "every_frame"},
                            "build the lit polygons once per world (static) or every frame")};
}

void WagShadowsPass::setup(PassBuilder& b) {
  everyFrame_ = b.params().string("update") == "every_frame";
  io_ = slotIo(b, "visibility");
}

void WagShadowsPass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  const CpuImage& hits = c.cpuRead(io_.hits);
  CpuImage& out = c.cpuWrite(io_.signal);
  const int w = hits.desc.width, h = hits.desc.height;
  const std::size_t lightCount = world.scene().lights.size();
  checkVisibilitySignal(out, w, h, lightCount, "wag_shadows");
  // The hidden-surface step from each light: once per world, or in this frame.
  const Stopwatch clock;
  std::vector<std::unique_ptr<LitPolygons>> ownLights;
  auto& cache = world.cpuCached<WagShadowsCache>();
  const std::vector<std::unique_ptr<LitPolygons>>* lit = &cache.lights;
  if (everyFrame_) {
    ownLights = buildLitPolygons(world);
    lit = &ownLights;
  } else if (!cache.built) {
    cache.lights = buildLitPolygons(world);
    cache.built = true;
    world.addOneTime("wag_shadows build", clock.milliseconds());
  }
  LitPolygons::Stats stats;
  for (const auto& l : *lit) {
    stats.polygons += l->stats().polygons;
    stats.clips += l->stats().clips;
    stats.pieces += l->stats().pieces;
    stats.partial += l->stats().partial;
    stats.shadowed += l->stats().shadowed;
  }
  c.count("wag_polygons", double(stats.polygons));
  c.count("wag_occluder_clips", double(stats.clips));
  c.count("wag_lit_pieces", double(stats.pieces));
  c.count("wag_partial_triangles", double(stats.partial));
  c.count("wag_shadowed_triangles", double(stats.shadowed));
  // Each pixel: the G-buffer's triangle and its point on it (no analytic lift: the lit pieces
  // are the tessellation's), looked up in that triangle's lit pieces for every light.
  const PinholeFrame pinhole(c.frame().camera, w, h);
  const WorldGeometry& geometry = world.geometry();
  tbb::parallel_for(0, h, [&](int y) {
    thread_local std::vector<std::optional<SurfaceHit>> row;
    row.resize(std::size_t(w));
    for (int x = 0; x < w; ++x) {
      row[std::size_t(x)] = triangleTexel(hits, geometry, pinhole, x, y);
      // A texel naming no triangle of this world is an Error (hits_texel.h), not a stray read.
      if (const auto& hit = row[std::size_t(x)];
          hit && hit->primitive >= texelMesh(geometry, *hit).indices.size() / 3)
        throw Error("G-buffer hits texel: primitive " + std::to_string(hit->primitive) +
                    " out of range in instance " + std::to_string(hit->instance));
    }
    for (int l = 0; l < out.desc.layers; ++l) {
      std::uint32_t* texels = out.row(y, l);
      for (int x = 0; x < w; ++x) {
        const auto& hit = row[std::size_t(x)];
        const float v =
            hit && std::size_t(l) < lightCount
                ? (*lit)[std::size_t(l)]->visibility(hit->instance, hit->primitive, hit->u, hit->v)
                : 1.f;
        texels[x] = std::bit_cast<std::uint32_t>(v);
      }
    }
  });
}

}  // namespace diptych
