#include "engine/scene/lit_polygons.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <glm/gtx/component_wise.hpp>

#include "engine/core/error.h"

namespace diptych {
namespace {

using glm::dvec2;
using glm::dvec3;
using Poly = std::vector<dvec2>;

// The half-plane a u + b v + c <= 0.
struct HalfPlane {
  double a, b, c;
  double operator()(const dvec2& p) const { return a * p.x + b * p.y + c; }
};

// Sutherland and Hodgman's clip of a convex polygon (either orientation) to a half-plane, into
// `out` (its storage reused: the receiver loop below clips millions of times, and an allocation
// per clip was a third of building whitted's pieces; out must not alias p).
void clip(const Poly& p, const HalfPlane& h, Poly& out) {
  out.clear();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const dvec2& a = p[i];
    const dvec2& b = p[(i + 1) % p.size()];
    const double fa = h(a), fb = h(b);
    if (fa <= 0.0) out.push_back(a);
    if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0))
      out.push_back(a + (b - a) * (fa / (fa - fb)));
  }
  if (out.size() < 3) out.clear();
}
Poly clipped(const Poly& p, const HalfPlane& h) {
  Poly out;
  out.reserve(p.size() + 1);
  clip(p, h, out);
  return out;
}

// The same in 3D against f(q) = dot(k, q) + k0 <= 0 (a light frustum's planes).
std::vector<dvec3> clipped3(const std::vector<dvec3>& p, const dvec3& k, double k0) {
  std::vector<dvec3> out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const dvec3& a = p[i];
    const dvec3& b = p[(i + 1) % p.size()];
    const double fa = glm::dot(k, a) + k0, fb = glm::dot(k, b) + k0;
    if (fa <= 0.0) out.push_back(a);
    if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0))
      out.push_back(a + (b - a) * (fa / (fa - fb)));
  }
  return out.size() >= 3 ? out : std::vector<dvec3>{};
}

double signedArea(const Poly& p) {
  double s = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const dvec2& a = p[i];
    const dvec2& b = p[(i + 1) % p.size()];
    s += a.x * b.y - b.x * a.y;
  }
  return 0.5 * s;
}

