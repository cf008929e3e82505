// planCompounds: the model with each compound as one entity; classify: the elements put back.
#include "mesh/pipeline/compound.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "mesh/discrete/classification.h"
#include "mesh/discrete/discrete_surface_geometry.h"
#include "mesh/discrete/parametrization.h"
#include "mesh/discrete/surface_curvature.h"
#include "mesh/discrete/triangulation.h"

namespace geomesh {
namespace {

double length(Interval r) { return r.max - r.min; }

// The part of a compound curve's parameter s and the part's own parameter there.
std::pair<std::size_t, double> partAt(const std::vector<CompoundCurvePart>& parts, double s) {
  std::size_t k = 0;
  while (k + 1 < parts.size() && s >= parts[k + 1].offset) ++k;
  const CompoundCurvePart& p = parts[k];
  const double along = std::clamp(s - p.offset, 0.0, length(p.range));
  return {k, p.reversed ? p.range.max - along : p.range.min + along};
}

// A compound curve's shape: its curves end to end, each over its own parameter range.
class ChainGeometry final : public CurveGeometry {
 public:
  ChainGeometry(std::vector<CompoundCurvePart> parts,
                std::vector<std::shared_ptr<const CurveGeometry>> shapes)
      : parts_(std::move(parts)), shapes_(std::move(shapes)) {}
  Interval range() const override {
    return {0, parts_.back().offset + length(parts_.back().range)};
  }
  Vec3 point(double s) const override {
    const auto [k, t] = partAt(parts_, s);
    return shapes_[k]->point(t);
  }
  Vec3 firstDerivative(double s) const override {
    const auto [k, t] = partAt(parts_, s);
    const Vec3 d = shapes_[k]->firstDerivative(t);
    return parts_[k].reversed ? -d : d;
  }
  Vec3 secondDerivative(double s) const override {
    const auto [k, t] = partAt(parts_, s);
    return shapes_[k]->secondDerivative(t);
  }

