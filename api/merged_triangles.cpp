// Session: the merged triangulation as the plugins see it (Simplify, Fair, Curvature), and the
// report of a merged file's open and non-manifold edges.
#include <algorithm>
#include <array>
#include <compare>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <tuple>

#include "api/discrete_model.h"
#include "api/session.h"
#include "io/discrete_mesh.h"
#include "mesh/discrete/mesh_triangles.h"
#include "mesh/discrete/self_intersections.h"
#include "mesh/discrete/surface_fairing.h"
#include "mesh/discrete/surface_simplification.h"

namespace geomesh {

namespace {

std::string pointText(Vec3 p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.10g, %.10g, %.10g)", p.x, p.y, p.z);
  return text;
}

// An edge of one of the merged file's elements, and that element's number among the file's
// surface elements (from 1).
struct EdgeUse {
  NodeIndex low, high;
  std::size_t facet;
  auto operator<=>(const EdgeUse&) const = default;
};

// The triangles of surface `tag` of `d`, with their own vertices.
Triangulation surfacePart(const DiscreteModel& d, int tag) {
  Triangulation part;
  std::map<std::uint32_t, std::uint32_t> local;
  for (std::size_t k = 0; k < d.surfaceOf.size(); ++k) {
    if (d.surfaceOf[k] != tag) continue;
    TriangleVertices& out = part.triangles.emplace_back();
    for (std::size_t c = 0; c < 3; ++c) {
      const std::uint32_t v = d.triangulation.triangles[k][c];
      const auto [it, added] = local.try_emplace(v, std::uint32_t(part.points.size()));
      if (added) part.points.push_back(d.triangulation.points[v]);
      out[c] = it->second;
    }
  }
  return part;
}

// Surfaces simplified apart, put together again: their common edges were kept in place, so
// their vertices are welded back exactly. Where two surfaces collapsed into the same triangle
// (a flap of three vertices of their common edges, one copy on each side, back to back), both
// copies go: the surfaces then close over it. Vertices no triangle uses are dropped.
void weldSurfaces(Triangulation& t, std::vector<int>& surfaceOf) {
  std::map<std::tuple<double, double, double>, std::uint32_t> vertexAt;
  std::vector<std::uint32_t> welded(t.points.size());
  std::vector<Vec3> points;
  for (std::size_t k = 0; k < t.points.size(); ++k) {
    const Vec3 p = t.points[k];
    const auto [it, added] = vertexAt.try_emplace({p.x, p.y, p.z}, std::uint32_t(points.size()));
    if (added) points.push_back(p);
    welded[k] = it->second;
  }
  t.points = std::move(points);
  for (TriangleVertices& v : t.triangles)
    for (std::uint32_t& k : v) k = welded[k];
  std::map<std::array<std::uint32_t, 3>, int> uses;
  auto sorted = [](TriangleVertices v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  for (const TriangleVertices& v : t.triangles) ++uses[sorted(v)];
  std::size_t kept = 0;
  for (std::size_t k = 0; k < t.triangles.size(); ++k) {
    if (uses[sorted(t.triangles[k])] > 1) continue;
    t.triangles[kept] = t.triangles[k];
    surfaceOf[kept++] = surfaceOf[k];
  }
  t.triangles.resize(kept);
  surfaceOf.resize(kept);
  // A flap's middle vertex may be left without triangles.
  constexpr std::uint32_t kUnused = 0xffffffffu;
  std::vector<std::uint32_t> renumbered(t.points.size(), kUnused);
  std::vector<Vec3> used;
  for (TriangleVertices& v : t.triangles)
    for (std::uint32_t& k : v) {
      if (renumbered[k] == kUnused) {
        renumbered[k] = std::uint32_t(used.size());
        used.push_back(t.points[k]);
      }
      k = renumbered[k];
    }
  t.points = std::move(used);
}

}  // namespace

void Session::reportMergedEdges(const std::string& file) const {
  std::vector<EdgeUse> uses;
  std::size_t facet = 0;
  for (const auto& [id, em] : mesh_.entities()) {
    for (const ElementBlock& block : em.blocks) {
      if (dimension(block.type) != 2) continue;
      const std::size_t corners = std::size_t(vertexCount(block.type));
      for (std::size_t e = 0; e < block.size(); ++e) {
        ++facet;
        const auto nodes = block.element(e);
        for (std::size_t k = 0; k < corners; ++k) {
          const NodeIndex a = nodes[k], b = nodes[(k + 1) % corners];
          uses.push_back({std::min(a, b), std::max(a, b), facet});
        }
      }
    }
  }
  std::sort(uses.begin(), uses.end());  // each edge's uses together, its first facet first
  struct Tally {
    std::size_t count = 0, firstFacet = 0;
    NodeIndex node = 0;
  } open, nonManifold;
  for (std::size_t i = 0, j; i < uses.size(); i = j) {
    for (j = i + 1; j < uses.size() && uses[j].low == uses[i].low && uses[j].high == uses[i].high;)
      ++j;
    Tally* tally = j - i == 1 ? &open : j - i > 2 ? &nonManifold : nullptr;
    if (!tally) continue;
    if (tally->count++ == 0 || uses[i].facet < tally->firstFacet) {
      tally->firstFacet = uses[i].facet;
      tally->node = uses[i].low;
    }
  }
  const std::string where = "Merged '" + file + "': ";
  if (open.count > 0)
    log_.info(where + std::to_string(open.count) +
              " boundary edges (on one facet only: holes or open borders), the first on facet " +
              std::to_string(open.firstFacet) + " at " + pointText(mesh_.node(open.node)));
  if (nonManifold.count > 0)
    log_.warning(where + std::to_string(nonManifold.count) +
                 " non-manifold edges (on more than two facets), the first on facet " +
                 std::to_string(nonManifold.firstFacet) + " at " +
                 pointText(mesh_.node(nonManifold.node)));
  // Facets that cross others (not neighbours): a fold, or two parts pushed into each other.
  // The triangles are the file's facets in order when the file has triangles only.
  const MeshTriangles triangles = meshTriangles(mesh_);
  const SelfIntersections crossing = selfIntersections(triangles.triangulation, 1);
  if (crossing.count > 0) {
    const bool facetsKnown = triangles.triangulation.triangles.size() == facet;
    const auto [i, j] = crossing.pairs.front();
    log_.warning(where + std::to_string(crossing.count) +
                 " pairs of facets intersect (the surface crosses itself), the first " +
                 (facetsKnown ? "facets " + std::to_string(i + 1) + " and " +
                                    std::to_string(j + 1) + " "
                              : std::string()) +
                 "at " + pointText(crossing.points.front()));
  }
}

const Triangulation* Session::mergedTriangulation() {
  adoptSurfaceMeshFile();
  if (!discrete_ && discreteSurfaces_.empty()) return nullptr;
  const DiscreteModel& d = discreteModel();
  return d.triangulation.triangles.empty() ? nullptr : &d.triangulation;
}

DiscreteModel& Session::unclassifiedTriangles(const char* plugin) {
  if (!mergedTriangulation())
    throw std::runtime_error(std::string("Plugin(") + plugin +
                             ") works on merged triangles: merge an STL, PLY or OFF file first");
  DiscreteModel& d = discreteModel();
  if (!d.curves.empty() || !d.points.empty())
    throw std::runtime_error(std::string("Plugin(") + plugin +
                             ") changes the merged triangles before ClassifySurfaces, "
                             "CreateTopology or CreateGeometry, not after");
  return d;
}

// The merged surfaces' mesh made anew from the changed triangles, and the session's mesh too
// while it is still the merged file's; `statement` repeats the change in unrolled scripts.
void Session::mergedTrianglesChanged(std::string statement) {
  rebuildDiscreteMesh();
  if (meshIsMergedFile_) {
    Mesh mesh = discreteMesh_;
    Model scratch;  // the entities are those of the model already
    addDiscreteEntities(scratch, mesh);
    mesh_ = std::move(mesh);
  }
  factories_.discrete().noteDiscreteStatement(std::move(statement));
}

// The quadric error is a sum of squared distances to planes: bounding it by maxDistance^2
// bounds the distance to each plane by maxDistance.
std::pair<std::size_t, std::size_t> Session::simplifyMergedTriangles(std::size_t targetTriangles,
                                                                     double maxDistance) {
  DiscreteModel& d = unclassifiedTriangles("Simplify");
  SimplifyOptions options;
  options.targetTriangles = targetTriangles;
  options.maxError = maxDistance * maxDistance;
  const std::size_t before = d.triangulation.triangles.size();
  std::vector<int> tags(d.surfaceOf);
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  Triangulation result;
  std::vector<int> surfaceOf;
  for (int tag : tags) {
    const Triangulation part = surfacePart(d, tag);
    SimplifyOptions partOptions = options;
    if (options.targetTriangles > 0)  // each surface its share of the target
      partOptions.targetTriangles = std::max<std::size_t>(
          1, options.targetTriangles * part.triangles.size() / before);
    const Triangulation simpler = simplify(part, partOptions);
    const std::uint32_t offset = std::uint32_t(result.points.size());
    result.points.insert(result.points.end(), simpler.points.begin(), simpler.points.end());
    for (TriangleVertices v : simpler.triangles) {
      for (std::uint32_t& k : v) k += offset;
      result.triangles.push_back(v);
      surfaceOf.push_back(tag);
    }
  }
  weldSurfaces(result, surfaceOf);
  d.triangulation = std::move(result);
  d.surfaceOf = std::move(surfaceOf);
  char statement[160];
  std::snprintf(statement, sizeof statement,
                "Plugin(Simplify).TargetTriangles = %zu; Plugin(Simplify).MaxError = %.16g; "
                "Plugin(Simplify).Run;",
                targetTriangles, maxDistance);
  mergedTrianglesChanged(statement);
  return {before, d.triangulation.triangles.size()};
}

double Session::fairMergedTriangles(const FairingOptions& options) {
  DiscreteModel& d = unclassifiedTriangles("Fair");
  const std::vector<Vec3> before = d.triangulation.points;
  fair(d.triangulation, options);
  double moved = 0;
  for (std::size_t k = 0; k < before.size(); ++k)
    moved = std::max(moved, distance(before[k], d.triangulation.points[k]));
  char statement[128];
  std::snprintf(statement, sizeof statement,
                "Plugin(Fair).Iterations = %d; Plugin(Fair).TimeStep = %.16g; Plugin(Fair).Run;",
                options.iterations, options.step);
  mergedTrianglesChanged(statement);
  return moved;
}

}  // namespace geomesh
