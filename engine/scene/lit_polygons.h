#pragma once
// Object-precision cast shadows after Atherton, Weiler and Greenberg ("Polygon Shadow
// Generation", SIGGRAPH 1978; the lecture's "Algoritmo de Weiler-Atherton-Greenberg"): hidden
// surfaces are removed with the light as the observer, by clipping polygons against each other
// in the light's projection, and what survives of each polygon is its lit part: "detail
// polygons" attached to the original, from which any view then reads the shadows at no further
// cost. The result depends on the scene and the light, not on the camera.
//
// How the hidden-surface step is done here: every triangle is projected from the light (a point
// or spot light through the six 90-degree faces of a cube around it, each triangle clipped to
// each face's frustum; a directional light orthographically along its direction). For each
// receiving polygon Q, every casting polygon O whose projection overlaps it (found through a
// uniform grid over the projection) is first clipped to the half-plane where it lies in front of
// Q (both are planar, so "O nearer the light than Q" is a linear inequality in the projected
// coordinates, also where the two interpenetrate), then subtracted from Q's lit pieces: Weiler
// and Atherton's inside/outside clip, with every piece kept convex (a convex piece minus a
// convex polygon is at most one convex piece per edge of the polygon). Arithmetic in double.
#include <cstdint>
#include <vector>

#include "engine/scene/scene.h"
#include "engine/scene/world_geometry.h"

namespace diptych {

// The lit parts of every triangle of a WorldGeometry for one light.
class LitPolygons {
 public:
  enum class Coverage : std::uint8_t { Lit, Shadowed, Partial };
  // A convex piece of a triangle's lit part, its corners in that triangle's barycentric
  // coordinates (u weights vertex 1, v vertex 2, as Embree's and the G-buffer's).
  using Piece = std::vector<glm::dvec2>;

  // casts[i]: whether world.meshes[i] casts shadows (its material's castsShadows; alpha-masked
  // and blended triangles cast whole). A light with castsShadows false, or an area light taken
  // at its centre, as rt_shadows' one-sample form.
  LitPolygons(const WorldGeometry& world, const std::vector<bool>& casts, const Light& light);

  // Whether the point at barycentrics (u, v) of triangle `triangle` of mesh `mesh` is lit: 1 or 0
  // (a point on a piece's boundary counts as lit).
  float visibility(int mesh, std::uint32_t triangle, float u, float v) const;
  Coverage coverage(int mesh, std::uint32_t triangle) const;
  const std::vector<Piece>& pieces(int mesh, std::uint32_t triangle) const;

  // What the hidden-surface step did: projected polygons (a triangle in each light-frustum face
  // it reaches), occluder clips tried, lit pieces kept.
  struct Stats {
    std::uint64_t polygons = 0, clips = 0, pieces = 0, partial = 0, shadowed = 0;
  };
  const Stats& stats() const { return stats_; }

 private:
  struct Triangle {
    Coverage coverage = Coverage::Lit;
    std::vector<Piece> pieces;  // Partial only
    // Partial with many pieces: a cells x cells grid over their bounding box listing the pieces
    // each cell overlaps, so a lookup tests a few pieces, not all (whitted's floor: ~1700).
    int cells = 0;
    glm::dvec2 lo{0.0}, scale{0.0};
    std::vector<std::uint32_t> cellStart, cellPieces;
  };
  static void index(Triangle& t);
  std::vector<std::vector<Triangle>> triangles_;  // [mesh][triangle]
  Stats stats_;
};

}  // namespace diptych