 private:
  std::vector<CompoundCurvePart> parts_;
  std::vector<std::shared_ptr<const CurveGeometry>> shapes_;
};

// The entities of a model, edited before they make the compound model.
struct Entities {
  std::map<int, ModelPoint> points;
  std::map<int, ModelCurve> curves;
  std::map<int, ModelSurface> surfaces;
  std::map<int, ModelVolume> volumes;
  MeshConstraints constraints;
};

Entities entitiesOf(const Model& model) {
  return {model.points(), model.curves(), model.surfaces(), model.volumes(),
          model.meshConstraints()};
}

std::string listed(const std::vector<int>& tags) {
  std::string text = "{";
  for (std::size_t k = 0; k < tags.size(); ++k)
    text += (k ? ", " : "") + std::to_string(tags[k]);
  return text + "}";
}

// The compounds the script declared, each once, ascending tags; single entities left out.
template <typename Map>
std::vector<std::vector<int>> compoundGroups(const Map& entities) {
  std::set<std::vector<int>> groups;
  for (const auto& [tag, entity] : entities) {
    std::vector<int> group = entity.compound;
    std::sort(group.begin(), group.end());
    group.erase(std::unique(group.begin(), group.end()), group.end());
    if (group.size() >= 2) groups.insert(group);
  }
  return {groups.begin(), groups.end()};
}

bool extrudedInLayers(const std::optional<ExtrusionRecord>& record) {
  return record && !record->layers.elements.empty();
}

bool contains(const std::vector<int>& tags, int tag) {
  return std::find(tags.begin(), tags.end(), tag) != tags.end();
}

// Why entities of dimension `dim` in `group` cannot stop being entities of their own: another
// entity copies one of them (periodic) or is swept from or to one in layers. Empty when none.
std::string referenceProblem(const Entities& e, int dim, const std::vector<int>& group) {
  // Entities of dimension `dim` copying one of the group.
  auto copies = [&](const auto& entities, const char* kind) -> std::string {
    for (const auto& [tag, entity] : entities)
      if (entity.periodic && contains(group, entity.periodic->master) && !contains(group, tag))
        return std::string(kind) + " " + std::to_string(tag) + " is a periodic copy of " +
               std::to_string(entity.periodic->master);
    return {};
  };
  // Entities of dimension dim + 1 swept from one of the group (or to one).
  auto sweeps = [&](const auto& entities, const char* kind) -> std::string {
    for (const auto& [tag, entity] : entities) {
      const auto& x = entity.extrusion;
      if (extrudedInLayers(x) && (contains(group, x->source) || contains(group, x->top)))
        return std::string(kind) + " " + std::to_string(tag) + " is swept in layers from " +
               std::to_string(contains(group, x->source) ? x->source : x->top);
    }
    return {};
  };
  std::string why = dim == 1 ? copies(e.curves, "curve") : copies(e.surfaces, "surface");
  if (why.empty()) why = dim == 1 ? sweeps(e.surfaces, "surface") : sweeps(e.volumes, "volume");
  return why;
}

// The entities the BoundaryLayer fields in use name: walls, points, fans, surfaces left out.
// A compound must keep them (a layer along a curve the compound removed would be lost).
std::set<EntityId> boundaryLayerEntities(const Model& model) {
  static constexpr std::pair<const char*, int> kLists[] = {
      {"CurvesList", 1},      {"EdgesList", 1},           {"PointsList", 0},
      {"NodesList", 0},       {"VerticesList", 0},        {"FanPointsList", 0},
      {"FanNodesList", 0},    {"ExcludedSurfacesList", 2}, {"ExcludedFaceList", 2}};
  std::set<EntityId> named;
  const MeshConstraints& c = model.meshConstraints();
  for (int field : c.boundaryLayerFields) {
    const auto it = c.sizeFields.find(field);
    if (it == c.sizeFields.end()) continue;
    for (const auto& [list, dim] : kLists)
      if (const auto values = it->second.numbers.find(list); values != it->second.numbers.end())
        for (double tag : values->second) named.insert({dim, static_cast<int>(tag)});
  }
  return named;
}

// Why the BoundaryLayer fields keep `id` from being left out; empty when they do not.
std::string layerProblem(const std::set<EntityId>& layered, EntityId id) {
  if (!layered.contains(id)) return {};
  static constexpr const char* kKinds[] = {"point", "curve", "surface"};
  return std::string(kKinds[id.dim]) + " " + std::to_string(id.tag) +
         " is named by a BoundaryLayer field";
}

// ---- Compound surfaces --------------------------------------------------------------------

// How the curves of a compound surface's surfaces are used: boundary curves once, the inner
// ones twice.
struct SurfaceGroup {
  std::vector<int> parts;
  std::map<int, int> uses;           // curve -> loops of the parts that use it
  std::map<int, int> firstSign;      // curve -> its sign in the first loop that uses it
  std::map<int, std::size_t> partOf; // boundary curve -> index of the part it bounds
  std::vector<int> inner;            // curves used twice
};

std::string surfaceGroupProblem(const Model& model, SurfaceGroup& g,
                                const std::set<EntityId>& layered) {
  const MeshConstraints& c = model.meshConstraints();
  for (std::size_t k = 0; k < g.parts.size(); ++k) {
    const int tag = g.parts[k];
    const ModelSurface* s = model.surface(tag);
    if (!s) return "surface " + std::to_string(tag) + " does not exist";
    if (s->discrete || !s->geometry)
      return "surface " + std::to_string(tag) + " has no geometry of its own";
    if (c.transfiniteSurfaces.contains(tag))
      return "surface " + std::to_string(tag) + " is transfinite";
    if (s->periodic) return "surface " + std::to_string(tag) + " is periodic";
    if (extrudedInLayers(s->extrusion))
      return "surface " + std::to_string(tag) + " is extruded in layers";
    for (const auto& loop : s->loops)
      for (int curve : loop) {
        const int t = std::abs(curve);
        if (++g.uses[t] == 1) {
          g.firstSign[t] = curve > 0 ? 1 : -1;
          g.partOf[t] = k;
        }
      }
  }
  for (const auto& [curve, count] : g.uses) {
    if (count > 2) return "curve " + std::to_string(curve) + " bounds more than two of them";
    if (count < 2) continue;
    g.inner.push_back(curve);
    for (int above : model.upward({1, curve}))
      if (!contains(g.parts, above))
        return "curve " + std::to_string(curve) + " between them also bounds surface " +
               std::to_string(above);
  }
  if (g.inner.size() == g.uses.size()) return "they have no boundary curve";
  for (int tag : g.parts)
    if (std::string why = layerProblem(layered, {2, tag}); !why.empty()) return why;
  std::set<int> kept;  // the points the boundary curves end at
  for (const auto& [curve, count] : g.uses)
    if (count == 1) kept.insert({model.curve(curve)->startPoint, model.curve(curve)->endPoint});
  for (int curve : g.inner) {
    if (std::string why = layerProblem(layered, {1, curve}); !why.empty()) return why;
    for (int point : {model.curve(curve)->startPoint, model.curve(curve)->endPoint})
      if (std::string why = kept.contains(point) ? "" : layerProblem(layered, {0, point});
          !why.empty())
        return why;
  }
  for (const auto& [tag, v] : model.volumes()) {
    std::size_t shellsWith = 0, found = 0;
    for (const auto& shell : v.shells) {
      std::size_t here = 0;
      for (int s : shell) here += contains(g.parts, std::abs(s));
      shellsWith += here > 0;
      found += here;
    }
    if (shellsWith > 1 || (found > 0 && found != g.parts.size()))
      return "volume " + std::to_string(tag) + " is not bounded by all of them in one shell";
  }
  return {};
}

// The meshes of the surfaces as one triangulation, the triangles turned to face the first
// surface's way; partOf: the index of each triangle's surface, flipped: per surface.
struct PartsTriangulation {
  Triangulation t;
  std::vector<int> partOf;
  std::vector<bool> flipped;
};

std::optional<PartsTriangulation> partsTriangulation(const Mesh& fine,
                                                     const std::vector<int>& parts) {
  PartsTriangulation out;
  std::map<NodeIndex, std::uint32_t> local;
  auto vertex = [&](NodeIndex n) {
    const auto [it, added] = local.emplace(n, static_cast<std::uint32_t>(out.t.points.size()));
    if (added) out.t.points.push_back(fine.node(n));
    return it->second;
  };
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const EntityMesh* em = fine.find({2, parts[k]});
    const ElementBlock* block = em ? em->findBlock(ElementType::Triangle3) : nullptr;
    if (!block || block->size() == 0) return std::nullopt;
    for (std::size_t e = 0; e < block->size(); ++e) {
      const auto n = block->element(e);
      out.t.triangles.push_back({vertex(n[0]), vertex(n[1]), vertex(n[2])});
      out.partOf.push_back(static_cast<int>(k));
    }
  }
  const std::vector<TriangleVertices> before = out.t.triangles;
  orientConsistently(out.t);
  auto turned = [&](std::size_t i) { return out.t.triangles[i] != before[i]; };
  if (turned(0))
    for (TriangleVertices& tri : out.t.triangles) std::swap(tri[1], tri[2]);
  std::vector<std::size_t> turnedCount(parts.size(), 0), count(parts.size(), 0);
  for (std::size_t i = 0; i < before.size(); ++i) {
    ++count[out.partOf[i]];
    turnedCount[out.partOf[i]] += turned(i);
  }
  for (std::size_t k = 0; k < parts.size(); ++k)
    out.flipped.push_back(2 * turnedCount[k] > count[k]);
  return out;
}

double loopExtent(const Triangulation& t, const std::vector<std::uint32_t>& loop) {
  BoundingBox box;
  for (std::uint32_t v : loop) box.include(t.points[v]);
  return distance(box.min, box.max);
}

// The boundary curves chained into loops, each curve signed the way its loop runs; the loop
// of largest extent first. Empty when the curves do not close into loops.
std::vector<std::vector<int>> boundaryCurveLoops(const Model& model, const SurfaceGroup& g,
                                                 const std::vector<bool>& flipped) {
  std::vector<int> boundary;
  for (const auto& [curve, count] : g.uses)
    if (count == 1) boundary.push_back(curve);
  std::set<int> unused(boundary.begin(), boundary.end());
  auto startOf = [&](int signedCurve) {
    const ModelCurve& c = *model.curve(std::abs(signedCurve));
    return signedCurve > 0 ? c.startPoint : c.endPoint;
  };
  std::vector<std::pair<double, std::vector<int>>> loops;
  while (!unused.empty()) {
    const int first = *unused.begin();
    unused.erase(unused.begin());
    const int sign = g.firstSign.at(first) * (flipped[g.partOf.at(first)] ? -1 : 1);
    std::vector<int> loop{sign * first};
    const int closesAt = startOf(loop.front());
    int at = startOf(-loop.front());
    while (at != closesAt) {
      const auto next = std::find_if(unused.begin(), unused.end(), [&](int c) {
        return model.curve(c)->startPoint == at || model.curve(c)->endPoint == at;
      });
      if (next == unused.end()) return {};
      const int signedNext = model.curve(*next)->startPoint == at ? *next : -*next;
      unused.erase(next);
      loop.push_back(signedNext);
      at = startOf(-signedNext);
    }
    BoundingBox box;
    for (int c : loop) box.include(model.boundingBox({1, std::abs(c)}));
    loops.emplace_back(distance(box.min, box.max), std::move(loop));
  }
  std::stable_sort(loops.begin(), loops.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::vector<int>> out;
  for (auto& entry : loops) out.push_back(std::move(entry.second));
  return out;
}

// The model of the compounds' surfaces, their curves and points alone, with no constraint but
// the size fields: what is meshed first to make their maps.
Model partsModel(const Model& model, const std::vector<SurfaceGroup>& groups) {
  Model parts;
  std::set<int> curves, points;
  for (const SurfaceGroup& g : groups)
    for (const auto& [curve, count] : g.uses) {
      curves.insert(curve);
      points.insert(model.curve(curve)->startPoint);
      points.insert(model.curve(curve)->endPoint);
    }
  for (int p : points) parts.addPoint(*model.point(p));
  for (int c : curves) {
    ModelCurve curve = *model.curve(c);
    curve.compound.clear();
    curve.embeddedPoints.clear();
    parts.addCurve(std::move(curve));
  }
  for (const SurfaceGroup& g : groups)
    for (int tag : g.parts) {
      ModelSurface s = *model.surface(tag);
      s.compound.clear();
      s.embeddedPoints.clear();
      s.embeddedCurves.clear();
      parts.addSurface(std::move(s));
    }
  MeshConstraints& c = parts.meshConstraints();
  c.sizeFields = model.meshConstraints().sizeFields;
  c.backgroundField = model.meshConstraints().backgroundField;
  c.backgroundView = model.meshConstraints().backgroundView;
  for (const auto& [tag, curve] : model.meshConstraints().transfiniteCurves)
    if (curves.contains(tag)) c.transfiniteCurves.emplace(tag, curve);
  parts.widenSizeBox(model.sizeBox());
  return parts;
}

// The discrete map of a compound surface's fine mesh; the reason it cannot be made otherwise.
std::string mapSurfaceGroup(const PartsTriangulation& parts, CompoundMeshing::Surface& out) {
  std::vector<std::vector<std::uint32_t>> loops = boundaryLoops(parts.t.triangles);
  if (loops.empty()) return "their meshes have no boundary";
  std::stable_sort(loops.begin(), loops.end(), [&](const auto& a, const auto& b) {
    return loopExtent(parts.t, a) > loopExtent(parts.t, b);
  });
  std::vector<std::uint32_t> all(parts.t.triangles.size());
  for (std::uint32_t k = 0; k < all.size(); ++k) all[k] = k;
  ParametrizationResult result = parametrizePatch(parts.t, all, loops);
  if (!result.map) return "their meshes cannot be mapped to the plane (" + result.failure + ")";
  PatchMap& map = *result.map;
  Triangulation patch;
  for (std::uint32_t v : map.vertices) patch.points.push_back(parts.t.points[v]);
  patch.triangles = map.triangles;
  std::vector<double> curvature;
  if (!map.planar) curvature = vertexCurvatures(patch).maxAbs;
  out.partOfTriangle = parts.partOf;
  out.geometry = std::make_shared<DiscreteSurfaceGeometry>(
      std::move(patch.points), std::move(map), std::map<int, CurveTrace>{}, std::move(curvature));
  return {};
}

template <typename Map>
void replaceInConstraint(Map& byTag, const std::vector<int>& parts, int tag) {
  for (int p : parts) {
    const auto it = byTag.find(p);
    if (it == byTag.end()) continue;
    byTag.try_emplace(tag, it->second);
    byTag.erase(it);
  }
}

// Puts the compound surface `out` in place of its surfaces, the curves between them removed.
void applySurfaceGroup(const Model& model, const SurfaceGroup& g,
                       std::vector<std::vector<int>> loops, CompoundMeshing::Surface& out,
                       Entities& e) {
  ModelSurface s;
  s.tag = out.tag;
  s.loops = std::move(loops);
  s.geometry = out.geometry;
  for (int p : g.parts) {
    const ModelSurface& part = *model.surface(p);
    s.embeddedPoints.insert(s.embeddedPoints.end(), part.embeddedPoints.begin(),
                            part.embeddedPoints.end());
    s.embeddedCurves.insert(s.embeddedCurves.end(), part.embeddedCurves.begin(),
                            part.embeddedCurves.end());
    e.surfaces.erase(p);
  }
  e.surfaces.emplace(s.tag, std::move(s));
  for (int c : g.inner) e.curves.erase(c);
  auto signedTag = [&](int signedPart) {
    for (const CompoundSurfacePart& part : out.parts)
      if (part.tag == std::abs(signedPart))
        return (signedPart > 0) == !part.flipped ? out.tag : -out.tag;
    return signedPart;
  };
  auto replace = [&](std::vector<int>& tags) {
    const auto first = std::find_if(tags.begin(), tags.end(),
                                    [&](int t) { return contains(g.parts, std::abs(t)); });
    if (first == tags.end()) return;
    const int replacement = signedTag(*first);
    std::erase_if(tags, [&](int t) { return contains(g.parts, std::abs(t)); });
    tags.push_back(replacement);
  };
  for (auto& [tag, v] : e.volumes) {
    for (auto& shell : v.shells) replace(shell);
    replace(v.embeddedSurfaces);
  }
  replaceInConstraint(e.constraints.recombinedSurfaces, g.parts, out.tag);
  replaceInConstraint(e.constraints.surfaceAlgorithms, g.parts, out.tag);
}

// ---- Compound curves ----------------------------------------------------------------------

// The curves of a compound curve end to end, from the end point of smaller tag (a closed chain:
// from the first curve's start); the reason they cannot be otherwise.
std::string chainCurves(const Entities& e, const std::vector<int>& group,
                        std::vector<CompoundCurvePart>& chain, int& first, int& last) {
  std::map<int, int> degree;
  for (int tag : group) {
    const auto it = e.curves.find(tag);
    if (it == e.curves.end())
      return "curve " + std::to_string(tag) + " lies inside a compound surface";
    const ModelCurve& c = it->second;
    if (c.discrete || !c.geometry || c.geometry->isDegenerate())
      return "curve " + std::to_string(tag) + " has no geometry of its own";
    if (e.constraints.transfiniteCurves.contains(tag))
      return "curve " + std::to_string(tag) + " is transfinite";
    if (c.periodic) return "curve " + std::to_string(tag) + " is periodic";
    if (extrudedInLayers(c.extrusion))
      return "curve " + std::to_string(tag) + " is extruded in layers";
    if (c.startPoint == c.endPoint) return "curve " + std::to_string(tag) + " is closed";
    ++degree[c.startPoint];
    ++degree[c.endPoint];
  }
  std::vector<int> ends;
  for (const auto& [point, count] : degree) {
    if (count > 2) return "three of them meet at point " + std::to_string(point);
    if (count == 1) ends.push_back(point);
    if (count != 2) continue;
    for (const auto& [tag, c] : e.curves)
      if (!contains(group, tag) && (c.startPoint == point || c.endPoint == point))
        return "point " + std::to_string(point) + " between them is also an end of curve " +
               std::to_string(tag);
    for (const auto& [tag, s] : e.surfaces)
      if (contains(s.embeddedPoints, point))
        return "point " + std::to_string(point) + " between them is embedded in surface " +
               std::to_string(tag);
  }
  if (!ends.empty() && ends.size() != 2) return "they do not form one chain";
  int at = ends.empty() ? e.curves.at(group.front()).startPoint : ends.front();
  first = at;
  std::set<int> unused(group.begin(), group.end());
  double offset = 0;
  while (!unused.empty()) {
    const auto next = std::find_if(unused.begin(), unused.end(), [&](int c) {
      return e.curves.at(c).startPoint == at || e.curves.at(c).endPoint == at;
    });
    if (next == unused.end()) return "they do not form one chain";
    const ModelCurve& c = e.curves.at(*next);
    CompoundCurvePart part{c.tag, c.startPoint != at, offset, c.geometry->range()};
    offset += length(part.range);
    at = part.reversed ? c.startPoint : c.endPoint;
    chain.push_back(part);
    unused.erase(next);
  }
  last = at;
  if (ends.empty() != (first == last)) return "they do not form one chain";
  return {};
}

// Replaces the chain's run in a loop by the compound curve; the reason it cannot be (the loop
// uses some of its curves only, or not one after the other).
std::string replaceInLoop(std::vector<int>& loop, const std::vector<CompoundCurvePart>& chain,
                          int tag) {
  auto inChain = [&](int c) {
    return std::any_of(chain.begin(), chain.end(),
                       [&](const CompoundCurvePart& p) { return p.tag == std::abs(c); });
  };
  const std::size_t n = loop.size();
  const auto count =
      static_cast<std::size_t>(std::count_if(loop.begin(), loop.end(), inChain));
  if (count == 0) return {};
  if (count != chain.size()) return "a curve loop uses some of them only";
  std::size_t start = 0;
  while (start < n && !(inChain(loop[start]) && !inChain(loop[(start + n - 1) % n]))) ++start;
  if (start == n) start = 0;  // the loop is the chain
  for (std::size_t k = 0; k < count; ++k)
    if (!inChain(loop[(start + k) % n]))
      return "a curve loop does not use them one after the other";
  const int firstUse = loop[start];
  const auto part = std::find_if(chain.begin(), chain.end(), [&](const CompoundCurvePart& p) {
    return p.tag == std::abs(firstUse);
  });
  const int sign = (firstUse > 0) == !part->reversed ? 1 : -1;
  std::vector<int> replaced{sign * tag};
  for (std::size_t k = count; k < n; ++k) replaced.push_back(loop[(start + k) % n]);
  loop = std::move(replaced);
  return {};
}

std::string replaceEmbedded(std::vector<int>& tags, const std::vector<int>& group, int tag) {
  const std::size_t count = static_cast<std::size_t>(
      std::count_if(tags.begin(), tags.end(), [&](int t) { return contains(group, t); }));
  if (count == 0) return {};
  if (count != group.size()) return "some of them only are embedded in an entity";
  std::erase_if(tags, [&](int t) { return contains(group, t); });
  tags.push_back(tag);
  return {};
}

// Puts a compound curve in place of its curves; the reason it cannot be (nothing changed then).
std::string applyCurveGroup(const std::vector<int>& group, CompoundMeshing::Curve& out,
                            const std::set<EntityId>& layered, Entities& e) {
  int first = 0, last = 0;
  std::string why = chainCurves(e, group, out.parts, first, last);
  if (why.empty()) why = referenceProblem(e, 1, group);
  for (std::size_t k = 0; k < out.parts.size() && why.empty(); ++k) {
    const ModelCurve& c = e.curves.at(out.parts[k].tag);
    why = layerProblem(layered, {1, c.tag});
    // The points between two curves of the chain are left out.
    const int inner = out.parts[k].reversed ? c.startPoint : c.endPoint;
    if (why.empty() && k + 1 < out.parts.size()) why = layerProblem(layered, {0, inner});
  }
  if (!why.empty()) return why;
  Entities edited = e;
  for (auto& [tag, s] : edited.surfaces) {
    for (auto& loop : s.loops)
      if (why = replaceInLoop(loop, out.parts, out.tag); !why.empty()) return why;
    if (why = replaceEmbedded(s.embeddedCurves, group, out.tag); !why.empty()) return why;
  }
  for (auto& [tag, v] : edited.volumes)
    if (why = replaceEmbedded(v.embeddedCurves, group, out.tag); !why.empty()) return why;
  std::vector<std::shared_ptr<const CurveGeometry>> shapes;
  bool boxedByPoints = true;
  for (const CompoundCurvePart& p : out.parts) {
    shapes.push_back(edited.curves.at(p.tag).geometry);
    boxedByPoints = boxedByPoints && edited.curves.at(p.tag).boxedByPoints;
    edited.curves.erase(p.tag);
  }
  ModelCurve c;
  c.tag = out.tag;
  c.startPoint = first;
  c.endPoint = last;
  c.geometry = std::make_shared<ChainGeometry>(out.parts, std::move(shapes));
  c.boxedByPoints = boxedByPoints;
  edited.curves.emplace(c.tag, std::move(c));
  e = std::move(edited);
  return {};
}

// The model of the edited entities; points that only removed curves ended at are left out.
Model modelOf(const Model& original, Entities e) {
  std::set<int> held;
  for (const auto& [tag, c] : e.curves) held.insert({c.startPoint, c.endPoint});
  for (const auto& [tag, s] : e.surfaces)
    held.insert(s.embeddedPoints.begin(), s.embeddedPoints.end());
  for (const auto& [tag, v] : e.volumes)
    held.insert(v.embeddedPoints.begin(), v.embeddedPoints.end());
  Model model;
  for (const auto& [tag, p] : e.points)
    if (held.contains(tag) || original.upward({0, tag}).empty()) model.addPoint(p);
  for (auto& [tag, c] : e.curves) model.addCurve(std::move(c));
  for (auto& [tag, s] : e.surfaces) model.addSurface(std::move(s));
  for (auto& [tag, v] : e.volumes) model.addVolume(std::move(v));
  std::erase_if(e.constraints.transfiniteCurves,
                [&](const auto& entry) { return !model.curve(entry.first); });
  model.meshConstraints() = std::move(e.constraints);
  model.widenSizeBox(original.sizeBox());
  return model;
}

// Reverses a linear element's orientation, its first corner kept.
void turnRound(std::vector<NodeIndex>& nodes) { std::reverse(nodes.begin() + 1, nodes.end()); }

void classifyCurve(const CompoundMeshing::Curve& cc, const Model& compound, Mesh& mesh) {
  const EntityMesh* found = mesh.find({1, cc.tag});
  if (!found) return;
  const EntityMesh em = *found;
  mesh.eraseEntity({1, cc.tag});
  const ModelCurve& curve = *compound.curve(cc.tag);
  const double total = curve.geometry->range().max;
  std::map<NodeIndex, double> sOf;
  for (std::size_t k = 0; k < em.nodes.size() && k < em.parametric.size(); ++k)
    sOf[em.nodes[k]] = em.parametric[k];
  const EntityMesh* start = mesh.find({0, curve.startPoint});
  const EntityMesh* end = mesh.find({0, curve.endPoint});
  const NodeIndex startNode = start && !start->nodes.empty() ? start->nodes[0] : NodeIndex(-1);
  const NodeIndex endNode = end && !end->nodes.empty() ? end->nodes[0] : NodeIndex(-1);
  // A node at an end of the chain: 0 or the whole length, the one nearer `other` for a closed
  // chain (whose ends are one node).
  auto parameter = [&](NodeIndex n, double other) {
    if (const auto it = sOf.find(n); it != sOf.end()) return it->second;
    if (n == startNode && n == endNode) return other < total / 2 ? 0.0 : total;
    return n == startNode ? 0.0 : total;
  };
  for (const ElementBlock& block : em.blocks) {
    for (std::size_t e = 0; e < block.size(); ++e) {
      std::vector<NodeIndex> nodes(block.element(e).begin(), block.element(e).end());
      // One segment over the whole chain runs from its start to its end.
      const bool firstKnown = sOf.contains(nodes[0]), secondKnown = sOf.contains(nodes[1]);
      const double a = firstKnown    ? sOf.at(nodes[0])
                       : secondKnown ? parameter(nodes[0], sOf.at(nodes[1]))
                                     : 0.0;
      const double b = firstKnown || secondKnown ? parameter(nodes[1], a) : total;
      const auto [k, t] = partAt(cc.parts, (a + b) / 2);
      if (cc.parts[k].reversed) std::swap(nodes[0], nodes[1]);
      ElementBlock& to = mesh.entity({1, cc.parts[k].tag}).block(block.type);
      to.nodes.insert(to.nodes.end(), nodes.begin(), nodes.end());
    }
  }
  for (std::size_t k = 0; k < em.nodes.size(); ++k) {
    const auto [part, t] = partAt(cc.parts, k < em.parametric.size() ? em.parametric[k] : 0);
    EntityMesh& to = mesh.entity({1, cc.parts[part].tag});
    to.nodes.push_back(em.nodes[k]);
    to.parametric.push_back(t);
  }
  // A reversed part's nodes and elements were added from its end: put them in its own order.
  for (const CompoundCurvePart& p : cc.parts) {
    if (!p.reversed) continue;
    EntityMesh* to = mesh.findMutable({1, p.tag});
    if (!to) continue;
    std::reverse(to->nodes.begin(), to->nodes.end());
    std::reverse(to->parametric.begin(), to->parametric.end());
    for (ElementBlock& block : to->blocks) {
      const std::size_t n = nodeCount(block.type);
      std::vector<NodeIndex> reversed;
      for (std::size_t e = block.size(); e-- > 0;)
        reversed.insert(reversed.end(), block.nodes.begin() + e * n,
                        block.nodes.begin() + (e + 1) * n);
      block.nodes = std::move(reversed);
    }
  }
}

void classifySurface(const CompoundMeshing::Surface& sc, const Model& original, Mesh& mesh) {
  const EntityMesh* found = mesh.find({2, sc.tag});
  if (!found) return;
  const EntityMesh em = *found;
  mesh.eraseEntity({2, sc.tag});
  for (const ElementBlock& block : em.blocks) {
    for (std::size_t e = 0; e < block.size(); ++e) {
      std::vector<NodeIndex> nodes(block.element(e).begin(), block.element(e).end());
      Vec3 centroid{0, 0, 0};
      for (NodeIndex n : nodes) centroid += mesh.node(n);
      centroid = centroid * (1.0 / static_cast<double>(nodes.size()));
      const CompoundSurfacePart& part = sc.parts[static_cast<std::size_t>(
          sc.partOfTriangle[sc.geometry->closestTriangle(centroid)])];
      if (part.flipped) turnRound(nodes);
      ElementBlock& to = mesh.entity({2, part.tag}).block(block.type);
      to.nodes.insert(to.nodes.end(), nodes.begin(), nodes.end());
    }
  }
  // A node goes to the surface it lies on, and onto that surface's own shape (it was placed on
  // the piecewise linear map of the first meshes).
  for (NodeIndex n : em.nodes) {
    const int tag = sc.parts[static_cast<std::size_t>(
                                 sc.partOfTriangle[sc.geometry->closestTriangle(mesh.node(n))])]
                        .tag;
    const SurfaceGeometry& shape = *original.surface(tag)->geometry;
    const Vec2 uv = shape.project(mesh.node(n));
    mesh.setNode(n, shape.point(uv));
    EntityMesh& to = mesh.entity({2, tag});
    to.nodes.push_back(n);
    to.parametric.insert(to.parametric.end(), {uv.u, uv.v});
  }
}

}  // namespace

void CompoundMeshing::classify(const Model& original, Mesh& mesh) const {
  for (const Curve& c : curves) classifyCurve(c, model, mesh);
  for (const Surface& s : surfaces) classifySurface(s, original, mesh);
}

std::optional<CompoundMeshing> planCompounds(const Model& model, const MeshOptions& options,
                                             int dim, const PartMesher& meshParts,
                                             MessageSink& log) {
  const std::vector<std::vector<int>> surfaceGroups =
      dim >= 2 ? compoundGroups(model.surfaces()) : std::vector<std::vector<int>>{};
  const std::vector<std::vector<int>> curveGroups = compoundGroups(model.curves());
  if (surfaceGroups.empty() && curveGroups.empty()) return std::nullopt;
  if (options.compoundClassify == 0)
    log.warning("Mesh.CompoundClassify 0 is not available: the elements of compounds are put "
                "on the entities they lie on (as with 1)");
  auto skip = [&](int dim, const std::vector<int>& group, const std::string& why) {
    log.warning(std::string("Compound ") + (dim == 1 ? "Curve" : "Surface") + listed(group) +
                ": " + why + "; " + (dim == 1 ? "its curves" : "its surfaces") +
                " are meshed one by one");
  };
  CompoundMeshing plan;
  Entities e = entitiesOf(model);
  const std::set<EntityId> layered = boundaryLayerEntities(model);
  // Surfaces: their meshes on their own, finer, then one map each.
  std::vector<SurfaceGroup> groups;
  for (const std::vector<int>& parts : surfaceGroups) {
    SurfaceGroup g{parts, {}, {}, {}, {}};
    std::string why = surfaceGroupProblem(model, g, layered);
    if (why.empty()) why = referenceProblem(e, 2, parts);
    bool overlaps = false;
    for (const SurfaceGroup& other : groups)
      for (int tag : parts) overlaps = overlaps || contains(other.parts, tag);
    if (!why.empty() || overlaps) {
      skip(2, parts, why.empty() ? "it shares a surface with another compound surface" : why);
      continue;
    }
    groups.push_back(std::move(g));
  }
  Mesh fine;
  if (!groups.empty()) {
    try {
      meshParts(partsModel(model, groups), options.compoundSizeFactor, fine);
    } catch (const std::exception& error) {
      for (const SurfaceGroup& g : groups)
        skip(2, g.parts,
             std::string("their surfaces cannot be meshed first (") + error.what() + ")");
      groups.clear();
    }
  }
  int nextSurface = model.maxTag(2) + 1;
  for (const SurfaceGroup& g : groups) {
    std::optional<PartsTriangulation> parts = partsTriangulation(fine, g.parts);
    if (!parts) {
      skip(2, g.parts, "a surface of it got no triangle");
      continue;
    }
    CompoundMeshing::Surface out;
    out.tag = nextSurface;
    for (std::size_t k = 0; k < g.parts.size(); ++k)
      out.parts.push_back({g.parts[k], parts->flipped[k]});
    std::vector<std::vector<int>> loops = boundaryCurveLoops(model, g, parts->flipped);
    std::string why = loops.empty() ? "their boundary curves do not close" : "";
    if (why.empty()) why = mapSurfaceGroup(*parts, out);
    if (!why.empty()) {
      skip(2, g.parts, why);
      continue;
    }
    log.info("Compound Surface" + listed(g.parts) + ": meshed as one, on the map of " +
             std::to_string(parts->t.triangles.size()) + " triangles");
    applySurfaceGroup(model, g, std::move(loops), out, e);
    plan.surfaces.push_back(std::move(out));
    ++nextSurface;
  }
  int nextCurve = model.maxTag(1) + 1;
  for (const std::vector<int>& group : curveGroups) {
    CompoundMeshing::Curve out;
    out.tag = nextCurve;
    if (const std::string why = applyCurveGroup(group, out, layered, e); !why.empty()) {
      skip(1, group, why);
      continue;
    }
    plan.curves.push_back(std::move(out));
    ++nextCurve;
  }
  if (plan.curves.empty() && plan.surfaces.empty()) return std::nullopt;
  plan.model = modelOf(model, std::move(e));
  return plan;
}

}  // namespace geomesh
