// CAD parts for tests, built with OpenCASCADE and written to scratch BREP or STEP files at run
// time: a cylinder, a sphere, a cone, a torus and a box with a cylindrical hole.
#pragma once
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepTools.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Ax2.hxx>

#include <numbers>
#include <string>

#include "tests/scratch.h"

namespace geomesh::occ_fixtures {

struct Part {
  const char* name;
  TopoDS_Shape shape;
  double area, volume;  // exact
};

inline Part cylinder() {  // radius 1, height 2
  const double pi = std::numbers::pi;
  return {"cylinder", BRepPrimAPI_MakeCylinder(1.0, 2.0).Shape(), 2 * pi * 1 * 2 + 2 * pi,
          pi * 2};
}
inline Part sphere() {  // radius 1
  const double pi = std::numbers::pi;
  return {"sphere", BRepPrimAPI_MakeSphere(1.0).Shape(), 4 * pi, 4 * pi / 3};
}
inline Part cone() {  // base radius 1, apex at height 2
  const double pi = std::numbers::pi;
  const double slant = std::sqrt(1.0 + 4.0);
  return {"cone", BRepPrimAPI_MakeCone(1.0, 0.0, 2.0).Shape(), pi * slant + pi, pi * 2 / 3};
}
inline Part torus() {  // radii 2 and 0.5
  const double pi = std::numbers::pi;
  return {"torus", BRepPrimAPI_MakeTorus(2.0, 0.5).Shape(), 4 * pi * pi * 2 * 0.5,
          2 * pi * pi * 2 * 0.25};
}
inline Part boxWithHole() {  // 2 x 2 x 1, a hole of radius 0.5 through its height
  const double pi = std::numbers::pi;
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(2.0, 2.0, 1.0).Shape();
  const TopoDS_Shape hole =
      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(1, 1, -1), gp_Dir(0, 0, 1)), 0.5, 3.0).Shape();
  BRepAlgoAPI_Cut cut(box, hole);
  return {"box_with_hole", cut.Shape(), 2 * (4 - pi * 0.25) + 4 * 2 + 2 * pi * 0.5,
          4 - pi * 0.25};
}

// A saddle: the ruled face between two skew unit segments, z = (1 - 2x) y / 2 over the unit
// square, bounded by four straight edges; its curvature is 1 at its centre.
inline Part saddle() {
  auto segment = [](gp_Pnt a, gp_Pnt b) {
    return BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(a, b).Edge()).Wire();
  };
  BRepOffsetAPI_ThruSections loft(false, true);
  loft.AddWire(segment(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)));
  loft.AddWire(segment(gp_Pnt(0, 1, 0.5), gp_Pnt(1, 1, -0.5)));
  loft.Build();
  return {"saddle", loft.Shape(), 0, 0};
}

inline std::string writeBrep(const Part& part) {
  const std::string path = scratch::path(std::string(part.name) + ".brep").string();
  BRepTools::Write(part.shape, path.c_str());
  return path;
}

inline std::string writeStep(const Part& part) {
  const std::string path = scratch::path(std::string(part.name) + ".step").string();
  STEPControl_Writer writer;
  writer.Transfer(part.shape, STEPControl_AsIs);
  writer.Write(path.c_str());
  return path;
}

}  // namespace geomesh::occ_fixtures
