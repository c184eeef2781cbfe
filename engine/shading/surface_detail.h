#pragma once
// The "surface detail" comparison axis (docs/materials.md#bump-vs-normal-maps): one height field
// per material (its BumpMap, the lecture's f_h with k and Delta) rendered four ways.
//  - Bump:      as authored, the lecture's normal perturbation at every shading point;
//  - Flat:      the bump removed (the unperturbed normal);
//  - NormalMap: the bump replaced by a tangent-space normal map baked from the same height field
//               (bakeNormalMap), sampled as glTF normalTexture;
//  - Displaced: the exact answer: the surface tessellated finely and every vertex moved by
//               k f_h(u, v) along its normal (displaceSurfaces), traced as triangles.
#include <string>

#include "engine/scene/scene.h"

namespace diptych {

enum class SurfaceDetail { Bump, Flat, NormalMap, Displaced };

// "bump", "flat", "normal_map", "displaced"; std::nullopt for anything else.
std::optional<SurfaceDetail> parseSurfaceDetail(const std::string& text);
const char* surfaceDetailName(SurfaceDetail mode);

bool hasBumpMaps(const Scene& scene);

// The scene with its bump-mapped materials rendered as `mode` says (Bump: unchanged). Analytic
// shapes of bump-mapped materials are tessellated for Displaced (at 256 segments, then refined as
// below). Throws Error when the displaced scene would exceed kMaxDisplacedTriangles.
Scene withSurfaceDetail(const Scene& scene, SurfaceDetail mode);

// Displaced: each triangle of a bump-mapped mesh is split into n x n (n from its longest uv edge
// over the height field's sampling step: 1/16 of the sinusoid's shortest period, or one texel),
// in world space, each new vertex moved to P + k f_h(uv) N (N: the interpolated unit normal) and
// given the displaced surface's exact normal, normalize(dQ/db1 x dQ/db2) with
// dQ/db = dP/db + k (df/db) N + k f dN/db over the parent triangle's barycentrics b.
constexpr std::size_t kMaxDisplacedTriangles = 8u << 20;

// A tangent-space normal map of `resolution`^2 texels (linear RGBA32F, repeat, bilinear) baked
// from the bump map with the lecture's formula on a flat frame of the given metric: at each texel
// centre, d_u and d_v by the same central differences (k, Delta), t_u = metric.x T,
// t_v = -metric.y B (glTF's v grows down the image, the tangent convention of
// computeVertexTangents), n' = bumpNormal(t_u, t_v, N, d_u, d_v), texel = (n' + 1) / 2 in
// (T, B, N). The metric is the surface's |dP/du|, |dP/dv|; a map has one, so it is exact where
// the surface's metric equals it (a plane) and not elsewhere (a sphere toward its poles).
Texture bakeNormalMap(const Scene& scene, const BumpMap& bump, vec2 metric, int resolution);

}  // namespace diptych
