// Plugins Curvature and VertexNormals: per-node views on the triangles of the current surface
// mesh (the session's mesh when it has surface elements, else the merged triangulation), the
// surfaces taken whole, so that a node shared by two surfaces gets one value.
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "mesh/discrete/classification.h"
#include "mesh/discrete/mesh_triangles.h"
#include "mesh/discrete/surface_curvature.h"
#include "mesh/views/plugin_functions.h"

namespace geomesh::post::plugins {
namespace {

// Flips every closed component of `t` whose triangles enclose a negative volume, so that
// closed surfaces face outwards (the sign of the mean curvature then follows the usual rule:
// positive on a sphere).
void turnClosedPartsOutwards(Triangulation& t) {
  DisjointSets parts(t.points.size());
  for (const TriangleVertices& v : t.triangles) {
    parts.join(v[0], v[1]);
    parts.join(v[0], v[2]);
  }
  std::vector<double> volume(t.points.size(), 0);
  std::vector<char> open(t.points.size(), 0);
  const TriangleAdjacency adjacency = triangleAdjacency(t.triangles);
  for (std::uint32_t k = 0; k < t.triangles.size(); ++k) {
    const TriangleVertices& v = t.triangles[k];
    const std::uint32_t r = parts.find(v[0]);
    volume[r] += dot(t.points[v[0]], cross(t.points[v[1]], t.points[v[2]]));
    for (std::uint32_t n : adjacency.neighbours[k])
      if (n == kNoTriangle) open[r] = 1;
  }
  for (TriangleVertices& v : t.triangles) {
    const std::uint32_t r = parts.find(v[0]);
    if (!open[r] && volume[r] < 0) std::swap(v[1], v[2]);
  }
}

// The triangles the plugin works on, consistently oriented, closed parts outwards; none (and
// a warning) when there is neither a surface mesh nor a merged triangulation.
std::optional<Triangulation> currentSurface(const PluginContext& context,
                                            std::string_view plugin) {
  Triangulation t;
  if (context.mesh.elementCount(2) > 0) {
    t = meshTriangles(context.mesh).triangulation;
  } else if (const Triangulation* merged =
                 context.mergedTriangles ? context.mergedTriangles() : nullptr;
             merged && !merged->triangles.empty()) {
    t = *merged;
  } else {
    context.log.warning("Plugin(" + std::string(plugin) +
                        "): there is no surface mesh and no merged triangulation; nothing done");
    return std::nullopt;
  }
  orientConsistently(t);
  turnClosedPartsOutwards(t);
  return t;
}

// A view of the triangles of `t` with `components` values per vertex.
void addVertexView(PluginContext& context, const std::string& name, const Triangulation& t,
                   FieldKind kind, const std::vector<double>& values) {
  const std::size_t components = std::size_t(componentCount(kind));
  View& view = context.views.add(name);
  ElementList& list = view.list(ElementShape::Triangle, kind);
  std::array<Vec3, 3> corners;
  std::vector<double> cornerValues;
  for (const TriangleVertices& v : t.triangles) {
    cornerValues.clear();
    for (std::size_t k = 0; k < 3; ++k) {
      corners[k] = t.points[v[k]];
      for (std::size_t c = 0; c < components; ++c)
        cornerValues.push_back(values[v[k] * components + c]);
    }
    appendElement(list, corners, cornerValues);
  }
}

}  // namespace

void curvature(const PluginOptions& options, PluginContext& context) {
  constexpr std::string_view plugin = "Curvature";
  const double type = options.number("Type", 0);
  if (type != 0 && type != 1 && type != 2)
    fail(plugin, optionText("Type", type) +
                     ": not 0 (mean), 1 (Gaussian) or 2 (largest principal curvature)");
  const std::optional<Triangulation> t = currentSurface(context, plugin);
  if (!t) return;
  VertexCurvatures curvatures = vertexCurvatures(*t);
  static const char* const kNames[] = {"Mean curvature", "Gaussian curvature",
                                       "Largest principal curvature"};
  std::vector<double>* values[] = {&curvatures.mean, &curvatures.gaussian, &curvatures.maxAbs};
  const int k = int(type);
  addVertexView(context, kNames[k], *t, FieldKind::Scalar, *values[k]);
}

void vertexNormals(const PluginOptions&, PluginContext& context) {
  const std::optional<Triangulation> t = currentSurface(context, "VertexNormals");
  if (!t) return;
  std::vector<double> values;
  values.reserve(3 * t->points.size());
  for (const Vec3& n : vertexNormals(*t)) values.insert(values.end(), {n.x, n.y, n.z});
  addVertexView(context, "Vertex normals", *t, FieldKind::Vector, values);
}

}  // namespace geomesh::post::plugins
