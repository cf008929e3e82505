// The OpenCASCADE factory's queries (boundary, points, boxes) and shape operations
// (transformations, copies, deletion).
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_GTransform.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_GTrsf.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"
#include "kernel/occ/occ_shapes.h"

namespace geomesh {

namespace {

constexpr TopAbs_ShapeEnum kTypes[4] = {TopAbs_VERTEX, TopAbs_EDGE, TopAbs_FACE, TopAbs_SOLID};

// A face's edges as the reference lists them: each wire of the face taken forward, as it stores
// its edges (a wire reversed as a whole to bound the face is read as it was made, see
// addPlaneSurface), chained from the wire's first stored edge along the wire.
std::vector<int> faceEdges(const OccShapes& s, const TopoDS_Shape& faceShape) {
  const TopoDS_Face face = TopoDS::Face(faceShape.Oriented(TopAbs_FORWARD));
  std::vector<int> edges;
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
    const TopoDS_Wire wire = TopoDS::Wire(w.Current().Oriented(TopAbs_FORWARD));
    std::vector<int> chained;
    for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next())
      chained.push_back(s.tagOf(1, it.Current()));
    TopExp_Explorer first(wire, TopAbs_EDGE);
    if (chained.empty() || !first.More()) continue;
    const int start = s.tagOf(1, first.Current());
    auto at = std::find(chained.begin(), chained.end(), start);
    if (at != chained.end()) std::rotate(chained.begin(), at, chained.end());
    edges.insert(edges.end(), chained.begin(), chained.end());
  }
  return edges;
}

std::vector<EntityId> boundaryOf(const OccShapes& s, EntityId e) {
  const TopoDS_Shape& shape = s.find(e.dim, std::abs(e.tag));
  std::vector<EntityId> out;
  if (e.dim == 1) {
    const TopoDS_Edge edge = TopoDS::Edge(shape.Oriented(TopAbs_FORWARD));
    int a = s.tagOf(0, TopExp::FirstVertex(edge)), b = s.tagOf(0, TopExp::LastVertex(edge));
    if (e.tag < 0) std::swap(a, b);
    out = {{0, a}, {0, b}};
  } else if (e.dim == 2) {
    for (int c : faceEdges(s, shape)) out.push_back({1, c});
  } else if (e.dim == 3) {
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next())
      out.push_back({2, s.tagOf(2, it.Current())});
  }
  return out;
}

}  // namespace

std::vector<EntityId> OccFactory::boundary(const std::vector<EntityId>& shapes,
                                           bool combined) const {
  std::vector<EntityId> out;
  for (const EntityId& e : shapes) {
    const std::vector<EntityId> b = boundaryOf(*shapes_, e);
    out.insert(out.end(), b.begin(), b.end());
  }
  if (!combined) return out;
  std::map<EntityId, int> count;
  for (const EntityId& e : out) ++count[{e.dim, std::abs(e.tag)}];
  std::vector<EntityId> kept;
  for (const auto& [e, n] : count)
    if (n == 1) kept.push_back(e);
  return kept;
}

// As the reference lists them: a curve's start and end (reversed for a negative tag), the
// points of a surface or a volume in ascending tags; each point once.
std::vector<int> OccFactory::pointsOf(const std::vector<EntityId>& shapes) const {
  std::vector<int> out;
  std::set<int> seen;
  for (const EntityId& e : shapes) {
    std::vector<int> points;
    if (e.dim == 1) {
      for (const EntityId& end : boundaryOf(*shapes_, e)) points.push_back(end.tag);
    } else {
      std::set<int> sorted;
      for (TopExp_Explorer it(shapes_->find(e.dim, std::abs(e.tag)), TopAbs_VERTEX); it.More();
           it.Next())
        sorted.insert(shapes_->tagOf(0, it.Current()));
      points.assign(sorted.begin(), sorted.end());
    }
    for (int tag : points)
      if (seen.insert(tag).second) out.push_back(tag);
  }
  return out;
}

namespace {

BoundingBox fromBndBox(const Bnd_Box& box) {
  BoundingBox result;
  if (box.IsVoid()) return result;
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  result.include(Vec3{x0, y0, z0});
  result.include(Vec3{x1, y1, z1});
  return result;
}

// OpenCASCADE's box of the shape, which holds the shape's tolerance around it.
BoundingBox occBox(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box, false);
  return fromBndBox(box);
}

// The tight box of the shape (without the tolerance OpenCASCADE adds around it).
BoundingBox tightBox(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::AddOptimal(shape, box, false, false);
  return fromBndBox(box);
}

}  // namespace

BoundingBox OccFactory::boundingBox(EntityId shape) const {
  return occBox(shapes_->find(shape.dim, std::abs(shape.tag)));
}

// Entities whose tight box is inside `box`, to 1e-8 of the box's diagonal.
std::vector<int> OccFactory::entitiesInBox(int dim, const BoundingBox& box) const {
  std::vector<int> out;
  if (dim < 0 || dim > 3 || box.empty()) return out;
  const double tol = 1e-8 * distance(box.min, box.max);
  auto within = [&](const BoundingBox& b) {
    return !b.empty() && b.min.x >= box.min.x - tol && b.min.y >= box.min.y - tol &&
           b.min.z >= box.min.z - tol && b.max.x <= box.max.x + tol &&
           b.max.y <= box.max.y + tol && b.max.z <= box.max.z + tol;
  };
  for (const auto& [tag, shape] : shapes_->byTag[dim])
    if (within(tightBox(shape))) out.push_back(tag);
  return out;
}

