#include "engine/gl/closed_mesh.h"

#include <array>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace diptych::gl {

namespace {

struct CellHash {
  std::size_t operator()(const glm::i64vec3& c) const {
    return std::size_t(c.x * 73856093ll ^ c.y * 19349663ll ^ c.z * 83492791ll);
  }
};

struct EdgeHash {
  std::size_t operator()(const std::pair<std::uint32_t, std::uint32_t>& e) const {
    return std::size_t(e.first) * 0x9e3779b97f4a7c15ull ^ e.second;
  }
};

// Union-find representative of each vertex, vertices closer than `weld` being one corner: a
// hash grid of cell `weld`, each vertex compared with the 27 cells around its own.
std::vector<std::uint32_t> weldCorners(const std::vector<vec3>& positions, float weld) {
  std::vector<std::uint32_t> parent(positions.size());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto find = [&](std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  std::unordered_map<glm::i64vec3, std::vector<std::uint32_t>, CellHash> grid;
  const auto cellOf = [&](const vec3& p) {
    return glm::i64vec3(glm::floor(glm::dvec3(p) / double(weld)));
  };
  for (std::uint32_t v = 0; v < positions.size(); ++v) {
    const glm::i64vec3 c = cellOf(positions[v]);
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = grid.find(c + glm::i64vec3(dx, dy, dz));
          if (it == grid.end()) continue;
          for (std::uint32_t w : it->second)
            if (glm::distance(positions[v], positions[w]) <= weld) parent[find(v)] = find(w);
        }
    grid[c].push_back(v);
  }
  for (std::uint32_t v = 0; v < positions.size(); ++v) parent[v] = find(v);
  return parent;
}

}  // namespace

bool isClosedOutward(const std::vector<vec3>& positions,
                     const std::vector<std::uint32_t>& indices) {
  Aabb box;
  for (std::uint32_t i : indices) {
    const vec3& p = positions.at(i);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
    box.extend(p);
  }
  if (box.empty()) return false;
  const float weld = kClosedMeshWeld * std::max(glm::length(box.hi - box.lo), 1e-30f);
  const std::vector<std::uint32_t> corner = weldCorners(positions, weld);
  std::unordered_map<std::pair<std::uint32_t, std::uint32_t>, int, EdgeHash> edges;
  edges.reserve(indices.size());
  double volume = 0;  // 6 x the signed volume (divergence theorem over the faces)
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const std::uint32_t c[3] = {corner[indices[t]], corner[indices[t + 1]], corner[indices[t + 2]]};
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) continue;  // covers no pixel
    for (int i = 0; i < 3; ++i)
      if (++edges[{c[i], c[(i + 1) % 3]}] > 1) return false;  // non-manifold or mis-wound
    const glm::dvec3 a(positions[indices[t]]), b(positions[indices[t + 1]]),
        d(positions[indices[t + 2]]);
    volume += glm::dot(a, glm::cross(b, d));
  }
  if (edges.empty()) return false;
  for (const auto& [e, count] : edges)
    if (!edges.count({e.second, e.first})) return false;  // a border
  return volume > 0;
}

bool outsideBounds(const vec3& eye, const vec3& lo, const vec3& hi) {
  const vec3 margin = 1e-4f * (glm::abs(lo) + glm::abs(hi) + (hi - lo)) + 1e-6f;
  return glm::any(glm::lessThan(eye, lo - margin)) || glm::any(glm::greaterThan(eye, hi + margin));
}

}  // namespace diptych::gl