// The convex hull (Andrew's monotone chain, counter-clockwise, collinear points dropped). A
// clipped sliver can come out of the arithmetic slightly reflex, and the intersection of a
// reflex polygon's edge half-planes is not the polygon: the supporting lines of its two long,
// nearly parallel edges bound a wedge reaching far beyond it, which subtract() would cut out of
// a receiver (a thin false shadow across whitted's floor before this). The hull's half-planes
// bound the hull itself.
// Into h (its storage reused; p is sorted in place, h must not alias it).
void hullOf(Poly& p, Poly& h) {
  h.clear();
  if (p.size() < 3) return;
  std::sort(p.begin(), p.end(),
            [](const dvec2& a, const dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  const auto turn = [](const dvec2& o, const dvec2& a, const dvec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  h.resize(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], p[i]) <= 0.0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(h[k - 2], h[k - 1], p[i]) <= 0.0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  if (h.size() < 3) h.clear();
}
Poly hull(Poly p) {
  Poly h;
  hullOf(p, h);
  return h;
}

struct Box {
  dvec2 lo{1e300}, hi{-1e300};
  void add(const dvec2& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  bool overlaps(const Box& o) const {
    return lo.x <= o.hi.x && o.lo.x <= hi.x && lo.y <= o.hi.y && o.lo.y <= hi.y;
  }
};
Box boxOf(const Poly& p) {
  Box b;
  for (const dvec2& q : p) b.add(q);
  return b;
}

// The light's point of view: a cube face (perspective through the light's position: (u, v) =
// (x / z, y / z) of the face's local coordinates) or, for a directional light, the orthographic
// frame along its direction ((u, v) = (x, y), depth z).
struct View {
  bool perspective = true;
  dvec3 origin{0.0}, right{1, 0, 0}, up{0, 1, 0}, forward{0, 0, 1};
  dvec3 local(const vec3& p) const {
    const dvec3 d = dvec3(p) - origin;
    return {glm::dot(d, right), glm::dot(d, up), glm::dot(d, forward)};
  }
};

// One triangle as the view sees it: its projected (clipped) polygon, its plane n . q = c and its
// corners in the view's local coordinates, and where it came from.
struct Projected {
  Poly corners;
  Box box;
  dvec3 n{0.0}, q0{0.0}, e1{0.0}, e2{0.0};
  double c = 0.0, area = 0.0;
  double magnitude = 0.0;  // the largest |local coordinate| of its corners
  int mesh = 0;
  std::uint32_t triangle = 0;
  bool casts = false;
};

// Depth along the view at projected point p on plane (n, c): the local z there.
double depthAt(const View& view, const Projected& t, const dvec2& p) {
  if (view.perspective) return t.c / (t.n.x * p.x + t.n.y * p.y + t.n.z);
  return (t.c - t.n.x * p.x - t.n.y * p.y) / t.n.z;
}

// Where occluder `o` lies nearer the light than receiver `r`, as a half-plane of the projection
// (both planar: the depth difference changes sign on a line). Perspective: along the ray
// (u, v, 1) the planes are met at s = c / (n . (u, v, 1)), both s > 0 inside the frustum, so
// s_o < k s_r <=> sign(c_o c_r) (c_o (n_r . ray) - k c_r (n_o . ray)) < 0. Orthographic:
// z_o < z_r - margin, linear as it stands. k = 1 - 1e-9 and the margin (1e-9 of the two
// triangles' largest local coordinate) keep a surface from shadowing its coplanar neighbour,
// the object-precision form of a shadow map's bias at the scale of double rounding of these
// coordinates, not of the scene: a 5 mm occluder on a 2e4-unit floor still casts its shadow.
HalfPlane inFront(const View& view, const Projected& o, const Projected& r) {
  if (view.perspective) {
    constexpr double k = 1.0 - 1e-9;
    const dvec3 w = o.c * r.n - k * r.c * o.n;
    const double s = (o.c * r.c) < 0.0 ? -1.0 : 1.0;
    return {s * w.x, s * w.y, s * w.z};
  }
  return {-o.n.x / o.n.z + r.n.x / r.n.z, -o.n.y / o.n.z + r.n.y / r.n.z,
          o.c / o.n.z - r.c / r.n.z + 1e-9 * std::max(o.magnitude, r.magnitude)};
}

// The inside of edge e of the counter-clockwise convex polygon c (a hull()): left of a -> b,
// cross(b - a, p - a) >= 0, as a half-plane -cross <= 0.
HalfPlane leftOf(const Poly& c, std::size_t e) {
  const dvec2 a = c[e];
  const dvec2 b = c[(e + 1) % c.size()];
  const dvec2 d = b - a;
  return {d.y, -d.x, d.x * a.y - d.y * a.x};
}

// Per-thread storage that subtract() and the receiver loop reuse, call after call.
struct Scratch {
  Poly a, b, front, frontHull;
  std::vector<Poly> out;
  std::vector<Box> outBoxes;
};

// Whether the convex polygon `c` (a hull()) covers more than rounding (`tiny`) of `piece`: their
// intersection, clipped into s.a (s.b its scratch).
bool cuts(const Poly& piece, const Poly& c, double tiny, Scratch& s) {
  s.a = piece;
  for (std::size_t e = 0; e < c.size() && !s.a.empty(); ++e) {
    clip(s.a, leftOf(c, e), s.b);
    std::swap(s.a, s.b);
  }
  return !s.a.empty() && std::abs(signedArea(s.a)) > tiny;
}

// The pieces minus the convex polygon `c` (a hull(), counter-clockwise): each piece cut along c's
// edges, the parts outside kept (convex, at most one per edge), the part inside dropped. False when
// nothing changed, which is most calls: those return before touching the pieces.
bool subtract(std::vector<Poly>& pieces, std::vector<Box>& boxes, const Poly& c, double tiny,
              Scratch& s) {
  const Box cb = boxOf(c);
  std::size_t first = 0;  // the first piece c cuts
  while (first < pieces.size() && !(boxes[first].overlaps(cb) && cuts(pieces[first], c, tiny, s)))
    ++first;
  if (first == pieces.size()) return false;
  std::vector<Poly>& out = s.out;
  std::vector<Box>& outBoxes = s.outBoxes;
  out.clear();
  outBoxes.clear();
  for (std::size_t i = 0; i < first; ++i) out.push_back(std::move(pieces[i]));
  outBoxes.assign(boxes.begin(), boxes.begin() + std::ptrdiff_t(first));
  for (std::size_t i = first; i < pieces.size(); ++i) {
    // Untouched unless the piece and c overlap in more than rounding.
    if (i > first && !(boxes[i].overlaps(cb) && cuts(pieces[i], c, tiny, s))) {
      out.push_back(std::move(pieces[i]));
      outBoxes.push_back(boxes[i]);
      continue;
    }
    Poly rest = std::move(pieces[i]);
    // First the parts outside c's bounding box, whole (axis-aligned cuts): cutting the piece
    // along c's edge lines alone leaves fans of slivers across the whole receiver, which every
    // later occluder cuts again (5k small occluders over one floor triangle made 11k pieces,
    // 50k made 575k and took 230 s: review of session 25); kept inside the box they cannot.
    const std::array<HalfPlane, 4> box = {
        HalfPlane{-1.0, 0.0, cb.lo.x}, HalfPlane{1.0, 0.0, -cb.hi.x}, HalfPlane{0.0, -1.0, cb.lo.y},
        HalfPlane{0.0, 1.0, -cb.hi.y}};  // inside: <= 0
    // Only for a piece much larger than c: against its neighbours' (a tessellation's adjacent
    // triangles) the box adds pieces without confining anything (whitted and shadow-sphere
    // built 4x slower with it everywhere).
    const dvec2 pieceSize = boxes[i].hi - boxes[i].lo, cSize = cb.hi - cb.lo;
    const bool confine = pieceSize.x * pieceSize.y > 16.0 * cSize.x * cSize.y;
    for (const HalfPlane& side : box) {
      if (!confine) break;
      Poly part = hull(clipped(rest, {-side.a, -side.b, -side.c}));
      if (!part.empty() && std::abs(signedArea(part)) > tiny) {
        out.push_back(std::move(part));
        outBoxes.push_back(boxOf(out.back()));
      }
      rest = clipped(rest, side);
    }
    for (std::size_t e = 0; e < c.size() && !rest.empty(); ++e) {
      const HalfPlane left = leftOf(c, e);
      // Right of the edge: outside c. As a hull: a sliver that rounding left slightly reflex
      // would answer the lookup's same-side test in a wedge beyond itself.
      Poly part = hull(clipped(rest, {-left.a, -left.b, -left.c}));
      if (!part.empty() && std::abs(signedArea(part)) > tiny) {
        out.push_back(std::move(part));
        outBoxes.push_back(boxOf(out.back()));
      }
      rest = clipped(rest, left);
    }
  }
  // The pieces' old storage goes back to the scratch for the next call.
  std::swap(pieces, out);
  std::swap(boxes, outBoxes);
  return true;
}

}  // namespace

LitPolygons::LitPolygons(const WorldGeometry& world, const std::vector<bool>& casts,
                         const Light& light) {
  if (casts.size() != world.meshes.size())
    throw Error("LitPolygons: " + std::to_string(casts.size()) + " caster flags for " +
                std::to_string(world.meshes.size()) + " meshes");
  triangles_.resize(world.meshes.size());
  for (std::size_t m = 0; m < world.meshes.size(); ++m)
    triangles_[m].resize(world.meshes[m].indices.size() / 3);
  if (!light.castsShadows) return;

  std::vector<View> views;
  if (light.type == LightType::Directional) {
    View v;
    v.perspective = false;
    v.forward = glm::normalize(dvec3(light.direction));
    const dvec3 helper = std::abs(v.forward.y) < 0.9 ? dvec3(0, 1, 0) : dvec3(1, 0, 0);
    v.right = glm::normalize(glm::cross(helper, v.forward));
    v.up = glm::cross(v.forward, v.right);
    views.push_back(v);
  } else {  // point, spot, area lights at their centre: the six faces of a cube
    const std::array<std::array<dvec3, 3>, 6> faces = {
        {{dvec3(1, 0, 0), dvec3(0, 0, -1), dvec3(0, 1, 0)},
         {dvec3(-1, 0, 0), dvec3(0, 0, 1), dvec3(0, 1, 0)},
         {dvec3(0, 1, 0), dvec3(1, 0, 0), dvec3(0, 0, -1)},
         {dvec3(0, -1, 0), dvec3(1, 0, 0), dvec3(0, 0, 1)},
         {dvec3(0, 0, 1), dvec3(1, 0, 0), dvec3(0, 1, 0)},
         {dvec3(0, 0, -1), dvec3(-1, 0, 0), dvec3(0, 1, 0)}}};
    for (const auto& f : faces) {
      View v;
      v.origin = dvec3(light.position);
      v.forward = f[0];
      v.right = f[1];
      v.up = f[2];
      views.push_back(v);
    }
  }
  // The near plane of a positional light's frusta: 1e-7 of its reach (the farthest vertex).
  double reach = 0.0;
  if (light.type != LightType::Directional)
    for (const WorldMesh& m : world.meshes)
      for (const vec3& p : m.positions)
        reach = std::max(reach, glm::length(dvec3(p) - dvec3(light.position)));
  const double nearPlane = 1e-7 * std::max(reach, 1e-30);

  std::vector<std::uint8_t> touchedTriangle;
  std::vector<std::size_t> base(world.meshes.size() + 1, 0);
  for (std::size_t m = 0; m < world.meshes.size(); ++m)
    base[m + 1] = base[m] + world.meshes[m].indices.size() / 3;
  touchedTriangle.assign(base.back(), 0);
  std::vector<std::vector<Piece>> collected(base.back());

  for (const View& view : views) {
    // Project every triangle (clipped to the face's frustum).
    std::vector<Projected> polys;
    for (std::size_t m = 0; m < world.meshes.size(); ++m) {
      const WorldMesh& mesh = world.meshes[m];
      for (std::size_t t = 0; 3 * t + 2 < mesh.indices.size(); ++t) {
        const std::uint32_t* i = &mesh.indices[3 * t];
        const dvec3 q0 = view.local(mesh.positions[i[0]]), q1 = view.local(mesh.positions[i[1]]),
                    q2 = view.local(mesh.positions[i[2]]);
        Projected p;
        p.q0 = q0;
        p.e1 = q1 - q0;
        p.e2 = q2 - q0;
        p.n = glm::cross(p.e1, p.e2);
        if (glm::dot(p.n, p.n) == 0.0) continue;  // degenerate: nothing to light or shadow
        p.c = glm::dot(p.n, q0);
        p.magnitude = glm::compMax(glm::max(glm::abs(q0), glm::max(glm::abs(q1), glm::abs(q2))));
        std::vector<dvec3> poly = {q0, q1, q2};
        if (view.perspective) {
          poly = clipped3(poly, dvec3(0, 0, -1), nearPlane);
          poly = clipped3(poly, dvec3(1, 0, -1), 0.0);
          poly = clipped3(poly, dvec3(-1, 0, -1), 0.0);
          poly = clipped3(poly, dvec3(0, 1, -1), 0.0);
          poly = clipped3(poly, dvec3(0, -1, -1), 0.0);
          if (poly.empty()) continue;
          for (const dvec3& q : poly) p.corners.push_back({q.x / q.z, q.y / q.z});
        } else {
          if (std::abs(p.n.z) <= 1e-12 * glm::length(p.n)) continue;  // edge-on to the light
          for (const dvec3& q : poly) p.corners.push_back({q.x, q.y});
        }
        p.area = std::abs(signedArea(p.corners));
        if (!(p.area > 0.0) || !std::isfinite(p.area)) continue;  // edge-on: no area to occlude
        p.box = boxOf(p.corners);
        p.mesh = int(m);
        p.triangle = std::uint32_t(t);
        p.casts = casts[m];
        polys.push_back(std::move(p));
      }
    }
    if (polys.empty()) continue;
    stats_.polygons += polys.size();
    // A uniform grid over the projection holding the casters.
    Box all;
    for (const Projected& p : polys) {
      all.add(p.box.lo);
      all.add(p.box.hi);
    }
    const int g = std::clamp(int(std::sqrt(double(polys.size())) / 2.0), 1, 256);
    const dvec2 size = glm::max(all.hi - all.lo, dvec2(1e-300));
    auto cellOf = [&](const dvec2& p) {
      const dvec2 c = (p - all.lo) / size * double(g);
      return glm::ivec2(std::clamp(int(c.x), 0, g - 1), std::clamp(int(c.y), 0, g - 1));
    };
    // A caster spanning more than kMaxCells cells goes into `wide`, which every receiver scans:
    // a long diagonal sliver would otherwise sit in every cell (N of them: N g^2 entries).
    constexpr int kMaxCells = 64;
    std::vector<std::vector<std::uint32_t>> grid(std::size_t(g) * g + 1);
    std::vector<std::uint32_t>& wide = grid.back();
    for (std::size_t k = 0; k < polys.size(); ++k) {
      if (!polys[k].casts) continue;
      const glm::ivec2 lo = cellOf(polys[k].box.lo), hi = cellOf(polys[k].box.hi);
      if ((hi.x - lo.x + 1) * (hi.y - lo.y + 1) > kMaxCells) {
        wide.push_back(std::uint32_t(k));
        continue;
      }
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) grid[std::size_t(y) * g + x].push_back(std::uint32_t(k));
    }
    std::vector<std::vector<Poly>> result(polys.size());
    std::vector<std::uint8_t> touched(polys.size(), 0);
    std::vector<std::uint64_t> clips(polys.size(), 0);
    tbb::parallel_for(std::size_t(0), polys.size(), [&](std::size_t k) {
      const Projected& r = polys[k];
      // A receiver spanning many cells of the caster grid starts as its parts in those cells:
      // every cut then stays inside the cells its occluder reaches. Whole, each of thousands of
      // small occluders scattered over a floor cut strips across all of it that the next ones
      // cut again (5k made 66k pieces in 2 s, 20k made 614k in 116 s; review of session 25).
      std::vector<Poly> pieces;
      std::vector<Box> boxes;
      const glm::ivec2 lo = cellOf(r.box.lo), hi = cellOf(r.box.hi);
      if ((hi.x - lo.x + 1) * (hi.y - lo.y + 1) <= 4) {
        pieces = {r.corners};
        boxes = {r.box};
      } else {
        const dvec2 step = size / double(g);
        for (int y = lo.y; y <= hi.y; ++y)
          for (int x = lo.x; x <= hi.x; ++x) {
            // Shared boundaries computed by the same expression on both sides: no gaps.
            const dvec2 a = all.lo + dvec2(x, y) * step, b = all.lo + dvec2(x + 1, y + 1) * step;
            Poly part = r.corners;
            for (const HalfPlane& side : {HalfPlane{-1.0, 0.0, a.x}, HalfPlane{1.0, 0.0, -b.x},
                                          HalfPlane{0.0, -1.0, a.y}, HalfPlane{0.0, 1.0, -b.y}})
              part = clipped(part, side);
            if (part.empty() || std::abs(signedArea(part)) <= 1e-12 * r.area) continue;
            boxes.push_back(boxOf(part));
            pieces.push_back(std::move(part));
          }
      }
      // What counts as rounding: relative to the smaller of receiver and occluder (below), so
      // that a small occluder on a large receiver still counts.
      const double receiverTiny = 1e-12 * r.area;
      thread_local Scratch scratch;
      thread_local std::vector<std::uint32_t> seen;
      thread_local std::uint32_t stamp = 0;
      if (seen.size() < polys.size()) seen.assign(polys.size(), 0);
      if (++stamp == 0) {
        std::fill(seen.begin(), seen.end(), 0);
        stamp = 1;
      }
      // The receiver's cells, then the wide casters (cell index g * g).
      std::vector<std::size_t> cells;
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) cells.push_back(std::size_t(y) * g + x);
      cells.push_back(std::size_t(g) * g);
      for (std::size_t cell = 0; cell < cells.size() && !pieces.empty(); ++cell)
        for (const std::uint32_t j : grid[cells[cell]]) {
          if (seen[j] == stamp || j == k) continue;
          seen[j] = stamp;
          const Projected& o = polys[j];
          if (!o.box.overlaps(r.box)) continue;
          ++clips[k];
          clip(o.corners, inFront(view, o, r), scratch.front);
          hullOf(scratch.front, scratch.frontHull);
          const Poly& front = scratch.frontHull;
          const double tiny = std::min(receiverTiny, 1e-12 * o.area);
          if (front.empty() || std::abs(signedArea(front)) <= tiny) continue;
          if (subtract(pieces, boxes, front, tiny, scratch)) touched[k] = 1;
          if (pieces.empty()) break;
        }
      result[k] = std::move(pieces);
    });
    // Back to each triangle's barycentrics: the point of the piece's corner on the triangle's
    // plane (along the light's ray), then q = q0 + u e1 + v e2 solved with the normal.
    for (std::size_t k = 0; k < polys.size(); ++k) {
      const Projected& p = polys[k];
      stats_.clips += clips[k];
      const std::size_t id = base[std::size_t(p.mesh)] + p.triangle;
      touchedTriangle[id] |= touched[k];
      const double nn = glm::dot(p.n, p.n);
      for (const Poly& piece : result[k]) {
        Piece bary;
        for (const dvec2& c : piece) {
          // Perspective: s (u, v, 1) at the plane's depth s; orthographic: (u, v, depth).
          const double depth = depthAt(view, p, c);
          const dvec3 q = view.perspective ? dvec3(c, 1.0) * depth : dvec3(c, depth);
          const dvec3 d = q - p.q0;
          bary.push_back(
              {glm::dot(glm::cross(d, p.e2), p.n) / nn, glm::dot(glm::cross(p.e1, d), p.n) / nn});
        }
        // Again a hull: mapped corner by corner, a sliver can come out reflex in barycentrics
        // and answer the lookup's same-side test in a wedge beyond itself (false light).
        bary = hull(std::move(bary));
        if (!bary.empty()) collected[id].push_back(std::move(bary));
      }
    }
  }
  for (std::size_t m = 0; m < world.meshes.size(); ++m)
    for (std::size_t t = 0; t < triangles_[m].size(); ++t) {
      const std::size_t id = base[m] + t;
      Triangle& tri = triangles_[m][t];
      if (!touchedTriangle[id]) continue;  // no occluder in front of any part: lit
      tri.pieces = std::move(collected[id]);
      tri.coverage = tri.pieces.empty() ? Coverage::Shadowed : Coverage::Partial;
      index(tri);
      stats_.pieces += tri.pieces.size();
      stats_.partial += tri.coverage == Coverage::Partial;
      stats_.shadowed += tri.coverage == Coverage::Shadowed;
    }
}

