#include "engine/gl/closed_mesh.h"

#include <array>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace diptych::gl {

namespace {

struct CellHash {
  std::size_t operator()(const glm::i64vec3& c) const {  // unsigned: wraps, never overflows
    return std::size_t(std::uint64_t(c.x) * 73856093ull ^ std::uint64_t(c.y) * 19349663ull ^
                       std::uint64_t(c.z) * 83492791ull);
  }
};

struct EdgeHash {
  std::size_t operator()(const std::pair<std::uint32_t, std::uint32_t>& e) const {
    return std::size_t(e.first) * 0x9e3779b97f4a7c15ull ^ e.second;
  }
};

// Union-find over indices 0..n-1.
struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  }
  void join(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

// Representative of each vertex the triangles use, vertices closer than `weld` being one
// corner: a hash grid of cell `weld` over the box `lo`.. of those vertices (cells from 0 to
// 1 / kClosedMeshWeld: no overflow wherever the mesh lies), each vertex compared with the 27
// cells around its own. Unused vertices are their own corner.
std::vector<std::uint32_t> weldCorners(const std::vector<vec3>& positions,
                                       const std::vector<bool>& used, const vec3& lo, float weld) {
  UnionFind corners(positions.size());
  std::unordered_map<glm::i64vec3, std::vector<std::uint32_t>, CellHash> grid;
  const auto cellOf = [&](const vec3& p) {
    return glm::i64vec3(glm::floor((glm::dvec3(p) - glm::dvec3(lo)) / double(weld)));
  };
  for (std::uint32_t v = 0; v < positions.size(); ++v) {
    if (!used[v]) continue;
    const glm::i64vec3 c = cellOf(positions[v]);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = grid.find(c + glm::i64vec3(dx, dy, dz));
          if (it == grid.end()) continue;
          for (std::uint32_t w : it->second)
            if (glm::distance(positions[v], positions[w]) <= weld) corners.join(v, w);
        }
    grid[c].push_back(v);
  }
  for (std::uint32_t v = 0; v < positions.size(); ++v) corners.parent[v] = corners.find(v);
  return corners.parent;
}

}  // namespace

bool isClosedOutward(const std::vector<vec3>& positions,
                     const std::vector<std::uint32_t>& indices) {
  Aabb box;
  std::vector<bool> used(positions.size(), false);
  for (std::uint32_t i : indices) {
    const vec3& p = positions.at(i);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
    box.extend(p);
    used[i] = true;
  }
  if (box.empty()) return false;
  const float weld = kClosedMeshWeld * std::max(glm::length(box.hi - box.lo), 1e-30f);
  const std::vector<std::uint32_t> corner = weldCorners(positions, used, box.lo, weld);
  // Connected pieces (corners joined through their triangles): each must be outward on its own,
  // or an inside-out shell beside an outward one would pass on the total volume.
  UnionFind pieces(positions.size());
  std::unordered_map<std::pair<std::uint32_t, std::uint32_t>, int, EdgeHash> edges;
  edges.reserve(indices.size());
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const std::uint32_t c[3] = {corner[indices[t]], corner[indices[t + 1]], corner[indices[t + 2]]};
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) continue;  // covers no pixel
    for (int i = 0; i < 3; ++i)
      if (++edges[{c[i], c[(i + 1) % 3]}] > 1) return false;  // non-manifold or mis-wound
    pieces.join(c[0], c[1]);
    pieces.join(c[1], c[2]);
  }
  if (edges.empty()) return false;
  for (const auto& [e, count] : edges)
    if (!edges.count({e.second, e.first})) return false;  // a border
  // 6 x each piece's signed volume (divergence theorem over its faces), about the box's corner
  // so that far from the origin the terms stay small.
  std::unordered_map<std::uint32_t, double> volume;
  const glm::dvec3 origin(box.lo);
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const std::uint32_t c0 = corner[indices[t]];
    if (c0 == corner[indices[t + 1]] || c0 == corner[indices[t + 2]] ||
        corner[indices[t + 1]] == corner[indices[t + 2]])
      continue;
    const glm::dvec3 a = glm::dvec3(positions[indices[t]]) - origin,
                     b = glm::dvec3(positions[indices[t + 1]]) - origin,
                     d = glm::dvec3(positions[indices[t + 2]]) - origin;
    volume[pieces.find(c0)] += glm::dot(a, glm::cross(b, d));
  }
  for (const auto& [piece, v] : volume)
    if (!(v > 0)) return false;
  return true;
}

bool outsideBounds(const vec3& eye, const vec3& lo, const vec3& hi, float clearance) {
  const vec3 margin = 1e-4f * (glm::abs(lo) + glm::abs(hi) + (hi - lo)) + 1e-6f;
  const vec3 gap = glm::max(glm::max(lo - margin - eye, eye - hi - margin), vec3(0.f));
  return glm::length(gap) > clearance;
}

float nearPlaneReach(float znear, float verticalFov, float aspect) {
  const float t = std::tan(0.5f * verticalFov);
  return znear * std::sqrt(1.f + t * t * (1.f + aspect * aspect));
}

}  // namespace diptych::gl
