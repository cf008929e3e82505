// checkMesh: node ownership, curve chains, orientation, conformity, Jacobians, periodicity.
#include "mesh/checks/mesh_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <map>
#include <set>
#include <tuple>
#include <type_traits>

#include "mesh/checks/high_order_check.h"
#include "mesh/structured/periodic.h"
#include "mesh/volumes/embedded_conformity.h"

namespace geomesh {
namespace {

constexpr std::size_t kMaxProblemsPerCheck = 10;
// A corner whose edges span less than this fraction of the volume of the box they would span
// at right angles is flat: its element has a scaled Jacobian (SICN) of about that size.
constexpr double kFlatCorner = 1e-10;
// A triangle whose doubled area is below this fraction of the sum of its squared edge lengths
// is flat (its SICN is about 3.5 times that fraction).
constexpr double kFlatTriangle = 1e-12;

std::string nodeName(NodeIndex n) {
  return "node " + std::to_string(n + 1);
}

std::string edgeName(NodeIndex a, NodeIndex b) {
  return "edge (" + std::to_string(a + 1) + ", " + std::to_string(b + 1) + ")";
}

std::uint64_t edgeKey(NodeIndex a, NodeIndex b) {
  return a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
}

// The edges of the triangles as keys (smaller node in the high half), in increasing order.
// When the triangles' nodes span a range comparable to their number (the usual case), a
// counting sort on the smaller node then a small sort within each bucket: linear time.
std::vector<std::uint64_t> sortedEdges(const ElementBlock& triangles) {
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * triangles.size());
  NodeIndex lo = ~NodeIndex{0}, hi = 0;
  for (std::size_t e = 0; e < triangles.size(); ++e) {
    const auto n = triangles.element(e);
    for (int i = 0; i < 3; ++i) {
      edges.push_back(edgeKey(n[i], n[(i + 1) % 3]));
      lo = std::min(lo, n[i]);
      hi = std::max(hi, n[i]);
    }
  }
  if (edges.empty() || hi - lo > 4 * edges.size()) {
    std::sort(edges.begin(), edges.end());
    return edges;
  }
  std::vector<std::uint32_t> start(std::size_t{hi - lo} + 2, 0);
  for (std::uint64_t key : edges) ++start[(key >> 32) - lo + 1];
  for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  std::vector<std::uint64_t> sorted(edges.size());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::uint64_t key : edges) sorted[fill[(key >> 32) - lo]++] = key;
  for (std::size_t k = 0; k + 1 < start.size(); ++k)
    std::sort(sorted.begin() + start[k], sorted.begin() + start[k + 1]);
  return sorted;
}

class Checker {
 public:
  Checker(const Model& model, const Mesh& mesh) : model_(model), mesh_(mesh) {
    const BoundingBox box = model.boundingBox();
    const double diagonal = box.empty() ? 0 : distance(box.min, box.max);
    tolerance_ = 1e-9 * (diagonal > 0 ? diagonal : 1);
  }

  MeshCheckReport run() {
    checkIndicesAndOwnership();
    if (hasHighOrderElements(mesh_)) {
      corners_ = cornerMeshes(mesh_);
      checkEdgeNodes(mesh_, kMaxProblemsPerCheck, report_.problems);
    }
    checkDuplicates();
    for (const auto& [tag, point] : model_.points()) checkPoint(point);
    for (const auto& [tag, curve] : model_.curves()) checkCurve(curve);
    for (const auto& [tag, surface] : model_.surfaces()) checkSurface(surface);
    checkVolumes();
    checkPeriodicLinks();
    return std::move(report_);
  }

  MeshCheckReport runVolumes() {
    checkVolumes();
    return std::move(report_);
  }

 private:
  // An entity's mesh as the checks see it: high-order elements cut down to their corners (the
  // nodes inside their edges, faces and cells are checked as held nodes only).
  const EntityMesh* find(EntityId e) const {
    const auto it = corners_.find(e);
    return it != corners_.end() ? &it->second : mesh_.find(e);
  }

  void problem(EntityId e, std::string message) {
    report_.problems.push_back({e, std::move(message)});
  }

