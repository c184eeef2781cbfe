#pragma once
// Variants of a comparison: a recipe plus slot overrides. The default set covers every
// registered producer of every slot (docs/compare.md).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/graph/recipe.h"
#include "engine/graph/registry.h"
#include "engine/scene/scene.h"
#include "passes/rt/texture_supersample.h"

namespace diptych::cli {

// N of the texture_filtering slot's exact answer when measuring against it (compare's default
// --texture-samples, sweep's exact frame): each pixel's texture colour over N x N sub-pixel rays.
// The built-in hybrid recipe itself uses N = 1 (the pixel centre), its cheap form.
inline constexpr int kExactTextureSamples = TextureSupersamplePass::kDefaultSamples;

// The built-in hybrid recipe with its texture_supersample at N = textureSamples.
Recipe exactHybridRecipe(int textureSamples);

struct Variant {
  std::string name;
  std::string recipeFile;          // empty: the built-in hybrid recipe
  std::vector<std::string> slots;  // --slot overrides, "SLOT=TYPE[:k=v,...]"
  // > 0: the scene's analytic quadrics are traced as tessellations of this many segments
  // (tessellateAnalytic), the "geometry" axis; 0: as the scene says.
  int tessellation = 0;
  // "flat", "bump", "normal_map" or "displaced": how bump-mapped materials are rendered, the
  // "surface detail" axis (engine/shading/surface_detail.h); empty: as the scene says (bump).
  std::string surfaceDetail;
  // > 1: the accumulation buffer (Haeberli and Akeley, SIGGRAPH 1990), the raster side's motion
  // blur: the frame rendered on the scene's static snapshots (sceneAtTime) at the N instants
  // (k + 1/2) / N of the shutter, k = 0..N-1, and the images averaged; its time is the N frames'.
  // 0: the frame's instant, as every other variant.
  int shutterSamples = 0;
  // The recipe with the overrides applied. exactTextureSamples > 0: the recipe's (built-in or
  // file) texture_supersample, the texture_filtering slot's exact producer, takes N = that many
  // samples per axis before the overrides (compare's --texture-samples), and so do its
  // rt_reflection and rt_transmission (their texture_samples: the footprint of the textures seen
  // in a mirror or through glass); an override of the slot sets its own.
  Recipe build(const PassRegistry& registry, int exactTextureSamples = 0) const;
};

std::vector<Variant> defaultVariants(const PassRegistry& registry);
// The geometry axis, added to the defaults when the scene has analytic quadrics: the all-exact
// hybrid with them tessellated at 16, 64 and 256 segments.
std::vector<Variant> geometryVariants();
// The texture-LOD axis at traced hits, added to the defaults where the scene has colour textures
// and mirrors (reflective) or glass (transmissive): rt_reflection / rt_transmission with the
// secondary hits' own level-0 lookup, and with ray cones (texture_lod=cone), both measured
// against the exact producers' footprint (--texture-samples).
std::vector<Variant> textureLodVariants(bool reflective, bool transmissive);
// The surface-detail axis, added to the defaults when the scene has bump maps: the all-exact
// hybrid with them flat, bump-mapped, normal-mapped (baked from the same height) and displaced.
std::vector<Variant> surfaceDetailVariants();
// The motion-blur axis, added to the defaults when something in the scene moves: the all-raster
// and the all-exact hybrid frames through the accumulation buffer of 8 instants.
std::vector<Variant> motionVariants(const PassRegistry& registry);
// The scene a variant runs on: tessellated (geometry axis), then with its surface detail
// rendered as the variant says; std::nullopt when that is the scene itself.
std::optional<Scene> variantScene(const Scene& scene, const Variant& variant);
// The scene state variantScene gives a variant, for compare's frame signature (same_frame.h):
// {"tessellation": N, or 0 for as authored; "surface_detail": the mode it applies, or "as
// authored" (also where the scene has no bump maps, or the mode is bump: nothing changes);
// "shutter_samples": its accumulation buffer's N, or 0}.
nlohmann::json variantSceneState(const Scene& scene, const Variant& variant);
// A .json file ({"variants": [{"name", "recipe"?, "slots"?}]}) or comma-separated names from
// the default set. Throws InputError naming the file/element or the unknown name.
std::vector<Variant> loadVariants(const std::string& spec, const PassRegistry& registry);

// The reference: "whitted", "distributed:SPP" or "path:SPP" -> a one-pass recipe.
struct ReferenceSpec {
  std::string text, passType;
  int spp = 1;
  // rt_whitted's texture_samples (passes/rt/rt_whitted.h): > 1 averages each pixel's texture
  // colour over N x N sub-pixel rays, the texture_filtering slot's exact answer.
  int textureSamples = 1;
  Recipe recipe() const;
};
ReferenceSpec parseReference(const std::string& text, const PassRegistry& registry);

}  // namespace diptych::cli
