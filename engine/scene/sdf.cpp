#include "engine/scene/sdf.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "engine/scene/scene.h"

namespace diptych {
namespace {

double maxComponent(const dvec3& v) {
  return std::max(v.x, std::max(v.y, v.z));
}

// GLSL mod: x - y floor(x / y), non-negative for y > 0.
dvec3 glslMod(const dvec3& x, double y) {
  return x - y * glm::floor(x / y);
}

// The primitive distances follow I. Quilez's catalogue of exact distance functions
// (iquilezles.org/articles/distfunctions); the Menger sponge is his iterated-box bound.
double primitiveDistance(const SdfNode& n, const dvec3& p) {
  switch (n.kind) {
    case SdfKind::Sphere:
      return glm::length(p) - n.radius;
    case SdfKind::Box: {
      const dvec3 q = glm::abs(p) - n.halfSize;
      return glm::length(glm::max(q, 0.0)) + std::min(maxComponent(q), 0.0);
    }
    case SdfKind::RoundBox: {
      const dvec3 q = glm::abs(p) - n.halfSize + n.radius;
      return glm::length(glm::max(q, 0.0)) + std::min(maxComponent(q), 0.0) - n.radius;
    }
    case SdfKind::Torus: {
      const glm::dvec2 q(glm::length(glm::dvec2(p.x, p.z)) - n.radius2, p.y);
      return glm::length(q) - n.radius;
    }
    case SdfKind::Capsule: {
      const dvec3 pa = p - n.a, ba = n.b - n.a;
      const double h = std::clamp(glm::dot(pa, ba) / glm::dot(ba, ba), 0.0, 1.0);
      return glm::length(pa - ba * h) - n.radius;
    }
    case SdfKind::Plane:
      return p.y;
    case SdfKind::Menger: {
      const double size = n.halfSize.x;
      const dvec3 q = p / size;  // the unit sponge in [-1, 1]^3
      const dvec3 b = glm::abs(q) - 1.0;
      double d = glm::length(glm::max(b, 0.0)) + std::min(maxComponent(b), 0.0);
      double s = 1.0;
      for (int i = 0; i < n.iterations; ++i) {
        const dvec3 a = glslMod(q * s, 2.0) - 1.0;
        s *= 3.0;
        const dvec3 r = glm::abs(1.0 - 3.0 * glm::abs(a));
        const double da = std::max(r.x, r.y), db = std::max(r.y, r.z), dc = std::max(r.z, r.x);
        d = std::max(d, (std::min(da, std::min(db, dc)) - 1.0) / s);
      }
      return d * size;
    }
    default:
      return 0.0;
  }
}

double nodeDistance(const Sdf& sdf, int index, const dvec3& p) {
  const SdfNode& n = sdf.nodes[std::size_t(index)];
  const dvec3 local = dvec3(n.toLocal * glm::dvec4(p, 1.0));
  double d;
  switch (n.kind) {
    case SdfKind::Union:
      d = std::min(nodeDistance(sdf, n.left, local), nodeDistance(sdf, n.right, local));
      break;
    case SdfKind::Intersection:
      d = std::max(nodeDistance(sdf, n.left, local), nodeDistance(sdf, n.right, local));
      break;
    case SdfKind::Difference:
      d = std::max(nodeDistance(sdf, n.left, local), -nodeDistance(sdf, n.right, local));
      break;
    case SdfKind::SmoothUnion: {
      const double a = nodeDistance(sdf, n.left, local), b = nodeDistance(sdf, n.right, local);
      const double h = std::clamp(0.5 + 0.5 * (b - a) / n.k, 0.0, 1.0);
      d = glm::mix(b, a, h) - n.k * h * (1.0 - h);
      break;
    }
    default:
      d = primitiveDistance(n, local);
  }
  return n.scale * d;
}

using Box = std::optional<std::pair<dvec3, dvec3>>;

Box nodeBounds(const Sdf& sdf, int index) {
  const SdfNode& n = sdf.nodes[std::size_t(index)];
  Box local;
  switch (n.kind) {
    case SdfKind::Sphere:
      local = {{dvec3(-n.radius), dvec3(n.radius)}};
      break;
    case SdfKind::Box:
    case SdfKind::RoundBox:
      local = {{-n.halfSize, n.halfSize}};
      break;
    case SdfKind::Menger:
      local = {{dvec3(-n.halfSize.x), dvec3(n.halfSize.x)}};
      break;
    case SdfKind::Torus: {
      const double e = n.radius2 + n.radius;
      local = {{dvec3(-e, -n.radius, -e), dvec3(e, n.radius, e)}};
      break;
    }
    case SdfKind::Capsule:
      local = {{glm::min(n.a, n.b) - n.radius, glm::max(n.a, n.b) + n.radius}};
      break;
    case SdfKind::Plane:
      return std::nullopt;
    case SdfKind::Union:
    case SdfKind::SmoothUnion: {
      const Box l = nodeBounds(sdf, n.left), r = nodeBounds(sdf, n.right);
      if (!l || !r) return std::nullopt;
      // The smooth minimum lies below min(a, b) by at most k / 4: grow by that.
      const double grow = n.kind == SdfKind::SmoothUnion ? 0.25 * n.k : 0.0;
      local = {{glm::min(l->first, r->first) - grow, glm::max(l->second, r->second) + grow}};
      break;
    }
    case SdfKind::Intersection: {
      const Box l = nodeBounds(sdf, n.left), r = nodeBounds(sdf, n.right);
      if (!l && !r) return std::nullopt;
      if (!l || !r) {
        local = l ? l : r;
      } else {
        local = {{glm::max(l->first, r->first), glm::min(l->second, r->second)}};
      }
      break;
    }
    case SdfKind::Difference:
      local = nodeBounds(sdf, n.left);
      if (!local) return std::nullopt;
      break;
  }
  // To the parent's space: the corners through the inverse of toLocal.
  const glm::dmat4 toParent = glm::inverse(n.toLocal);
  dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (int c = 0; c < 8; ++c) {
    const dvec3 corner((c & 1) ? local->second.x : local->first.x,
                       (c & 2) ? local->second.y : local->first.y,
                       (c & 4) ? local->second.z : local->first.z);
    const dvec3 q = dvec3(toParent * glm::dvec4(corner, 1.0));
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  return {{lo, hi}};
}

}  // namespace

double sdfDistance(const Sdf& sdf, const dvec3& p) {
  return nodeDistance(sdf, sdf.root, p);
}

std::optional<std::pair<dvec3, dvec3>> sdfBounds(const Sdf& sdf) {
  return nodeBounds(sdf, sdf.root);
}

dvec3 sdfNormal(const Sdf& sdf, const dvec3& p, double h) {
  dvec3 g;
  for (int i = 0; i < 3; ++i) {
    dvec3 e(0.0);
    e[i] = h;
    g[i] = sdfDistance(sdf, p + e) - sdfDistance(sdf, p - e);
  }
  const double len = glm::length(g);
  return len > 0.0 && std::isfinite(len) ? g / len : dvec3(0.0, 1.0, 0.0);
}

SphereTraceResult sphereTrace(const Sdf& sdf, const dvec3& o, const dvec3& d, double tmin,
                              double tmax, const SphereTraceSettings& settings) {
  SphereTraceResult result;
  const double speed = glm::length(d);  // distances are in object units, t in units of |d|
  if (!(speed > 0.0) || !(tmin <= tmax)) return result;
  const double tol = settings.tolerance;
  double t = tmin;
  // Trace the side of the surface the ray starts on: sign * f > 0 until the surface.
  double f = sdfDistance(sdf, o + t * d);
  ++result.steps;
  double sign = f < 0.0 ? -1.0 : 1.0;
  bool leaving = std::abs(f) < 2.0 * tol;
  if (leaving) sign = glm::dot(d, sdfNormal(sdf, o + t * d, tol)) >= 0.0 ? 1.0 : -1.0;
  // Keinert et al. 2014, Listing 2: step omega * r; when the unbounding spheres of two
  // successive points do not overlap (r_prev + r < step), the step overshot: go back and
  // continue with omega = 1.
  double omega = settings.relaxation, previousRadius = 0.0, step = 0.0;
  for (;;) {
    const double signedRadius = sign * f, radius = std::abs(f);
    const bool overshot = omega > 1.0 && radius + previousRadius < step;
    if (overshot) {
      step -= omega * step;  // back to the last safe point
      omega = 1.0;
    } else {
      if (leaving && signedRadius >= 2.0 * tol) leaving = false;
      if (!leaving && signedRadius < tol) {
        result.t = t;
        return result;
      }
      step = (leaving ? std::max(signedRadius, tol) : signedRadius) * omega / speed;
    }
    previousRadius = radius;
    t += step;
    if (!overshot && t > tmax) return result;
    if (result.steps >= settings.maxSteps) {
      result.cappedOut = true;
      return result;
    }
    f = sdfDistance(sdf, o + t * d);
    ++result.steps;
    if (!std::isfinite(f)) return result;
  }
}

SdfRayTally& threadSdfTally() {
  thread_local SdfRayTally tally;
  return tally;
}

void SdfStats::record(const SphereTraceResult& r) {
  SdfRayTally& tally = threadSdfTally();
  ++tally.rays;
  tally.steps += std::uint64_t(r.steps);
  tally.capped += r.cappedOut ? 1 : 0;
  tally.maxSteps = std::max(tally.maxSteps, r.steps);
  rays.fetch_add(1, std::memory_order_relaxed);
  steps.fetch_add(std::uint64_t(r.steps), std::memory_order_relaxed);
  if (r.cappedOut) capped.fetch_add(1, std::memory_order_relaxed);
  int seen = maxSteps.load(std::memory_order_relaxed);
  while (r.steps > seen && !maxSteps.compare_exchange_weak(seen, r.steps)) {
  }
}

void SdfStats::reset() {
  rays = 0;
  steps = 0;
  capped = 0;
  maxSteps = 0;
}

Mesh polygonizeSdf(const Sdf& sdf, const dvec3& boxLo, const dvec3& boxHi, int cells) {
  cells = std::max(cells, 2);
  // Pad by one cell so surfaces touching the bounds are closed.
  const dvec3 cell = (boxHi - boxLo) / double(cells - 2);
  const dvec3 lo = boxLo - cell;
  const int n = cells + 1;  // samples per axis
  auto index = [&](int x, int y, int z) { return (std::size_t(z) * n + y) * n + x; };
  std::vector<double> f(std::size_t(n) * n * n);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) f[index(x, y, z)] = sdfDistance(sdf, lo + dvec3(x, y, z) * cell);

