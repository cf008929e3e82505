// OccFactory: OpenCASCADE boxes, their sub-shapes tagged, exported to the Model.
#include "kernel/occ/occ_factory.h"

#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_geometry.h"
#include "kernel/occ/occ_shapes.h"

namespace geomesh {

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
  tag = primitiveTag(3, tag, "Box");
  normalizeBox(corner, extent, tag);
  const TopoDS_Shape solid = guarded("Box " + std::to_string(tag), [&] {
    BRepPrimAPI_MakeBox maker(gp_Pnt(corner.x, corner.y, corner.z), extent.x, extent.y,
                              extent.z);
    return maker.Solid();
  });
  shapes_->bindTree(3, tag, solid);
  return tag;
}

namespace {

double mass(const TopoDS_Shape& s, int dim) {
  GProp_GProps properties;
  if (dim == 3) BRepGProp::VolumeProperties(s, properties);
  if (dim == 2) BRepGProp::SurfaceProperties(s, properties);
  if (dim == 1) BRepGProp::LinearProperties(s, properties);
  return properties.Mass();
}

}  // namespace

double OccFactory::volume(int tag) const { return mass(shapes_->find(3, tag), 3); }
double OccFactory::area(int tag) const { return mass(shapes_->find(2, tag), 2); }
double OccFactory::length(int tag) const { return mass(shapes_->find(1, tag), 1); }

int OccFactory::maxTag(int kind) const {
  if (kind >= 0 && kind <= 3) return shapes_->maxTag(kind);
  if (kind == kCurveLoop) return shapes_->wires.empty() ? 0 : shapes_->wires.rbegin()->first;
  if (kind == kSurfaceLoop) return shapes_->shells.empty() ? 0 : shapes_->shells.rbegin()->first;
  return 0;
}

bool OccFactory::contains(EntityId e) const { return shapes_->contains(e.dim, e.tag); }

std::vector<int> OccFactory::tags(int dim) const {
  std::vector<int> tags;
  if (dim >= 0 && dim <= 3)
    for (const auto& entry : shapes_->byTag[dim]) tags.push_back(entry.first);
  return tags;
}

Vec3 OccFactory::pointCoordinates(int tag) const {
  const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(shapes_->find(0, tag)));
  return {p.X(), p.Y(), p.Z()};
}

void OccFactory::clear() {
  shapes_ = std::make_unique<OccShapes>();
  meshSizes_.clear();
}

// A primitive's tag: the one given, or the next free one; taken tags are refused.
int OccFactory::primitiveTag(int dim, int tag, const char* what) const {
  if (tag < 0) return shapes_->maxTag(dim) + 1;
  if (shapes_->contains(dim, tag))
    throw GeometryError(std::string(what) + ": " + entityName(dim, tag) + " already exists");
  return tag;
}

namespace {

using Extrusions = std::map<EntityId, ExtrusionRecord>;
void exportPoints(const OccShapes& s, const std::map<int, double>& sizes, Model& model);
void exportCurves(const OccShapes& s, const Extrusions& extrusions, Model& model);
void exportSurfaces(const OccShapes& s, const Extrusions& extrusions, Model& model);
void exportVolumes(const OccShapes& s, const Extrusions& extrusions, Model& model);

// The record of an extruded entity, if it still exists as extruded.
std::optional<ExtrusionRecord> extrusionOf(const Extrusions& extrusions, EntityId e) {
  auto it = extrusions.find(e);
  if (it == extrusions.end()) return std::nullopt;
  return it->second;
}

}  // namespace

void OccFactory::synchronize(Model& model) const {
  guarded("synchronizing the OpenCASCADE model", [&] {
    exportPoints(*shapes_, meshSizes_, model);
    exportCurves(*shapes_, shapes_->extrusions, model);
    exportSurfaces(*shapes_, shapes_->extrusions, model);
    exportVolumes(*shapes_, shapes_->extrusions, model);
    applyConstraints(*shapes_, model);
    return 0;
  });
}

namespace {

void exportPoints(const OccShapes& s, const std::map<int, double>& sizes, Model& model) {
  for (const auto& [tag, shape] : s.byTag[0]) {
    const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(shape));
    auto size = sizes.find(tag);
    model.addPoint(ModelPoint{tag, {p.X(), p.Y(), p.Z()}, size == sizes.end() ? 0 : size->second});
  }
}