  void checkIndicesAndOwnership() {
    std::vector<std::uint8_t> owners(mesh_.nodeCount(), 0);
    for (const auto& [id, em] : mesh_.entities()) {
      std::size_t reported = 0;
      for (NodeIndex n : em.nodes) {
        if (n >= mesh_.nodeCount()) {
          if (reported++ < kMaxProblemsPerCheck) problem(id, nodeName(n) + " does not exist");
        } else if (++owners[n] == 2 && reported++ < kMaxProblemsPerCheck) {
          problem(id, nodeName(n) + " also belongs to another entity");
        }
      }
      for (const ElementBlock& block : em.blocks)
        for (NodeIndex n : block.nodes)
          if (n >= mesh_.nodeCount() && reported++ < kMaxProblemsPerCheck)
            problem(id, std::string(elementName(block.type)) + " uses missing " + nodeName(n));
    }
    std::size_t orphans = 0;
    for (std::size_t n = 0; n < owners.size(); ++n)
      if (owners[n] == 0 && orphans++ < kMaxProblemsPerCheck)
        problem({-1, 0}, nodeName(static_cast<NodeIndex>(n)) + " belongs to no entity");
  }

  // Nodes rounded to a grid of the tolerance's size; equal cells are duplicates.
  void checkDuplicates() {
    using Cell = std::tuple<long long, long long, long long, NodeIndex>;
    std::vector<Cell> cells;
    cells.reserve(mesh_.nodeCount());
    for (NodeIndex n = 0; n < mesh_.nodeCount(); ++n) {
      const Vec3 p = mesh_.node(n);
      cells.emplace_back(std::llround(p.x / tolerance_), std::llround(p.y / tolerance_),
                         std::llround(p.z / tolerance_), n);
    }
    std::sort(cells.begin(), cells.end());
    std::size_t reported = 0;
    for (std::size_t k = 1; k < cells.size(); ++k) {
      const auto& [x0, y0, z0, n0] = cells[k - 1];
      const auto& [x1, y1, z1, n1] = cells[k];
      if (x0 == x1 && y0 == y1 && z0 == z1 && reported++ < kMaxProblemsPerCheck)
        problem({-1, 0}, nodeName(n0) + " and " + nodeName(n1) + " coincide");
    }
  }

  void checkPoint(const ModelPoint& point) {
    const EntityId id{0, point.tag};
    const EntityMesh* em = find(id);
    if (!em) return;
    if (em->nodes.size() != 1) return problem(id, "does not own exactly one node");
    if (em->nodes[0] < mesh_.nodeCount() &&
        !(distance(mesh_.node(em->nodes[0]), point.xyz) <= tolerance_))
      problem(id, nodeName(em->nodes[0]) + " is not at the point");
  }

  // The curves of `entity`'s compound (itself included, each once) that the model has, if
  // there are two or more; empty otherwise.
  template <typename Entity>
  std::vector<const Entity*> compoundOf(const Entity& entity) const {
    std::vector<const Entity*> group;
    for (int tag : entity.compound) {
      const Entity* member = nullptr;
      if constexpr (std::is_same_v<Entity, ModelCurve>)
        member = model_.curve(tag);
      else
        member = model_.surface(tag);
      if (member && std::find(group.begin(), group.end(), member) == group.end())
        group.push_back(member);
    }
    if (group.size() < 2) group.clear();
    return group;
  }

  // Whether a compound curve was meshed as one: a point where two of its curves meet got no
  // node (the compound's mesh runs through it).
  static bool meshedAsOne(const std::vector<const ModelCurve*>& group,
                          const std::map<int, int>& degree, const Mesh& mesh) {
    if (group.empty()) return false;
    for (const auto& [point, count] : degree) {
      const EntityMesh* em = count == 2 ? mesh.find({0, point}) : nullptr;
      if (count == 2 && (!em || em->nodes.empty())) return true;
    }
    return false;
  }

