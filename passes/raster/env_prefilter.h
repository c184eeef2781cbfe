#pragma once
// GGX-prefiltered environment levels for the env_* reflection producers (docs/environment-maps.md,
// "Rough reflections"): level i of an n-level map holds, per texel direction R, the first factor
// of the split-sum approximation (Karis, "Real Shading in Unreal Engine 4", SIGGRAPH 2013):
//   L_pre(R) = sum_k L(l_k) (n.l_k) / sum_k (n.l_k),  h_k ~ GGX(alpha), n = v = R,
//   l_k = 2 (v.h_k) h_k - v,  alpha = roughness_i^2,  roughness_i = i / (n - 1).
// The raster lookup reads lod = roughness (n - 1) with trilinear filtering between levels. The
// samples read a box-filtered cube mip chain of the environment at the level that matches each
// sample's solid angle (filtered importance sampling, Colbert and Krivanek, GPU Gems 3 ch. 20),
// so a few dozen samples per texel give a smooth result. Our own code, CPU, TBB.
#include <array>
#include <functional>
#include <vector>

#include "engine/core/image.h"
#include "engine/scene/scene.h"

namespace diptych::envmap {

// Levels of a prefiltered map whose level 0 is width x height: at most 6 (roughness steps of
// 0.2), and no level under 4 texels on its short side.
int prefilterLevelCount(int width, int height);

// The environment resampled to a cube (2x2 supersampled) with box-filtered mips down to 1 texel.
class CubeChain {
 public:
  CubeChain(const Environment& env, int size);
  // Bilinear within the face, linear between levels; lod in texel levels of this chain.
  vec3 sample(const vec3& direction, float lod) const;
  int size() const { return size_; }

 private:
  vec3 sampleLevel(int level, int face, vec2 st) const;
  int size_;
  std::vector<std::array<Image, 6>> levels_;  // RGB, level 0 size_ x size_
};

// One prefiltered level: width x height RGBA texels (alpha 1), direction(st) the unit world
// direction through texel centre st in [0,1]^2 (t = 0 on the top row), as env_maps.h resamples.
Image prefilteredLevel(const CubeChain& source, int width, int height, float roughness,
                       const std::function<vec3(vec2)>& direction);

// Prefiltered levels as cube faces in world space: what env_sphere's levels hold, made
// independent of the view, so that turning the camera only resamples them (resampledLevel)
// instead of integrating again. levels[i] for i >= 1 (levels[0] stays empty: level 0 is the map).
struct PrefilteredCube {
  std::vector<std::array<Image, 6>> levels;
  vec3 sample(int level, const vec3& direction) const;  // bilinear within the face
};

// Levels 1 .. faceSides.size() - 1, level i at roughness i / (n - 1) with faces faceSides[i].
PrefilteredCube prefilteredCube(const CubeChain& source, const std::vector<int>& faceSides);

// width x height RGBA (alpha 1) of one PrefilteredCube level looked up at direction(st).
Image resampledLevel(const PrefilteredCube& cube, int level, int width, int height,
                     const std::function<vec3(vec2)>& direction);

}  // namespace diptych::envmap