void LitPolygons::index(Triangle& t) {
  if (t.pieces.size() <= 8) return;
  t.cells = std::clamp(int(std::sqrt(double(t.pieces.size()))), 2, 64);
  Box all;
  std::vector<Box> boxes;
  for (const Piece& p : t.pieces) {
    boxes.push_back(boxOf(p));
    all.add(boxes.back().lo);
    all.add(boxes.back().hi);
  }
  t.lo = all.lo;
  t.scale = double(t.cells) / glm::max(all.hi - all.lo, dvec2(1e-300));
  const auto cell = [&](const dvec2& p) {
    const dvec2 c = (p - t.lo) * t.scale;
    return glm::ivec2(std::clamp(int(c.x), 0, t.cells - 1), std::clamp(int(c.y), 0, t.cells - 1));
  };
  // Counting sort of (cell, piece) pairs into cellStart / cellPieces.
  const std::size_t n = std::size_t(t.cells) * std::size_t(t.cells);
  std::vector<std::vector<std::uint32_t>> lists(n);
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    const glm::ivec2 a = cell(boxes[k].lo), b = cell(boxes[k].hi);
    for (int y = a.y; y <= b.y; ++y)
      for (int x = a.x; x <= b.x; ++x)
        lists[std::size_t(y) * t.cells + x].push_back(std::uint32_t(k));
  }
  t.cellStart.assign(n + 1, 0);
  for (std::size_t c = 0; c < n; ++c)
    t.cellStart[c + 1] = t.cellStart[c] + std::uint32_t(lists[c].size());
  t.cellPieces.reserve(t.cellStart[n]);
  for (const auto& l : lists) t.cellPieces.insert(t.cellPieces.end(), l.begin(), l.end());
}