  // A compound curve meshed as one: the segments of all its curves form one chain between the
  // chain's ends (a closed chain: a cycle); each node on its own curve.
  void checkCompoundCurve(const ModelCurve& curve, const std::vector<const ModelCurve*>& group,
                          const std::map<int, int>& degree) {
    int first = curve.tag;
    for (const ModelCurve* c : group) first = std::min(first, c->tag);
    if (first != curve.tag) return;  // checked with the first curve of the group
    const EntityId id{1, curve.tag};
    std::map<NodeIndex, int> uses;
    for (const ModelCurve* c : group)
      if (const EntityMesh* em = find({1, c->tag}))
        if (const ElementBlock* lines = em->findBlock(ElementType::Line2))
          for (NodeIndex n : lines->nodes) ++uses[n];
    std::set<NodeIndex> ends;
    for (const auto& [point, count] : degree)
      if (count == 1)
        if (const EntityMesh* em = find({0, point}); em && !em->nodes.empty())
          ends.insert(em->nodes.front());
    for (const auto& [node, count] : uses)
      if (count != (ends.contains(node) ? 1 : 2))
        return problem(id, "the line elements of its compound do not form one chain (" +
                               nodeName(node) + " ends " + std::to_string(count) + " of them)");
  }

  void checkCurve(const ModelCurve& curve) {
    const EntityId id{1, curve.tag};
    const std::vector<const ModelCurve*> group = compoundOf(curve);
    std::map<int, int> degree;  // per end point of the group's curves: how many curves end there
    for (const ModelCurve* c : group) ++degree[c->startPoint], ++degree[c->endPoint];
    if (meshedAsOne(group, degree, mesh_)) {
      checkCompoundCurve(curve, group, degree);
      checkCurveNodes(curve);
      return;
    }
    const EntityMesh* em = find(id);
    if (!em) return;  // not meshed (dimension 0 only)
    const ElementBlock* lines = em->findBlock(ElementType::Line2);
    const bool degenerate = curve.geometry && curve.geometry->isDegenerate();
    if (degenerate && (!lines || lines->size() == 0) && em->nodes.empty()) return;  // a pole
    if (!lines || lines->size() == 0) return problem(id, "has no line elements");
    // End points of tag 0 are unknown: the curve was read from a file without topology.
    if (curve.startPoint != 0 || curve.endPoint != 0) {
      const EntityMesh* start = find({0, curve.startPoint});
      const EntityMesh* end = find({0, curve.endPoint});
      if (!start || !end || start->nodes.empty() || end->nodes.empty())
        return problem(id, "end points have no mesh nodes");
      if (lines->nodes.front() != start->nodes.front() ||
          lines->nodes.back() != end->nodes.front())
        problem(id, "line elements do not start and end at the curve's end points");
    }
    for (std::size_t e = 1; e < lines->size(); ++e)
      if (lines->element(e)[0] != lines->element(e - 1)[1])
        return problem(id, "line elements do not form a chain");
    checkCurveNodes(curve);
  }

  void checkCurveNodes(const ModelCurve& curve) {
    const EntityId id{1, curve.tag};
    const EntityMesh* em = find(id);
    if (!em || !curve.geometry || em->parametric.size() != em->nodes.size()) return;
    std::size_t reported = 0;
    for (std::size_t k = 0; k < em->nodes.size(); ++k) {
      const double d = distance(curve.geometry->point(em->parametric[k]), mesh_.node(em->nodes[k]));
      if (!(d <= tolerance_) && reported++ < kMaxProblemsPerCheck)
        problem(id, nodeName(em->nodes[k]) + " lies off the curve (distance " + std::to_string(d) +
                        ")");
    }
  }

  // Boundary segments of the surface with the number of triangles each must border.
  std::vector<std::pair<std::uint64_t, int>> expectedBoundary(const ModelSurface& surface) const {
    std::vector<std::pair<std::uint64_t, int>> expected;
    auto add = [&](int signedTag, int uses) {
      const EntityMesh* em = find({1, std::abs(signedTag)});
      const ElementBlock* lines = em ? em->findBlock(ElementType::Line2) : nullptr;
      if (!lines) return;
      for (std::size_t e = 0; e < lines->size(); ++e)
        expected.emplace_back(edgeKey(lines->element(e)[0], lines->element(e)[1]), uses);
    };
    for (const std::vector<int>& loop : surface.loops)
      for (int c : loop) add(c, 1);
    for (int c : surface.embeddedCurves) add(c, 2);
    std::sort(expected.begin(), expected.end());
    // A segment listed twice (a curve used twice) must border as many triangles.
    std::vector<std::pair<std::uint64_t, int>> merged;
    for (const auto& [key, uses] : expected) {
      if (!merged.empty() && merged.back().first == key)
        merged.back().second = std::min(2, merged.back().second + uses);
      else
        merged.emplace_back(key, uses);
    }
    return merged;
  }

