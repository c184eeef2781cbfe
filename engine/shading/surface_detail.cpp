#include "engine/shading/surface_detail.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/core/error.h"
#include "engine/scene/primitives.h"
#include "engine/shading/bump.h"
#include "engine/shading/texture_sampling.h"

namespace diptych {

std::optional<SurfaceDetail> parseSurfaceDetail(const std::string& text) {
  for (SurfaceDetail m : {SurfaceDetail::Bump, SurfaceDetail::Flat, SurfaceDetail::NormalMap,
                          SurfaceDetail::Displaced})
    if (text == surfaceDetailName(m)) return m;
  return std::nullopt;
}

const char* surfaceDetailName(SurfaceDetail mode) {
  switch (mode) {
    case SurfaceDetail::Flat:
      return "flat";
    case SurfaceDetail::NormalMap:
      return "normal_map";
    case SurfaceDetail::Displaced:
      return "displaced";
    default:
      return "bump";
  }
}

bool hasBumpMaps(const Scene& scene) {
  return std::any_of(scene.materials.begin(), scene.materials.end(),
                     [](const Material& m) { return m.bump.has_value(); });
}

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// f_h and its exact gradient in uv: closed form for the sinusoid (in double), central
// differences over a quarter texel of the bilinear texture (exact inside a texel cell).
struct Height {
  double f = 0, fu = 0, fv = 0;
};

Height heightAt(const Scene& scene, const BumpMap& b, vec2 uv) {
  if (b.texture < 0) {
    const double a = kTwoPi * b.frequency.x * uv.x, c = kTwoPi * b.frequency.y * uv.y;
    return {b.amplitude * std::sin(a) * std::cos(c),
            b.amplitude * kTwoPi * b.frequency.x * std::cos(a) * std::cos(c),
            -b.amplitude * kTwoPi * b.frequency.y * std::sin(a) * std::sin(c)};
  }
  if (b.texture >= int(scene.textures.size())) return {};
  const Texture& t = scene.textures[std::size_t(b.texture)];
  const auto f = [&](vec2 at) { return double(sampleBilinear(t.image, at, t.wrapS, t.wrapT).x); };
  const float hu = 0.25f / float(std::max(t.image.width, 1));
  const float hv = 0.25f / float(std::max(t.image.height, 1));
  return {f(uv), (f(uv + vec2(hu, 0.f)) - f(uv - vec2(hu, 0.f))) / (2.0 * hu),
          (f(uv + vec2(0.f, hv)) - f(uv - vec2(0.f, hv))) / (2.0 * hv)};
}

// The uv distance between samples the displaced surface needs: 1/16 of the sinusoid's shortest
// period, or one texel of the height texture.
double samplingStep(const Scene& scene, const BumpMap& b) {
  if (b.texture < 0)
    return 1.0 / (16.0 * std::max({double(std::abs(b.frequency.x)), double(std::abs(b.frequency.y)),
                                   1.0}));
  if (b.texture >= int(scene.textures.size())) return 1.0;
  const Image& i = scene.textures[std::size_t(b.texture)].image;
  return 1.0 / double(std::max({i.width, i.height, 1}));
}

// One instance of a bump-mapped mesh, in world space (the height is in world units, as the
// bump's t_u, t_v are), each triangle split n x n and displaced.
Mesh displaceInstance(const Scene& scene, const Mesh& mesh, const mat4& transform,
                      const BumpMap& bump, std::size_t& budget) {
  const bool mirrored = glm::determinant(mat3(transform)) < 0.f;
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(mat3(transform))));
  std::vector<dvec3> p(mesh.positions.size()), nrm(mesh.positions.size(), dvec3(0.0));
  for (std::size_t i = 0; i < p.size(); ++i) {
    p[i] = dvec3(transform * vec4(mesh.positions[i], 1.f));
    if (mesh.normals.size() == p.size()) nrm[i] = normalMatrix * dvec3(mesh.normals[i]);
  }
  double longest = 0;  // one n for the whole mesh: neighbours split shared edges alike
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e)
      longest = std::max(longest, double(glm::length(mesh.uvs[mesh.indices[t + e]] -
                                                     mesh.uvs[mesh.indices[t + (e + 1) % 3]])));
  const int n = std::clamp(int(std::ceil(longest / samplingStep(scene, bump))), 1, 1024);
  const std::size_t triangles = mesh.indices.size() / 3 * std::size_t(n) * std::size_t(n);
  if (triangles > budget)
    throw Error("surface detail: displacing '" + mesh.name + "' needs " +
                std::to_string(triangles) + " triangles, above the limit of " +
                std::to_string(kMaxDisplacedTriangles));
  budget -= triangles;
  Mesh out;
  out.name = mesh.name + " (displaced)";
  out.material = mesh.material;
  const double k = bump.k;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    std::uint32_t v[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
    if (mirrored) std::swap(v[1], v[2]);
    const dvec3 face = glm::cross(p[v[1]] - p[v[0]], p[v[2]] - p[v[0]]);
    dvec3 vn[3];
    for (int c = 0; c < 3; ++c) vn[c] = glm::length(nrm[v[c]]) > 0.0 ? nrm[v[c]] : face;
    const dvec2 uv0(mesh.uvs[v[0]]), uv1(mesh.uvs[v[1]]), uv2(mesh.uvs[v[2]]);
    const auto base = std::uint32_t(out.positions.size());
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n - i; ++j) {
        // Weights from whole counts: a vertex on a shared edge is computed bit for bit alike from
        // both triangles (the third weight is exactly 0).
        const double w1 = double(i) / n, w2 = double(j) / n, w0 = double(n - i - j) / n;
        const dvec3 P = w0 * p[v[0]] + w1 * p[v[1]] + w2 * p[v[2]];
        const dvec3 nSum = w0 * vn[0] + w1 * vn[1] + w2 * vn[2];
        const double nLen = std::max(glm::length(nSum), 1e-300);
        const dvec3 N = nSum / nLen;
        const vec2 uv = vec2(w0 * uv0 + w1 * uv1 + w2 * uv2);
        const Height h = heightAt(scene, bump, uv);
        // dQ/db for Q = P + k f N over the barycentrics b1, b2 (b0 = 1 - b1 - b2).
        dvec3 dq[2];
        for (int d = 0; d < 2; ++d) {
          const dvec3 dP = p[v[d + 1]] - p[v[0]];
          const dvec2 dUv = (d == 0 ? uv1 : uv2) - uv0;
          const dvec3 dnSum = vn[d + 1] - vn[0];
          const dvec3 dN = (dnSum - N * glm::dot(N, dnSum)) / nLen;
          dq[d] = dP + k * (h.fu * dUv.x + h.fv * dUv.y) * N + k * h.f * dN;
        }
        dvec3 m = glm::cross(dq[0], dq[1]);
        if (glm::dot(m, N) < 0.0) m = -m;
        const double mLen = glm::length(m);
        out.positions.push_back(vec3(P + k * h.f * N));
        out.normals.push_back(mLen > 0.0 ? vec3(m / mLen) : vec3(N));
        out.uvs.push_back(uv);
      }
    // Row i starts at i (n + 1) - i (i - 1) / 2 (rows shrink by one).
    const auto at = [&](int i, int j) {
      return base + std::uint32_t(i * (n + 1) - i * (i - 1) / 2 + j);
    };
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n - i; ++j) {
        out.indices.insert(out.indices.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});
        if (j + 1 < n - i)
          out.indices.insert(out.indices.end(), {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
  }
  return out;
}

