#include "kernel/occ/occ_factory.h"

#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <Bnd_Box.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_geometry.h"

namespace geomesh {

// Every shape the factory knows, by dimension: tag -> shape, and shape -> tag (the latter
// compares shapes regardless of orientation).
struct OccShapes {
  std::map<int, TopoDS_Shape> byTag[4];
  TopTools_DataMapOfShapeInteger tags[4];
  std::map<int, double> meshSizes;  // vertex tag -> MeshSize

  int tagOf(int dim, const TopoDS_Shape& s) const { return tags[dim].Find(s); }
  int maxTag(int dim) const { return byTag[dim].empty() ? 0 : byTag[dim].rbegin()->first; }
  void bind(int dim, int tag, const TopoDS_Shape& s) {
    byTag[dim][tag] = s;
    tags[dim].Bind(s, tag);
  }
  // Tags the sub-shapes of `s` not yet known, in OpenCASCADE's exploration order.
  void bindNewSubShapes(const TopoDS_Shape& s) {
    static constexpr TopAbs_ShapeEnum kTypes[3] = {TopAbs_VERTEX, TopAbs_EDGE, TopAbs_FACE};
    for (int dim = 0; dim < 3; ++dim)
      for (TopExp_Explorer it(s, kTypes[dim]); it.More(); it.Next())
        if (!tags[dim].IsBound(it.Current())) bind(dim, maxTag(dim) + 1, it.Current());
  }
};

namespace {

// Gmsh's box takes signed extents; OpenCASCADE's needs positive ones from the lowest corner.
void normalizeBox(Vec3& corner, Vec3& extent, int tag) {
  double* c[3] = {&corner.x, &corner.y, &corner.z};
  double* e[3] = {&extent.x, &extent.y, &extent.z};
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(*c[i]) || !std::isfinite(*e[i]))
      throw GeometryError("Box " + std::to_string(tag) + ": its dimensions are not finite");
    if (*e[i] == 0) throw GeometryError("Box " + std::to_string(tag) + " has a zero extent");
    if (*e[i] < 0) {
      *c[i] += *e[i];
      *e[i] = -*e[i];
    }
  }
}

int signedTag(int tag, const TopoDS_Shape& s) {
  return s.Orientation() == TopAbs_REVERSED ? -tag : tag;
}

}  // namespace

OccFactory::OccFactory() : shapes_(std::make_unique<OccShapes>()) {}
OccFactory::~OccFactory() = default;
OccFactory::OccFactory(OccFactory&&) noexcept = default;
OccFactory& OccFactory::operator=(OccFactory&&) noexcept = default;

int OccFactory::addBox(int tag, Vec3 corner, Vec3 extent) {
  if (tag < 0) tag = shapes_->maxTag(3) + 1;
  if (shapes_->byTag[3].contains(tag))
    throw GeometryError("Volume " + std::to_string(tag) + " already exists");
  normalizeBox(corner, extent, tag);
  try {
    BRepPrimAPI_MakeBox maker(gp_Pnt(corner.x, corner.y, corner.z), extent.x, extent.y,
                              extent.z);
    const TopoDS_Shape solid = maker.Solid();
    shapes_->bind(3, tag, solid);
    shapes_->bindNewSubShapes(solid);
  } catch (const Standard_Failure& e) {
    throw GeometryError("Box " + std::to_string(tag) + ": " + e.GetMessageString());
  }
  return tag;
}

double OccFactory::volume(int tag) const {
  auto it = shapes_->byTag[3].find(tag);
  if (it == shapes_->byTag[3].end())
    throw GeometryError("Volume " + std::to_string(tag) + " is not defined");
  GProp_GProps properties;
  BRepGProp::VolumeProperties(it->second, properties);
  return properties.Mass();
}

int OccFactory::maxTag(int kind) const {
  return kind >= 0 && kind <= 3 ? shapes_->maxTag(kind) : 0;
}

bool OccFactory::contains(EntityId e) const {
  return e.dim >= 0 && e.dim <= 3 && shapes_->byTag[e.dim].contains(e.tag);
}