  void checkConformity(EntityId id, const ModelSurface& surface, const ElementBlock& triangles) {
    const std::vector<std::uint64_t> edges = sortedEdges(triangles);
    const auto expected = expectedBoundary(surface);
    std::size_t reported = 0, next = 0;
    auto report = [&](std::uint64_t key, const std::string& what) {
      if (reported++ < kMaxProblemsPerCheck)
        problem(id, edgeName(static_cast<NodeIndex>(key >> 32),
                             static_cast<NodeIndex>(key & 0xffffffffu)) +
                        " " + what);
    };
    for (std::size_t k = 0; k < edges.size();) {
      std::size_t run = k;
      while (run < edges.size() && edges[run] == edges[k]) ++run;
      const int count = static_cast<int>(run - k);
      while (next < expected.size() && expected[next].first < edges[k])
        report(expected[next++].first, "of the boundary is not a triangle edge");
      // A surface read from a file without topology (MSH 2.2) has no known boundary: there,
      // an edge may border one triangle (the boundary) or two.
      int wanted = surface.loops.empty() ? std::clamp(count, 1, 2) : 2;
      if (next < expected.size() && expected[next].first == edges[k])
        wanted = expected[next++].second;
      if (count != wanted)
        report(edges[k], "borders " + std::to_string(count) + " triangles instead of " +
                             std::to_string(wanted));
      k = run;
    }
    while (next < expected.size())
      report(expected[next++].first, "of the boundary is not a triangle edge");
  }

  // Orientation against du x dv, non-flatness, and use of foreign nodes.
  void checkTriangles(EntityId id, const ModelSurface& surface, const EntityMesh& em,
                      const ElementBlock& triangles,
                      const std::vector<const ModelSurface*>& compound) {
    // allowedStamp_[n] == stamp: n belongs to the surface or its closure.
    const std::uint32_t stamp = ++stamp_;
    allowedStamp_.resize(mesh_.nodeCount(), 0);
    auto allowEntity = [&](EntityId e) {
      if (const EntityMesh* m = find(e))
        for (NodeIndex n : m->nodes) allowedStamp_[n] = stamp;
    };
    auto allowed = [&](NodeIndex n) { return allowedStamp_[n] == stamp; };
    // The surface's own nodes carry their parameters: the normal is read there, which spares
    // projecting each triangle (slow on CAD surfaces).
    for (NodeIndex n : em.nodes) allowedStamp_[n] = stamp;
    const bool ownParameters = em.parametric.size() == 2 * em.nodes.size();
    ownUvStamp_.resize(mesh_.nodeCount(), 0);
    ownUv_.resize(mesh_.nodeCount());
    if (ownParameters)
      for (std::size_t k = 0; k < em.nodes.size(); ++k) {
        ownUvStamp_[em.nodes[k]] = stamp;
        ownUv_[em.nodes[k]] = {em.parametric[2 * k], em.parametric[2 * k + 1]};
      }
    auto own = [&](NodeIndex n) { return ownUvStamp_[n] == stamp; };
    // A surface of a compound meshed as one may use the nodes of the others and their closures.
    std::vector<const ModelSurface*> closures{&surface};
    for (const ModelSurface* member : compound)
      if (member != &surface) closures.push_back(member), allowEntity({2, member->tag});
    for (const ModelSurface* s : closures) {
      for (const std::vector<int>& loop : s->loops)
        for (int c : loop) {
          allowEntity({1, std::abs(c)});
          if (const ModelCurve* curve = model_.curve(std::abs(c)))
            allowEntity({0, curve->startPoint}), allowEntity({0, curve->endPoint});
        }
      for (int c : s->embeddedCurves) {
        allowEntity({1, c});
        if (const ModelCurve* curve = model_.curve(c))
          allowEntity({0, curve->startPoint}), allowEntity({0, curve->endPoint});
      }
      for (int p : s->embeddedPoints) allowEntity({0, p});
    }
    std::size_t reported = 0;
    const SurfaceGeometry* g = surface.geometry.get();
    // Without a known boundary (MSH 2.2), the surface's closure is unknown too.
    const bool closureKnown = !surface.loops.empty();
    for (std::size_t e = 0; e < triangles.size(); ++e) {
      const auto n = triangles.element(e);
      if (closureKnown && (!allowed(n[0]) || !allowed(n[1]) || !allowed(n[2]))) {
        if (reported++ < kMaxProblemsPerCheck)
          problem(id, "triangle " + std::to_string(e + 1) + " uses a node of another entity");
        continue;
      }
      const Vec3 a = mesh_.node(n[0]), b = mesh_.node(n[1]), c = mesh_.node(n[2]);
      const Vec3 normal = cross(b - a, c - a);
      Vec3 reference = normal;
      if (g) {
        const auto corner = std::find_if(n.begin(), n.end(), own);
        const Vec2 uv = corner != n.end() ? ownUv_[*corner] : g->project((a + b + c) / 3);
        const SurfaceDerivatives d = g->firstDerivatives(uv);
        reference = cross(d.du, d.dv);
      }
      const double scale = dot(b - a, b - a) + dot(c - b, c - b) + dot(a - c, a - c);
      if (!(dot(normal, reference) > 0) || !(norm(normal) > kFlatTriangle * scale)) {
        if (reported++ < kMaxProblemsPerCheck)
          problem(id, "triangle " + std::to_string(e + 1) + " is inverted or flat");
      }
    }
  }