LitPolygons::Coverage LitPolygons::coverage(int mesh, std::uint32_t triangle) const {
  return triangles_[std::size_t(mesh)][triangle].coverage;
}

const std::vector<LitPolygons::Piece>& LitPolygons::pieces(int mesh, std::uint32_t triangle) const {
  return triangles_[std::size_t(mesh)][triangle].pieces;
}

float LitPolygons::visibility(int mesh, std::uint32_t triangle, float u, float v) const {
  const Triangle& t = triangles_[std::size_t(mesh)][triangle];
  if (t.coverage != Coverage::Partial) return t.coverage == Coverage::Lit ? 1.f : 0.f;
  const dvec2 p(u, v);
  // Inside a convex piece: on one side (or on) of every edge, whichever its orientation.
  const auto inside = [&](const Piece& piece) {
    bool pos = false, neg = false;
    for (std::size_t i = 0; i < piece.size() && !(pos && neg); ++i) {
      const dvec2& a = piece[i];
      const dvec2& b = piece[(i + 1) % piece.size()];
      const double cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
      pos = pos || cross > 0.0;
      neg = neg || cross < 0.0;
    }
    return !(pos && neg);
  };
  if (t.cells == 0) {
    for (const Piece& piece : t.pieces)
      if (inside(piece)) return 1.f;
    return 0.f;
  }
  const dvec2 c = (p - t.lo) * t.scale;
  if (c.x < 0.0 || c.y < 0.0 || c.x > double(t.cells) || c.y > double(t.cells)) return 0.f;
  const std::size_t cell = std::size_t(std::min(int(c.y), t.cells - 1)) * std::size_t(t.cells) +
                           std::size_t(std::min(int(c.x), t.cells - 1));
  for (std::uint32_t k = t.cellStart[cell]; k < t.cellStart[cell + 1]; ++k)
    if (inside(t.pieces[t.cellPieces[k]])) return 1.f;
  return 0.f;
}

}  // namespace diptych