std::vector<int> OccFactory::tags(int dim) const {
  std::vector<int> tags;
  if (dim >= 0 && dim <= 3)
    for (const auto& entry : shapes_->byTag[dim]) tags.push_back(entry.first);
  return tags;
}

Vec3 OccFactory::pointCoordinates(int tag) const {
  if (!contains({0, tag})) throw GeometryError("Point " + std::to_string(tag) + " is not defined");
  const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(shapes_->byTag[0].at(tag)));
  return {p.X(), p.Y(), p.Z()};
}

namespace {

// The shape of (dim, |tag|); throws GeometryError naming `operation` when there is none.
const TopoDS_Shape& requireShape(const OccShapes& s, EntityId shape, const char* operation) {
  const int tag = shape.tag < 0 ? -shape.tag : shape.tag;
  if (shape.dim >= 0 && shape.dim <= 3)
    if (auto it = s.byTag[shape.dim].find(tag); it != s.byTag[shape.dim].end()) return it->second;
  throw GeometryError(std::string(operation) + ": entity (" + std::to_string(shape.dim) + ", " +
                      std::to_string(tag) + ") is not defined");
}

}  // namespace

std::vector<int> OccFactory::entitiesInBox(int dim, const BoundingBox& box) const {
  std::vector<int> inside;
  if (dim < 0 || dim > 3 || box.empty()) return inside;
  const double tol = 1e-8 * distance(box.min, box.max);
  auto within = [&](const BoundingBox& b) {
    return !b.empty() && b.min.x >= box.min.x - tol && b.min.y >= box.min.y - tol &&
           b.min.z >= box.min.z - tol && b.max.x <= box.max.x + tol &&
           b.max.y <= box.max.y + tol && b.max.z <= box.max.z + tol;
  };
  for (const auto& [tag, shape] : shapes_->byTag[dim])
    if (within(boundingBox({dim, tag}))) inside.push_back(tag);
  return inside;
}

std::vector<int> OccFactory::pointsOf(const std::vector<EntityId>& shapes) const {
  for (EntityId shape : shapes) requireShape(*shapes_, shape, "PointsOf");
  std::vector<int> points;
  for (EntityId shape : shapes) {
    const TopoDS_Shape& s = requireShape(*shapes_, shape, "PointsOf");
    for (TopExp_Explorer it(s, TopAbs_VERTEX); it.More(); it.Next()) {
      const int tag = shapes_->tagOf(0, it.Current());
      if (std::find(points.begin(), points.end(), tag) == points.end()) points.push_back(tag);
    }
  }
  return points;
}

void OccFactory::setMeshSize(const std::vector<int>& points, double size) {
  for (int p : points)
    if (!contains({0, p}))
      throw GeometryError("MeshSize: point " + std::to_string(p) + " is not defined");
  for (int p : points) shapes_->meshSizes[p] = size;
}

// The box of the shape's vertices and of its curves and surfaces, tight (not enlarged by
// OpenCASCADE's tolerances).
BoundingBox OccFactory::boundingBox(EntityId shape) const {
  if (!contains(shape))
    throw GeometryError("BoundingBox: entity (" + std::to_string(shape.dim) + ", " +
                        std::to_string(shape.tag) + ") is not defined");
  Bnd_Box box;
  BRepBndLib::AddOptimal(shapes_->byTag[shape.dim].at(shape.tag), box, false, false);
  BoundingBox result;
  if (box.IsVoid()) return result;
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  result.include(Vec3{x0, y0, z0});
  result.include(Vec3{x1, y1, z1});
  return result;
}

void OccFactory::clear() { shapes_ = std::make_unique<OccShapes>(); }

namespace {

void exportPoints(const OccShapes& s, Model& model);
void exportCurves(const OccShapes& s, Model& model);
void exportSurfaces(const OccShapes& s, Model& model);
void exportVolumes(const OccShapes& s, Model& model);

}  // namespace

void OccFactory::synchronize(Model& model) const {
  exportPoints(*shapes_, model);
  exportCurves(*shapes_, model);
  exportSurfaces(*shapes_, model);
  exportVolumes(*shapes_, model);
}