  void checkSurfaceNodes(EntityId id, const ModelSurface& surface, const EntityMesh& em) {
    if (!surface.geometry) return;
    const SurfaceGeometry& g = *surface.geometry;
    const bool haveParameters = em.parametric.size() == 2 * em.nodes.size();
    std::size_t reported = 0;
    for (std::size_t k = 0; k < em.nodes.size(); ++k) {
      const Vec3 x = mesh_.node(em.nodes[k]);
      const Vec2 uv =
          haveParameters ? Vec2{em.parametric[2 * k], em.parametric[2 * k + 1]} : g.project(x);
      const double d = distance(g.point(uv), x);
      if (!(d <= tolerance_) && reported++ < kMaxProblemsPerCheck)
        problem(id, nodeName(em.nodes[k]) + " lies off the surface (distance " + std::to_string(d) +
                        ")");
    }
  }

  // The surface's triangles (if `withTriangles`), then its quadrangles each cut into two
  // along the diagonal from corner `first` to corner first + 2: the checks of triangles then
  // cover quadrangles. Cut along both diagonals in turn, a quadrangle that is inverted or not
  // convex has an inverted half; the diagonal is an interior edge of exactly two halves.
  ElementBlock splitFaces(const EntityMesh& em, bool withTriangles, int first) const {
    ElementBlock faces;
    if (const ElementBlock* triangles = em.findBlock(ElementType::Triangle3))
      if (withTriangles) faces = *triangles;
    if (const ElementBlock* quads = em.findBlock(ElementType::Quad4))
      for (std::size_t e = 0; e < quads->size(); ++e) {
        const auto q = quads->element(e);
        const NodeIndex a = q[first], b = q[first + 1], c = q[first + 2], d = q[(first + 3) % 4];
        faces.nodes.insert(faces.nodes.end(), {a, b, c, a, c, d});
      }
    return faces;
  }

  // The surfaces of `surface`'s compound when it was meshed as one (a curve between two of
  // them has no mesh), else empty.
  std::vector<const ModelSurface*> compoundMeshedAsOne(const ModelSurface& surface) const {
    std::vector<const ModelSurface*> group = compoundOf(surface);
    std::map<int, int> uses;
    for (const ModelSurface* s : group)
      for (const auto& loop : s->loops)
        for (int c : loop) ++uses[std::abs(c)];
    for (const auto& [curve, count] : uses)
      if (count == 2 && !find({1, curve})) return group;
    return {};
  }