// A curve starts at the vertex of its first parameter, whatever the edge's orientation.
void exportCurves(const OccShapes& s, const Extrusions& extrusions, Model& model) {
  for (const auto& [tag, shape] : s.byTag[1]) {
    const TopoDS_Edge edge = TopoDS::Edge(shape.Oriented(TopAbs_FORWARD));
    const int start = s.tagOf(0, TopExp::FirstVertex(edge));
    const int end = s.tagOf(0, TopExp::LastVertex(edge));
    model.addCurve(
        ModelCurve{tag, start, end, makeOccCurve(edge), extrusionOf(extrusions, {1, tag})});
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

// The vertices a face or a solid holds directly, not on its boundary (a point fragmented
// with it): the mesh goes through them.
std::vector<int> internalPoints(const OccShapes& s, const TopoDS_Shape& shape) {
  std::vector<int> points;
  for (TopoDS_Iterator it(shape); it.More(); it.Next())
    if (it.Value().ShapeType() == TopAbs_VERTEX && s.isBound(0, it.Value()))
      points.push_back(s.tagOf(0, it.Value()));
  return points;
}

void exportSurfaces(const OccShapes& s, const Extrusions& extrusions, Model& model) {
  for (const auto& [tag, shape] : s.byTag[2]) {
    const TopoDS_Face face = TopoDS::Face(shape.Oriented(TopAbs_FORWARD));
    const auto edgeTag = [&s](const TopoDS_Edge& e) { return signedTag(s.tagOf(1, e), e); };
    ModelSurface surface{tag, {}, makeOccSurface(face, edgeTag), {}, {},
                         extrusionOf(extrusions, {2, tag})};
    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    surface.loops.push_back(wireLoop(s, face, outer));
    for (TopExp_Explorer it(face, TopAbs_WIRE); it.More(); it.Next())
      if (!it.Current().IsSame(outer))
        surface.loops.push_back(wireLoop(s, face, TopoDS::Wire(it.Current())));
    surface.embeddedPoints = internalPoints(s, shape);
    model.addSurface(std::move(surface));
  }
}

// Faces and edges a solid holds inside it (a face or a curve fragmented with it: the solid
// keeps them as internal parts): the mesh conforms to them, as to embedded entities.
void internalFacesAndEdges(const OccShapes& s, const TopoDS_Shape& solid, ModelVolume& volume) {
  auto add = [](std::vector<int>& tags, int tag) {
    if (std::find(tags.begin(), tags.end(), tag) == tags.end()) tags.push_back(tag);
  };
  for (TopExp_Explorer face(solid, TopAbs_FACE); face.More(); face.Next())
    if (face.Current().Orientation() == TopAbs_INTERNAL && s.isBound(2, face.Current()))
      add(volume.embeddedSurfaces, s.tagOf(2, face.Current()));
  for (TopoDS_Iterator part(solid); part.More(); part.Next()) {
    if (part.Value().ShapeType() != TopAbs_WIRE && part.Value().ShapeType() != TopAbs_EDGE)
      continue;
    for (TopExp_Explorer edge(part.Value(), TopAbs_EDGE); edge.More(); edge.Next())
      if (s.isBound(1, edge.Current())) add(volume.embeddedCurves, s.tagOf(1, edge.Current()));
  }
}

void exportVolumes(const OccShapes& s, const Extrusions& extrusions, Model& model) {
  for (const auto& [tag, shape] : s.byTag[3]) {
    ModelVolume volume{tag, {}, extrusionOf(extrusions, {3, tag})};
    for (TopExp_Explorer shell(shape, TopAbs_SHELL); shell.More(); shell.Next()) {
      std::vector<int> faces;
      for (TopExp_Explorer face(shell.Current(), TopAbs_FACE); face.More(); face.Next())
        if (face.Current().Orientation() != TopAbs_INTERNAL)
          faces.push_back(signedTag(s.tagOf(2, face.Current()), face.Current()));
      if (!faces.empty()) volume.shells.push_back(std::move(faces));
    }
    volume.embeddedPoints = internalPoints(s, shape);
    internalFacesAndEdges(s, shape, volume);
    model.addVolume(std::move(volume));
  }
}

}  // namespace

}  // namespace geomesh
