#include "engine/scene/json_sdf.h"

#include <cmath>
#include <memory>

#include "engine/scene/sdf.h"

namespace diptych {
namespace {

using jsonread::JsonObject;
using nlohmann::json;

double positiveNumber(JsonObject& o, const std::string& key, double fallback) {
  const double v = o.number(key, float(fallback));
  if (!(v > 0.0)) o.fail(key, "must be positive (is " + std::to_string(v) + ")");
  return v;
}

// Node placement: "translate" [x,y,z], "rotate" [degrees about x, y, z], "scale" (one number:
// a uniform scale keeps the distance a distance). toLocal is the inverse of T R S.
// Limits that keep a hostile SDF from exhausting memory or time at load (docs/robustness.md).
constexpr std::size_t kMaxSdfNodes = 1024;

void readPlacement(JsonObject& o, SdfNode& n) {
  const dvec3 t(o.vector3("translate", vec3(0.f)));
  const dvec3 r = glm::radians(dvec3(o.vector3("rotate", vec3(0.f))));
  const double s = o.has("scale") ? positiveNumber(o, "scale", 1.0) : 1.0;
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), t);
  m = glm::rotate(m, r.z, dvec3(0, 0, 1));
  m = glm::rotate(m, r.y, dvec3(0, 1, 0));
  m = glm::rotate(m, r.x, dvec3(1, 0, 0));
  m = glm::scale(m, dvec3(s));
  n.toLocal = glm::inverse(m);
  n.scale = s;
}

int readNode(const json& value, const std::string& path, const std::string& file, Sdf& sdf,
             int depth) {
  JsonObject o(value, path, file);
  if (depth > 64) o.fail("", "SDF tree deeper than 64 levels");
  // Every distance evaluation walks every node, and polygonisation evaluates resolution^3 times:
  // the node count bounds both (kMaxSdfNodes, and the budget in readSdfObject).
  if (sdf.nodes.size() >= kMaxSdfNodes)
    o.fail("", "SDF tree has more than " + std::to_string(kMaxSdfNodes) + " nodes");
  const std::string type = o.requiredString("type");
  SdfNode n;
  readPlacement(o, n);
  const int index = int(sdf.nodes.size());
  sdf.nodes.push_back(n);
  auto size3 = [&](const char* key) {
    const vec3 v = o.vector3(key, vec3(1.f));
    if (!(v.x > 0.f && v.y > 0.f && v.z > 0.f)) o.fail(key, "must be positive");
    return dvec3(v);
  };
  if (type == "sphere") {
    n.kind = SdfKind::Sphere;
    n.radius = positiveNumber(o, "radius", 1.0);
  } else if (type == "box" || type == "round_box") {
    n.kind = type == "box" ? SdfKind::Box : SdfKind::RoundBox;
    n.halfSize = 0.5 * size3("size");
    if (n.kind == SdfKind::RoundBox) {
      n.radius = positiveNumber(o, "radius", 0.1);
      if (2.0 * n.radius > std::min(n.halfSize.x, std::min(n.halfSize.y, n.halfSize.z)) * 2.0)
        o.fail("radius", "must not exceed half the smallest size");
    }
  } else if (type == "torus") {
    n.kind = SdfKind::Torus;
    n.radius2 = positiveNumber(o, "major_radius", 1.0);
    n.radius = positiveNumber(o, "minor_radius", 0.25);
  } else if (type == "capsule") {
    n.kind = SdfKind::Capsule;
    n.a = dvec3(o.vector3("a", vec3(0.f, -0.5f, 0.f)));
    n.b = dvec3(o.vector3("b", vec3(0.f, 0.5f, 0.f)));
    n.radius = positiveNumber(o, "radius", 0.25);
    if (n.a == n.b) o.fail("b", "equals a (use a sphere)");
  } else if (type == "plane") {
    n.kind = SdfKind::Plane;
  } else if (type == "menger") {
    n.kind = SdfKind::Menger;
    n.halfSize = dvec3(0.5 * positiveNumber(o, "size", 2.0));
    const int it = o.integer("iterations").value_or(3);
    if (it < 0 || it > 8) o.fail("iterations", "must be between 0 and 8");
    n.iterations = it;
  } else if (type == "union" || type == "intersection" || type == "difference" ||
             type == "smooth_union") {
    n.kind = type == "union"          ? SdfKind::Union
             : type == "intersection" ? SdfKind::Intersection
             : type == "difference"   ? SdfKind::Difference
                                      : SdfKind::SmoothUnion;
    if (n.kind == SdfKind::SmoothUnion) n.k = positiveNumber(o, "k", 0.1);
    const json* children = o.find("children");
    if (!children || !children->is_array() || children->size() != 2)
      o.fail("children", "expected exactly two child shapes");
    sdf.nodes[std::size_t(index)] = n;
    const int left = readNode((*children)[0], o.pathOf("children") + "[0]", file, sdf, depth + 1);
    const int right = readNode((*children)[1], o.pathOf("children") + "[1]", file, sdf, depth + 1);
    n.left = left;
    n.right = right;
  } else {
    o.fail("type", "unknown SDF shape '" + type +
                       "' (sphere, box, round_box, torus, capsule, plane, menger, union, "
                       "intersection, difference, smooth_union)");
  }
  sdf.nodes[std::size_t(index)] = n;
  o.rejectUnknownKeys();
  return index;
}

}  // namespace

Mesh readSdfObject(JsonObject& o) {
  auto object = std::make_shared<SdfObject>();
  const json* shape = o.find("shape");
  if (!shape) o.fail("shape", "missing (an SDF shape tree)");
  object->sdf.root = readNode(*shape, o.pathOf("shape"), o.file(), object->sdf, 0);
  const auto bounds = sdfBounds(object->sdf);
  if (!bounds || !(bounds->first.x < bounds->second.x && bounds->first.y < bounds->second.y &&
                   bounds->first.z < bounds->second.z))
    o.fail("shape", "is unbounded or empty (intersect a plane with a bounded shape)");
  object->lo = bounds->first;
  object->hi = bounds->second;
  const double extent = glm::length(object->hi - object->lo);
  object->settings.tolerance = positiveNumber(o, "tolerance", 1e-5 * extent);
  const int steps = o.integer("max_steps").value_or(256);
  if (steps < 1 || steps > 100000) o.fail("max_steps", "must be between 1 and 100000");
  object->settings.maxSteps = steps;
  object->settings.relaxation = o.number("relaxation", 1.f);
  if (!(object->settings.relaxation >= 1.0 && object->settings.relaxation < 2.0))
    o.fail("relaxation", "must be in [1, 2) (1: plain sphere tracing)");
  const int resolution = o.integer("resolution").value_or(64);
  if (resolution < 4 || resolution > 256) o.fail("resolution", "must be between 4 and 256");
  // Polygonisation cost: (resolution + 1)^3 distance evaluations of every node, done at load.
  const double evaluations =
      std::pow(double(resolution) + 1.0, 3.0) * double(object->sdf.nodes.size());
  if (evaluations > kMaxSdfEvaluations)
    o.fail("resolution",
           "polygonising " + std::to_string(object->sdf.nodes.size()) +
               " nodes at this resolution needs " + std::to_string(std::llround(evaluations)) +
               " distance evaluations (limit " + std::to_string(std::llround(kMaxSdfEvaluations)) +
               "): lower the resolution or simplify the tree");
  Mesh mesh = polygonizeSdf(object->sdf, object->lo, object->hi, resolution);
  mesh.sdf = std::move(object);
  return mesh;
}

}  // namespace diptych