  // A compound meshed as one is conforming as a whole: its triangles together, bounded by the
  // segments of the curves only one of its surfaces uses (the others have no mesh).
  void checkCompoundConformity(const ModelSurface& surface,
                               const std::vector<const ModelSurface*>& group) {
    for (const ModelSurface* s : group)
      if (s->tag < surface.tag) return;  // checked with the first surface of the group
    ModelSurface whole;
    whole.tag = surface.tag;
    ElementBlock triangles;
    for (const ModelSurface* s : group) {
      whole.loops.insert(whole.loops.end(), s->loops.begin(), s->loops.end());
      whole.embeddedCurves.insert(whole.embeddedCurves.end(), s->embeddedCurves.begin(),
                                  s->embeddedCurves.end());
      if (const EntityMesh* em = find({2, s->tag})) {
        const ElementBlock faces = splitFaces(*em, true, 1);
        triangles.nodes.insert(triangles.nodes.end(), faces.nodes.begin(), faces.nodes.end());
      }
    }
    checkConformity({2, surface.tag}, whole, triangles);
  }

  void checkSurface(const ModelSurface& surface) {
    const EntityId id{2, surface.tag};
    const std::vector<const ModelSurface*> compound = compoundMeshedAsOne(surface);
    if (!compound.empty()) checkCompoundConformity(surface, compound);
    const EntityMesh* em = find(id);
    if (!em) return;
    // Cut along the diagonal that recombination did not join across (corners 1 and 3), so
    // that a quadrangle straddling a curve edge shows.
    const ElementBlock triangles = splitFaces(*em, true, 1);
    if (triangles.size() == 0) {
      if (compound.empty()) problem(id, "has no triangles");
      return;  // a small surface of a compound may get none
    }
    for (NodeIndex n : triangles.nodes)
      if (n >= mesh_.nodeCount()) return;  // reported already
    checkTriangles(id, surface, *em, triangles, compound);
    const ElementBlock otherHalves = splitFaces(*em, false, 0);
    if (otherHalves.size() > 0) checkTriangles(id, surface, *em, otherHalves, compound);
    if (compound.empty()) checkConformity(id, surface, triangles);
    checkSurfaceNodes(id, surface, *em);
  }

  void checkVolumes() {
    for (const auto& [id, original] : mesh_.entities()) {
      if (id.dim != 3) continue;
      const EntityMesh& em = *find(id);
      bool inRange = true;
      for (const ElementBlock& block : em.blocks)
        for (NodeIndex n : block.nodes) inRange = inRange && n < mesh_.nodeCount();
      if (!inRange) continue;  // reported already
      std::size_t reported = 0;
      for (const ElementBlock& block : em.blocks)
        for (std::size_t e = 0; e < block.size(); ++e)
          if (!positiveCorners(block.type, block.element(e)) && reported++ < kMaxProblemsPerCheck)
            problem(id, std::string(elementName(block.type)) + " " + std::to_string(e + 1) +
                            " has a non-positive Jacobian");
      if (const ModelVolume* volume = model_.volume(id.tag)) {
        checkVolumeFaces(*volume, em);
        checkEmbedded(*volume, em);
      }
    }
  }

  // The entities embedded in a volume of tetrahedra are meshed into them: their triangles are
  // faces of two tetrahedra (one each side), their segments edges and their points nodes.
  void checkEmbedded(const ModelVolume& volume, const EntityMesh& em) {
    const ElementBlock* tets = em.findBlock(ElementType::Tet4);
    if (!tets || em.blocks.size() != 1) return;
    for (std::string& defect :
         embeddedConformityDefects(volume, mesh_, *tets, kMaxProblemsPerCheck))
      problem({3, volume.tag}, std::move(defect));
  }