// Area-weighted mean |dP/du|, |dP/dv| over the world triangles of every instance of `material`.
vec2 materialMetric(const Scene& scene, int material) {
  double area = 0, su = 0, sv = 0;
  for (const Instance& inst : scene.instances) {
    const Mesh& mesh = scene.meshes[std::size_t(inst.mesh)];
    if (mesh.material != material || mesh.uvs.size() != mesh.positions.size()) continue;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      vec3 w[3];
      for (int c = 0; c < 3; ++c)
        w[c] = vec3(inst.transform * vec4(mesh.positions[mesh.indices[t + c]], 1.f));
      const SurfaceTangents tt =
          triangleTangents(w[0], w[1], w[2], mesh.uvs[mesh.indices[t]],
                           mesh.uvs[mesh.indices[t + 1]], mesh.uvs[mesh.indices[t + 2]]);
      const double a = 0.5 * glm::length(glm::cross(w[1] - w[0], w[2] - w[0]));
      area += a;
      su += a * glm::length(tt.tu);
      sv += a * glm::length(tt.tv);
    }
  }
  return area > 0 ? vec2(float(su / area), float(sv / area)) : vec2(1.f);
}

int bakeResolution(const Scene& scene, const BumpMap& b) {
  if (b.texture >= 0 && b.texture < int(scene.textures.size())) {
    const Image& i = scene.textures[std::size_t(b.texture)].image;
    return std::max(i.width, i.height);
  }
  // 32 texels per period of the sinusoid's highest frequency, a power of two in [64, 2048].
  const float f = std::max({std::abs(b.frequency.x), std::abs(b.frequency.y), 1.f});
  int r = 64;
  while (r < 32.f * f && r < 2048) r *= 2;
  return r;
}

}  // namespace