  Mesh mesh;
  mesh.name = "sdf";
  std::vector<std::int32_t> vertexOf(std::size_t(cells) * cells * cells, -1);
  auto cellIndex = [&](int x, int y, int z) { return (std::size_t(z) * cells + y) * cells + x; };
  static constexpr int kEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                        {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for (int z = 0; z < cells; ++z)
    for (int y = 0; y < cells; ++y)
      for (int x = 0; x < cells; ++x) {
        std::array<double, 8> v;
        for (int c = 0; c < 8; ++c) v[c] = f[index(x + (c & 1), y + ((c >> 1) & 1), z + (c >> 2))];
        dvec3 sum(0.0);
        int crossings = 0;
        for (const auto& e : kEdges) {
          if ((v[e[0]] < 0.0) == (v[e[1]] < 0.0)) continue;
          const double s = v[e[0]] / (v[e[0]] - v[e[1]]);
          const dvec3 p0((e[0] & 1), (e[0] >> 1) & 1, e[0] >> 2),
              p1((e[1] & 1), (e[1] >> 1) & 1, e[1] >> 2);
          sum += glm::mix(p0, p1, s);
          ++crossings;
        }
        if (crossings == 0) continue;
        const dvec3 p = lo + (dvec3(x, y, z) + sum / double(crossings)) * cell;
        vertexOf[cellIndex(x, y, z)] = std::int32_t(mesh.positions.size());
        mesh.positions.push_back(vec3(p));
        mesh.normals.push_back(vec3(sdfNormal(sdf, p, 0.5 * glm::length(cell) * 1e-3)));
      }
  // One quad per crossed edge of the sample grid, joining the four cells that share it.
  for (int z = 1; z < cells; ++z)
    for (int y = 1; y < cells; ++y)
      for (int x = 1; x < cells; ++x) {
        const bool inside = f[index(x, y, z)] < 0.0;
        for (int axis = 0; axis < 3; ++axis) {
          glm::ivec3 step(0);
          step[axis] = 1;
          const glm::ivec3 q = glm::ivec3(x, y, z) + step;
          if (q[axis] > cells) continue;
          if (inside == (f[index(q.x, q.y, q.z)] < 0.0)) continue;
          // The four cells around the edge from (x,y,z) along `axis`.
          const int u = (axis + 1) % 3, w = (axis + 2) % 3;
          std::array<std::int32_t, 4> quad;
          bool ok = true;
          for (int k = 0; k < 4; ++k) {
            glm::ivec3 c(x, y, z);
            c[u] -= (k == 1 || k == 2) ? 1 : 0;
            c[w] -= (k >= 2) ? 1 : 0;
            quad[k] = vertexOf[cellIndex(c.x, c.y, c.z)];
            ok = ok && quad[k] >= 0;
          }
          if (!ok) continue;
          // Counter-clockwise seen from outside: the order flips with the edge's direction.
          std::array<std::uint32_t, 4> qv;
          for (int k = 0; k < 4; ++k) qv[k] = std::uint32_t(quad[k]);
          if (!inside) std::swap(qv[1], qv[3]);
          mesh.indices.insert(mesh.indices.end(), {qv[0], qv[1], qv[2], qv[0], qv[2], qv[3]});
        }
      }
  mesh.uvs.assign(mesh.positions.size(), vec2(0.f));
  return mesh;
}

}  // namespace diptych