  // The Jacobian at every corner: the triple product of the corner's three edges, taken in
  // the order that is positive for the reference element of the MSH format, and not small
  // against the product of their lengths (a corner flat to rounding counts as flat).
  bool positiveCorners(ElementType type, std::span<const NodeIndex> n) const {
    auto positive = [&](int corner, int a, int b, int c) {
      const Vec3 o = mesh_.node(n[corner]);
      const Vec3 ea = mesh_.node(n[a]) - o, eb = mesh_.node(n[b]) - o, ec = mesh_.node(n[c]) - o;
      return dot(cross(ea, eb), ec) > kFlatCorner * norm(ea) * norm(eb) * norm(ec);
    };
    switch (type) {
      case ElementType::Tet4: return positive(0, 1, 2, 3);
      case ElementType::Prism6:
        for (int i = 0; i < 3; ++i) {
          const int next = (i + 1) % 3, previous = (i + 2) % 3;
          if (!positive(i, next, previous, i + 3) || !positive(i + 3, previous + 3, next + 3, i))
            return false;
        }
        return true;
      case ElementType::Hex8:
        for (int i = 0; i < 4; ++i) {
          const int next = (i + 1) % 4, previous = (i + 3) % 4;
          if (!positive(i, next, previous, i + 4) || !positive(i + 4, previous + 4, next + 4, i))
            return false;
        }
        return true;
      case ElementType::Pyramid5:
        for (int i = 0; i < 4; ++i)
          if (!positive(i, (i + 1) % 4, (i + 3) % 4, 4)) return false;
        return true;
      default: return true;
    }
  }

  // Faces as their sorted nodes (the fourth UINT32_MAX for triangles).
  using Face = std::array<NodeIndex, 4>;
  static Face faceKey(std::initializer_list<NodeIndex> nodes) {
    Face f{~NodeIndex{0}, ~NodeIndex{0}, ~NodeIndex{0}, ~NodeIndex{0}};
    std::copy(nodes.begin(), nodes.end(), f.begin());
    std::sort(f.begin(), f.end());
    return f;
  }

  static void addElementFaces(ElementType type, std::span<const NodeIndex> n,
                              std::vector<Face>& faces) {
    if (type == ElementType::Tet4) {
      for (int i = 0; i < 4; ++i)
        faces.push_back(faceKey({n[i], n[(i + 1) % 4], n[(i + 2) % 4]}));
    } else if (type == ElementType::Prism6) {
      faces.push_back(faceKey({n[0], n[1], n[2]}));
      faces.push_back(faceKey({n[3], n[4], n[5]}));
      for (int i = 0; i < 3; ++i)
        faces.push_back(faceKey({n[i], n[(i + 1) % 3], n[(i + 1) % 3 + 3], n[i + 3]}));
    } else if (type == ElementType::Pyramid5) {
      faces.push_back(faceKey({n[0], n[1], n[2], n[3]}));
      for (int i = 0; i < 4; ++i) faces.push_back(faceKey({n[i], n[(i + 1) % 4], n[4]}));
    } else if (type == ElementType::Hex8) {
      faces.push_back(faceKey({n[0], n[1], n[2], n[3]}));
      faces.push_back(faceKey({n[4], n[5], n[6], n[7]}));
      for (int i = 0; i < 4; ++i)
        faces.push_back(faceKey({n[i], n[(i + 1) % 4], n[(i + 1) % 4 + 4], n[i + 4]}));
    }
  }

  // Conformity with the boundary of volumes that have prisms, pyramids or hexahedra: every
  // face of the elements is shared by two of them or is a triangle or quadrangle of a boundary
  // surface, and every face of the boundary surfaces is a face of one element.
  void checkVolumeFaces(const ModelVolume& volume, const EntityMesh& em) {
    if (!em.findBlock(ElementType::Prism6) && !em.findBlock(ElementType::Hex8) &&
        !em.findBlock(ElementType::Pyramid5))
      return;
    const EntityId id{3, volume.tag};
    std::vector<Face> faces;
    for (const ElementBlock& block : em.blocks)
      for (std::size_t e = 0; e < block.size(); ++e)
        addElementFaces(block.type, block.element(e), faces);
    std::sort(faces.begin(), faces.end());
    std::vector<Face> boundary;
    for (const std::vector<int>& shell : volume.shells)
      for (int s : shell)
        if (const EntityMesh* sm = find({2, std::abs(s)}))
          for (const ElementBlock& block : sm->blocks)
            for (std::size_t e = 0; e < block.size(); ++e) {
              const auto n = block.element(e);
              if (block.type == ElementType::Triangle3)
                boundary.push_back(faceKey({n[0], n[1], n[2]}));
              if (block.type == ElementType::Quad4)
                boundary.push_back(faceKey({n[0], n[1], n[2], n[3]}));
            }
    std::sort(boundary.begin(), boundary.end());
    std::size_t reported = 0;
    auto report = [&](const std::string& what) {
      if (reported++ < kMaxProblemsPerCheck) problem(id, what);
    };
    for (std::size_t k = 0; k < faces.size();) {
      std::size_t run = k;
      while (run < faces.size() && faces[run] == faces[k]) ++run;
      const bool onBoundary = std::binary_search(boundary.begin(), boundary.end(), faces[k]);
      // A volume read from a file without topology (MSH 2.2) has no known boundary: there, a
      // face may bound one element (the boundary) or two.
      const bool allowed = volume.shells.empty() ? run - k <= 2 : run - k == (onBoundary ? 1u : 2u);
      if (!allowed)
        report("an element face at node " + nodeName(faces[k][0]) + " is shared by " +
               std::to_string(run - k) + " elements" + (onBoundary ? " on the boundary" : ""));
      k = run;
    }
    for (const Face& f : boundary)
      if (!std::binary_search(faces.begin(), faces.end(), f))
        report("a boundary face at " + nodeName(f[0]) + " is not a face of its elements");
  }

