// Shape healing: OpenCASCADE's ShapeFix tools, sewing and solids made of closed shells.
#include "kernel/occ/occ_healing.h"

#include <BRepBuilderAPI_Sewing.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <ShapeBuild_ReShape.hxx>
#include <ShapeFix_FixSmallFace.hxx>
#include <ShapeFix_Shape.hxx>
#include <ShapeFix_Solid.hxx>
#include <ShapeFix_Wireframe.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "kernel/occ/occ_factory.h"
#include "kernel/occ/occ_shapes.h"

namespace geomesh {

namespace {

using Options = SolidModeling::HealingOptions;

TopoDS_Shape fixDegenerated(const TopoDS_Shape& shape, double tolerance) {
  Handle(ShapeFix_Shape) fix = new ShapeFix_Shape(shape);
  fix->SetPrecision(tolerance);
  fix->SetMinTolerance(tolerance);
  fix->SetMaxTolerance(std::max(1.0, tolerance));
  fix->Perform();
  return fix->Shape();
}

// Degenerated edges (a sphere's poles) go first, then the edges shorter than the tolerance.
TopoDS_Shape fixSmallEdges(const TopoDS_Shape& shape, double tolerance) {
  Handle(ShapeBuild_ReShape) reshape = new ShapeBuild_ReShape;
  for (TopExp_Explorer it(shape, TopAbs_EDGE); it.More(); it.Next())
    if (BRep_Tool::Degenerated(TopoDS::Edge(it.Current()))) reshape->Remove(it.Current());
  Handle(ShapeFix_Wireframe) fix = new ShapeFix_Wireframe(reshape->Apply(shape));
  fix->SetPrecision(tolerance);
  fix->SetMaxTolerance(std::max(1.0, tolerance));
  fix->ModeDropSmallEdges() = Standard_True;
  fix->FixSmallEdges();
  return fix->Shape();
}

// Spot faces (shrunk to a point) and strip faces (to a line) go.
TopoDS_Shape fixSmallFaces(const TopoDS_Shape& shape, double tolerance) {
  ShapeFix_FixSmallFace fix;
  fix.Init(shape);
  fix.SetPrecision(tolerance);
  fix.SetMaxTolerance(std::max(1.0, tolerance));
  fix.FixSpotFace();
  return fix.FixStripFace();
}

// The parts of a shape: its solids, the shells and faces outside solids, the edges outside
// faces, the vertices outside edges.
struct Parts {
  std::vector<TopoDS_Shape> solids, shells, faces, rest;
};

Parts partsOf(const TopoDS_Shape& shape) {
  Parts parts;
  for (TopExp_Explorer it(shape, TopAbs_SOLID); it.More(); it.Next())
    parts.solids.push_back(it.Current());
  for (TopExp_Explorer it(shape, TopAbs_SHELL, TopAbs_SOLID); it.More(); it.Next())
    parts.shells.push_back(it.Current());
  for (TopExp_Explorer it(shape, TopAbs_FACE, TopAbs_SHELL); it.More(); it.Next())
    parts.faces.push_back(it.Current());
  for (TopExp_Explorer it(shape, TopAbs_EDGE, TopAbs_FACE); it.More(); it.Next())
    parts.rest.push_back(it.Current());
  for (TopExp_Explorer it(shape, TopAbs_VERTEX, TopAbs_EDGE); it.More(); it.Next())
    parts.rest.push_back(it.Current());
  return parts;
}

TopoDS_Shape compoundOf(const Parts& parts) {
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  for (const auto* list : {&parts.solids, &parts.shells, &parts.faces, &parts.rest})
    for (const TopoDS_Shape& s : *list) builder.Add(all, s);
  return all;
}

// The faces outside solids sewn together; solids and the rest stay as they are.
Parts sewFaces(Parts parts, double tolerance) {
  BRepBuilderAPI_Sewing sewing(tolerance);
  int added = 0;
  for (const auto* list : {&parts.shells, &parts.faces})
    for (const TopoDS_Shape& s : *list)
      for (TopExp_Explorer it(s, TopAbs_FACE); it.More(); it.Next(), ++added)
        sewing.Add(it.Current());
  if (added == 0) return parts;
  sewing.Perform();
  const Parts sewn = partsOf(sewing.SewedShape());
  parts.shells = sewn.shells;
  parts.faces = sewn.faces;
  return parts;
}

// Each closed shell outside solids becomes a solid, oriented outwards.
Parts makeSolids(Parts parts) {
  std::vector<TopoDS_Shape> open;
  for (const TopoDS_Shape& s : parts.shells) {
    const TopoDS_Shell shell = TopoDS::Shell(s);
    if (!BRep_Tool::IsClosed(shell)) {
      open.push_back(s);
      continue;
    }
    ShapeFix_Solid fix;
    parts.solids.push_back(fix.SolidFromShell(shell));
  }
  parts.shells = open;
  return parts;
}

}  // namespace

TopoDS_Shape healedShape(const TopoDS_Shape& shape, const Options& options) {
  const double tolerance = options.tolerance > 0 ? options.tolerance : 1e-8;
  TopoDS_Shape s = shape;
  if (options.fixDegenerated) s = fixDegenerated(s, tolerance);
  if (options.fixSmallEdges) s = fixSmallEdges(s, tolerance);
  if (options.fixSmallFaces) s = fixSmallFaces(s, tolerance);
  if (!options.sewFaces && !options.makeSolids) return s;
  Parts parts = partsOf(s);
  if (options.sewFaces) parts = sewFaces(std::move(parts), tolerance);
  if (options.makeSolids) parts = makeSolids(std::move(parts));
  return compoundOf(parts);
}

// HealShapes: the shapes go, their healed form takes new tags. Healing every shape starts the
// numbering again from 1, as in the reference.
std::vector<EntityId> OccFactory::healShapes(const std::vector<EntityId>& shapes,
                                             const HealingOptions& options) {
  TopoDS_Shape input = compoundOfAll(*shapes_);
  if (!shapes.empty()) input = compoundOf(*shapes_, shapes);
  const TopoDS_Shape result =
      guarded("HealShapes", [&] { return healedShape(input, options); });
  if (shapes.empty()) {
    clear();
  } else {
    for (const EntityId& e : shapes) shapes_->unbind(e.dim, std::abs(e.tag), true);
  }
  return bindShapes(*shapes_, result, true);
}

}  // namespace geomesh