std::vector<EntityId> OccFactory::closest(Vec3 point,
                                          const std::vector<EntityId>& shapes) const {
  const TopoDS_Vertex vertex = BRepBuilderAPI_MakeVertex(gp_Pnt(point.x, point.y, point.z));
  std::vector<std::pair<double, EntityId>> byDistance;
  for (const EntityId& e : shapes) {
    const TopoDS_Shape& shape = shapes_->find(e.dim, std::abs(e.tag));
    const double d = guarded("Closest", [&] {
      BRepExtrema_DistShapeShape distance(vertex, shape);
      if (!distance.IsDone())
        throw GeometryError("Closest: no distance to " + entityName(e.dim, std::abs(e.tag)));
      return distance.Value();
    });
    byDistance.push_back({d, e});
  }
  std::stable_sort(byDistance.begin(), byDistance.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<EntityId> out;
  for (const auto& entry : byDistance) out.push_back(entry.second);
  return out;
}

void OccFactory::remove(const std::vector<EntityId>& shapes, bool recursive) {
  for (const EntityId& e : shapes) {
    const int tag = std::abs(e.tag);
    if (!shapes_->contains(e.dim, tag)) continue;
    bool used = false;
    for (int up = e.dim + 1; up <= 3 && !used; ++up)
      for (const auto& [t, shape] : shapes_->byTag[up]) {
        for (TopExp_Explorer it(shape, kTypes[e.dim]); it.More() && !used; it.Next())
          used = it.Current().IsSame(shapes_->byTag[e.dim].at(tag));
        if (used) break;
      }
    if (!used) shapes_->unbind(e.dim, tag, recursive);
  }
}

namespace {

// Whether the map is a similarity OpenCASCADE's gp_Trsf holds (rotation times a uniform
// scale, possibly mirrored); else it needs a general transformation.
bool isSimilarity(const AffineMap& map, double& scale) {
  const auto& m = map.m;
  const Vec3 c0{m[0], m[4], m[8]}, c1{m[1], m[5], m[9]}, c2{m[2], m[6], m[10]};
  scale = std::cbrt(std::abs(dot(c0, cross(c1, c2))));
  if (!(scale > 0)) return false;
  const double tol = 1e-12 * scale * scale;
  const double s2 = scale * scale;
  return std::abs(dot(c0, c0) - s2) < tol && std::abs(dot(c1, c1) - s2) < tol &&
         std::abs(dot(c2, c2) - s2) < tol && std::abs(dot(c0, c1)) < tol &&
         std::abs(dot(c0, c2)) < tol && std::abs(dot(c1, c2)) < tol;
}

// The map with its pivot folded into the translation.
std::array<double, 12> folded(const AffineMap& map) {
  std::array<double, 12> m = map.m;
  const Vec3 p = map.pivot;
  for (int r = 0; r < 3; ++r)
    m[4 * r + 3] += (r == 0 ? p.x : r == 1 ? p.y : p.z) -
                    (m[4 * r] * p.x + m[4 * r + 1] * p.y + m[4 * r + 2] * p.z);
  return m;
}


}  // namespace

// As the reference does: each shape keeps its tag, and its sub-shapes, made anew, take new
// tags (after the shapes' old sub-shapes are gone). The shapes are transformed together, as
// one compound, so that shapes sharing a sub-shape still share its image.
void OccFactory::transform(const std::vector<EntityId>& shapes, const AffineMap& map) {
  const std::array<double, 12> m = folded(map);
  double scale = 1;
  const bool similarity = isSimilarity(map, scale);
  const TopoDS_Shape all = compoundOf(*shapes_, shapes);
  const TopoDS_Shape moved = guarded("the transformation", [&] {
    if (similarity) {
      gp_Trsf t;
      t.SetValues(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8], m[9], m[10], m[11]);
      return BRepBuilderAPI_Transform(all, t, true).Shape();
    }
    gp_GTrsf t;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) t.SetValue(r + 1, c + 1, m[4 * r + c]);
      t.SetValue(r + 1, 4, m[4 * r + 3]);
    }
    return BRepBuilderAPI_GTransform(all, t, true).Shape();
  });
  std::vector<std::pair<EntityId, TopoDS_Shape>> images;
  auto e = shapes.begin();
  for (TopoDS_Iterator it(moved); it.More() && e != shapes.end(); it.Next(), ++e)
    images.emplace_back(EntityId{e->dim, std::abs(e->tag)}, it.Value());
  for (const auto& [id, image] : images) shapes_->unbind(id.dim, id.tag, true);
  for (const auto& [id, image] : images) shapes_->bindTree(id.dim, id.tag, image);
}

// The shapes are copied together, as one compound, so that copies of shapes that shared
// sub-shapes (curves meeting at a point) share the copies of those.
std::vector<EntityId> OccFactory::duplicate(const std::vector<EntityId>& shapes) {
  const TopoDS_Shape all = compoundOf(*shapes_, shapes);
  const TopoDS_Shape copy =
      guarded("Duplicata", [&] { return BRepBuilderAPI_Copy(all).Shape(); });
  std::vector<EntityId> out;
  auto e = shapes.begin();
  for (TopoDS_Iterator it(copy); it.More() && e != shapes.end(); it.Next(), ++e)
    out.push_back({e->dim, shapes_->bindNew(e->dim, it.Value())});
  return out;
}

}  // namespace geomesh