  // The diagonal of the box around all nodes (1 for an empty or one-node mesh).
  double nodeExtent() const {
    BoundingBox box;
    for (NodeIndex n = 0; n < mesh_.nodeCount(); ++n) box.include(mesh_.node(n));
    const double diagonal = box.empty() ? 0 : distance(box.min, box.max);
    return diagonal > 0 ? diagonal : 1;
  }

  // Each node of a periodic entity's pairs is the affine image of its master node.
  void checkPeriodicLinks() {
    const double tolerance = 1e-9 * nodeExtent();
    for (const auto& [id, em] : mesh_.entities()) {
      if (!em.periodic) continue;
      if (!em.periodic->affine.empty() && em.periodic->affine.size() != 16) {
        problem(id, "periodic transformation has " +
                        std::to_string(em.periodic->affine.size()) + " values, not 16");
        continue;
      }
      std::size_t reported = 0;
      for (const auto& [node, master] : em.periodic->nodes) {
        if (node >= mesh_.nodeCount() || master >= mesh_.nodeCount()) {
          if (reported++ < kMaxProblemsPerCheck)
            problem(id, "periodic node pair (" + nodeName(node) + ", " + nodeName(master) +
                            ") uses a missing node");
          continue;
        }
        const Vec3 image = applyAffine(em.periodic->affine, mesh_.node(master));
        const double d = distance(image, mesh_.node(node));
        if (d > tolerance && reported++ < kMaxProblemsPerCheck)
          problem(id, nodeName(node) + " is not the image of its periodic master " +
                          nodeName(master) + " (distance " + std::to_string(d) + ")");
      }
    }
  }

  const Model& model_;
  const Mesh& mesh_;
  std::map<EntityId, EntityMesh> corners_;  // of the entities with high-order elements
  double tolerance_ = 0;
  std::vector<std::uint32_t> allowedStamp_;
  std::uint32_t stamp_ = 0;
  // ownUvStamp_[n] == the current stamp: ownUv_[n] holds node n's parameters on the surface.
  std::vector<std::uint32_t> ownUvStamp_;
  std::vector<Vec2> ownUv_;
  MeshCheckReport report_;
};

}  // namespace

std::string MeshCheckReport::summary() const {
  static constexpr const char* kNames[4] = {"point", "curve", "surface", "volume"};
  std::string text;
  for (const MeshProblem& p : problems) {
    if (p.entity.dim >= 0 && p.entity.dim < 4)
      text += std::string(kNames[p.entity.dim]) + " " + std::to_string(p.entity.tag) + ": ";
    else
      text += "mesh: ";
    text += p.message + "\n";
  }
  return text;
}

MeshCheckReport checkMesh(const Model& model, const Mesh& mesh) {
  return Checker(model, mesh).run();
}

MeshCheckReport checkVolumeElements(const Model& model, const Mesh& mesh) {
  return Checker(model, mesh).runVolumes();
}

}  // namespace geomesh