namespace {

void exportPoints(const OccShapes& s, Model& model) {
  for (const auto& [tag, shape] : s.byTag[0]) {
    const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(shape));
    const auto size = s.meshSizes.find(tag);
    model.addPoint(
        ModelPoint{tag, {p.X(), p.Y(), p.Z()}, size == s.meshSizes.end() ? 0 : size->second});
  }
}

// A curve starts at the vertex of its first parameter, whatever the edge's orientation.
void exportCurves(const OccShapes& s, Model& model) {
  for (const auto& [tag, shape] : s.byTag[1]) {
    const TopoDS_Edge edge = TopoDS::Edge(shape.Oriented(TopAbs_FORWARD));
    const int start = s.tagOf(0, TopExp::FirstVertex(edge));
    const int end = s.tagOf(0, TopExp::LastVertex(edge));
    model.addCurve(ModelCurve{tag, start, end, makeOccCurve(edge)});
  }
}

// Loops follow the face taken forward, so that the outer loop runs counter-clockwise in the
// surface's parameter plane; an edge used against its own direction gets a negative tag.
std::vector<int> wireLoop(const OccShapes& s, const TopoDS_Face& face,
                          const TopoDS_Wire& wire) {
  std::vector<int> loop;
  for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next())
    loop.push_back(signedTag(s.tagOf(1, it.Current()), it.Current()));
  return loop;
}

void exportSurfaces(const OccShapes& s, Model& model) {
  for (const auto& [tag, shape] : s.byTag[2]) {
    const TopoDS_Face face = TopoDS::Face(shape.Oriented(TopAbs_FORWARD));
    ModelSurface surface{tag, {}, makeOccSurface(face), {}, {}};
    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    surface.loops.push_back(wireLoop(s, face, outer));
    for (TopExp_Explorer it(face, TopAbs_WIRE); it.More(); it.Next())
      if (!it.Current().IsSame(outer))
        surface.loops.push_back(wireLoop(s, face, TopoDS::Wire(it.Current())));
    model.addSurface(std::move(surface));
  }
}

void exportVolumes(const OccShapes& s, Model& model) {
  for (const auto& [tag, shape] : s.byTag[3]) {
    ModelVolume volume{tag, {}};
    for (TopExp_Explorer shell(shape, TopAbs_SHELL); shell.More(); shell.Next()) {
      volume.shells.emplace_back();
      for (TopExp_Explorer face(shell.Current(), TopAbs_FACE); face.More(); face.Next())
        volume.shells.back().push_back(signedTag(s.tagOf(2, face.Current()), face.Current()));
    }
    model.addVolume(std::move(volume));
  }
}

}  // namespace

std::vector<EntityId> OccFactory::boundary(const std::vector<EntityId>& shapes,
                                           bool combined) const {
  for (EntityId shape : shapes) requireShape(*shapes_, shape, "Boundary");
  std::vector<EntityId> out;
  for (EntityId shape : shapes) {
    const TopoDS_Shape& s = requireShape(*shapes_, shape, "Boundary");
    if (shape.dim == 1) {
      const TopoDS_Edge edge = TopoDS::Edge(s.Oriented(TopAbs_FORWARD));
      int ends[2] = {shapes_->tagOf(0, TopExp::FirstVertex(edge)),
                     shapes_->tagOf(0, TopExp::LastVertex(edge))};
      if (shape.tag < 0) std::swap(ends[0], ends[1]);
      out.push_back({0, ends[0]});
      out.push_back({0, ends[1]});
    } else if (shape.dim == 2) {
      const TopoDS_Face face = TopoDS::Face(s.Oriented(TopAbs_FORWARD));
      for (TopExp_Explorer wire(face, TopAbs_WIRE); wire.More(); wire.Next())
        for (int c : wireLoop(*shapes_, face, TopoDS::Wire(wire.Current())))
          out.push_back({1, std::abs(c)});
    } else if (shape.dim == 3) {
      for (TopExp_Explorer face(s, TopAbs_FACE); face.More(); face.Next())
        out.push_back({2, shapes_->tagOf(2, face.Current())});
    }
  }
  return combined ? cancelShared(out) : out;
}

}  // namespace geomesh