Texture bakeNormalMap(const Scene& scene, const BumpMap& bump, vec2 metric, int resolution) {
  Texture t;
  t.name = "baked normal map";
  t.image = Image(resolution, resolution, 4, 1.f);
  t.minFilter = FilterMode::Linear;  // level 0 only: the map carries no mip chain
  const vec3 tu(metric.x, 0.f, 0.f), tv(0.f, -metric.y, 0.f), n(0.f, 0.f, 1.f);
  for (int y = 0; y < resolution; ++y)
    for (int x = 0; x < resolution; ++x) {
      const vec2 uv((float(x) + 0.5f) / float(resolution), (float(y) + 0.5f) / float(resolution));
      const vec3 m = bumpMapNormal(scene, bump, uv, tu, tv, n);
      for (int c = 0; c < 3; ++c) t.image.at(x, y, c) = 0.5f * m[c] + 0.5f;
    }
  return t;
}

Scene withSurfaceDetail(const Scene& scene, SurfaceDetail mode) {
  Scene out = scene;
  if (mode == SurfaceDetail::Bump) return out;
  if (mode == SurfaceDetail::NormalMap) {
    for (std::size_t i = 0; i < out.materials.size(); ++i) {
      Material& m = out.materials[i];
      if (!m.bump) continue;
      out.textures.push_back(bakeNormalMap(scene, *m.bump, materialMetric(scene, int(i)),
                                           bakeResolution(scene, *m.bump)));
      m.normalTexture = int(out.textures.size()) - 1;
      m.normalScale = 1.f;
    }
  }
  if (mode == SurfaceDetail::Displaced) {
    const Scene tessellated = tessellateAnalytic(scene, 256);
    std::size_t budget = kMaxDisplacedTriangles;
    for (Instance& inst : out.instances) {
      const Mesh& mesh = tessellated.meshes[std::size_t(inst.mesh)];
      const Material& material = scene.material(mesh.material);
      if (!material.bump || mesh.uvs.size() != mesh.positions.size() || mesh.sdf) continue;
      out.meshes.push_back(displaceInstance(scene, mesh, inst.transform, *material.bump, budget));
      inst.mesh = int(out.meshes.size()) - 1;
      inst.transform = mat4(1.f);
    }
  }
  for (Material& m : out.materials) m.bump.reset();
  return out;
}

}  // namespace diptych
