// Every kind of OpenCASCADE curve and surface a CAD part brings, meshed by every 2D algorithm
// (and recombined, and transfinite where the face has four sides), then filled with
// tetrahedra: surfaces of revolution (with and without poles), of linear extrusion, B-spline and
// Bezier patches, B-spline faces trimmed by holes, offset surfaces; ellipses, B-spline, offset
// and trimmed curves. Areas, volumes and lengths are compared with OpenCASCADE's own integrals
// of the exact shapes.
#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_GTransform.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <GProp_GProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Ellipse.hxx>
#include <Geom_OffsetCurve.hxx>
#include <Geom_OffsetSurface.hxx>
#include <Geom_SurfaceOfLinearExtrusion.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Ax2.hxx>
#include <gp_Ax1.hxx>
#include <gp_Elips.hxx>
#include <gp_GTrsf.hxx>

#include <cmath>
#include <numbers>
#include <string>

#include "kernel/occ/occ_factory.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/pipeline/generate.h"
#include "mesh/sizes/size_rules.h"
#include "mesh_measures.h"
#include "tests/scratch.h"

namespace geomesh {
namespace {

using namespace testing;

// What OpenCASCADE integrates on the exact shape.
double exactArea(const TopoDS_Shape& shape) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(shape, props, 1e-9);
  return props.Mass();
}
double exactVolume(const TopoDS_Shape& shape) {
  GProp_GProps props;
  BRepGProp::VolumeProperties(shape, props, 1e-9);
  return props.Mass();
}

// True when some face of the shape lies on a surface of the given OpenCASCADE type.
template <class SurfaceType>
bool hasFaceOf(const TopoDS_Shape& shape) {
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
    Handle(Geom_Surface) s = BRep_Tool::Surface(TopoDS::Face(e.Current()));
    if (!s.IsNull() && s->IsKind(STANDARD_TYPE(SurfaceType))) return true;
  }
  return false;
}

Model modelOf(const TopoDS_Shape& shape, const std::string& name) {
  const std::string path = scratch::path(name + ".brep").string();
  BRepTools::Write(shape, path.c_str());
  OccFactory occ;
  occ.importShapes(path);
  Model model;
  occ.synchronize(model);
  return model;
}

// --- The shapes -------------------------------------------------------------------------------

TopoDS_Edge segment(gp_Pnt a, gp_Pnt b) { return BRepBuilderAPI_MakeEdge(a, b).Edge(); }

// A ring whose outer wall is a surface of revolution of a Bezier arc (inner wall a cylinder):
// the profile x in [1, ~1.4], z in [0, 1] turned about z.
TopoDS_Shape revolvedRing() {
  TColgp_Array1OfPnt poles(1, 3);
  poles(1) = gp_Pnt(1, 0, 0);
  poles(2) = gp_Pnt(1.8, 0, 0.5);
  poles(3) = gp_Pnt(1, 0, 1);
  Handle(Geom_BezierCurve) arc = new Geom_BezierCurve(poles);
  BRepBuilderAPI_MakeWire wire(BRepBuilderAPI_MakeEdge(arc).Edge(),
                               segment(gp_Pnt(1, 0, 1), gp_Pnt(1, 0, 0)));
  const TopoDS_Face profile = BRepBuilderAPI_MakeFace(wire.Wire(), true).Face();
  return BRepPrimAPI_MakeRevol(profile, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1))).Shape();
}

// A closed surface of revolution with a pole at each end: a Bezier arc from the axis back to
// the axis, turned about it (a spindle-shaped shell).
TopoDS_Shape revolvedSpindle() {
  TColgp_Array1OfPnt poles(1, 4);
  poles(1) = gp_Pnt(0, 0, 0);
  poles(2) = gp_Pnt(1, 0, 0.2);
  poles(3) = gp_Pnt(1, 0, 1.3);
  poles(4) = gp_Pnt(0, 0, 1.5);
  Handle(Geom_BezierCurve) arc = new Geom_BezierCurve(poles);
  return BRepPrimAPI_MakeRevol(BRepBuilderAPI_MakeEdge(arc).Edge(),
                               gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)))
      .Shape();
}

// An elliptic cylinder: the side is a surface of linear extrusion of an ellipse.
TopoDS_Shape ellipticPrism() {
  const gp_Elips ellipse(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 1.5, 0.75);
  Handle(Geom_Ellipse) curve = new Geom_Ellipse(ellipse);
  BRepBuilderAPI_MakeWire wire(BRepBuilderAPI_MakeEdge(curve).Edge());
  const TopoDS_Face base = BRepBuilderAPI_MakeFace(wire.Wire(), true).Face();
  return BRepPrimAPI_MakePrism(base, gp_Vec(0, 0, 1.2)).Shape();
}

// A bumpy B-spline patch over [0, 2] x [0, 1] (cubic both ways, 4 x 4 poles), z about 1.
Handle(Geom_BSplineSurface) bumpySurface() {
  TColgp_Array2OfPnt poles(1, 4, 1, 4);
  for (int i = 1; i <= 4; ++i)
    for (int j = 1; j <= 4; ++j) {
      const double bump = (i == 2 || i == 3) && (j == 2 || j == 3) ? 0.35 * ((i + j) % 2 ? 1 : -1)
                                                                   : 0.0;
      poles(i, j) = gp_Pnt(2.0 * (i - 1) / 3, (j - 1) / 3.0, 1.0 + bump);
    }
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0;
  knots(2) = 1;
  TColStd_Array1OfInteger mults(1, 2);
  mults(1) = 4;
  mults(2) = 4;
  return new Geom_BSplineSurface(poles, knots, knots, mults, mults, 3, 3);
}

TopoDS_Face bumpyFace() { return BRepBuilderAPI_MakeFace(bumpySurface(), 1e-7).Face(); }

// The bumpy patch swept down by 1: B-spline top and bottom, sides extruded from B-spline edges.
TopoDS_Shape bumpyPrism() { return BRepPrimAPI_MakePrism(bumpyFace(), gp_Vec(0, 0, -1)).Shape(); }

// The bumpy prism with three round holes through it: its top and bottom are B-spline faces
// trimmed by three inner loops each.
TopoDS_Shape bumpyPrismWithHoles() {
  TopoDS_Shape shape = bumpyPrism();
  const double xs[3] = {0.4, 1.0, 1.6};
  for (double x : xs) {
    const TopoDS_Shape hole =
        BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, 0.5, -1), gp_Dir(0, 0, 1)), 0.17, 4).Shape();
    shape = BRepAlgoAPI_Cut(shape, hole).Shape();
  }
  return shape;
}

// A Bezier patch, 3 x 3 poles, saddle-like.
TopoDS_Shape bezierFace() {
  TColgp_Array2OfPnt poles(1, 3, 1, 3);
  for (int i = 1; i <= 3; ++i)
    for (int j = 1; j <= 3; ++j)
      poles(i, j) = gp_Pnt(i - 1.0, j - 1.0, (i == 2) == (j == 2) ? 0.0 : 0.6 * (i - j));
  Handle(Geom_BezierSurface) surface = new Geom_BezierSurface(poles);
  return BRepBuilderAPI_MakeFace(surface, 1e-7).Face();
}

// The bumpy patch offset by 0.15 along its normal.
TopoDS_Shape offsetFace() {
  Handle(Geom_OffsetSurface) surface = new Geom_OffsetSurface(bumpySurface(), 0.15);
  return BRepBuilderAPI_MakeFace(surface, 1e-7).Face();
}

// Loose curves: an ellipse (closed), a cubic B-spline-like Bezier, its offset in the xy plane,
// and a circle trimmed to 3/4 of a turn.
TopoDS_Shape looseCurves() {
  BRep_Builder builder;
  TopoDS_Compound all;
  builder.MakeCompound(all);
  const gp_Elips ellipse(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 2.0, 0.5);
  builder.Add(all, BRepBuilderAPI_MakeEdge(new Geom_Ellipse(ellipse)).Edge());
  TColgp_Array1OfPnt poles(1, 4);
  poles(1) = gp_Pnt(0, 3, 0);
  poles(2) = gp_Pnt(1, 4, 0);
  poles(3) = gp_Pnt(2, 2, 0);
  poles(4) = gp_Pnt(3, 3, 0);
  Handle(Geom_BezierCurve) wave = new Geom_BezierCurve(poles);
  builder.Add(all, BRepBuilderAPI_MakeEdge(wave).Edge());
  builder.Add(all, BRepBuilderAPI_MakeEdge(new Geom_OffsetCurve(wave, 0.2, gp_Dir(0, 0, 1))).Edge());
  Handle(Geom_Circle) circle = new Geom_Circle(gp_Ax2(gp_Pnt(6, 0, 0), gp_Dir(0, 0, 1)), 1.0);
  builder.Add(all, BRepBuilderAPI_MakeEdge(
                       new Geom_TrimmedCurve(circle, 0.0, 1.5 * std::numbers::pi)).Edge());
  return all;
}

double exactLength(const TopoDS_Shape& shape) {
  double length = 0;
  for (TopExp_Explorer e(shape, TopAbs_EDGE); e.More(); e.Next())
    length += GCPnts_AbscissaPoint::Length(BRepAdaptor_Curve(TopoDS::Edge(e.Current())), 1e-10);
  return length;
}

// --- Meshing ----------------------------------------------------------------------------------

struct Case {
  std::string name;
  TopoDS_Shape shape;
  bool solid;
};

// Meshes in 2D with the given options and checks validity and area; returns the mesh.
Mesh surfaceMesh(const Model& model, const Case& c, const MeshOptions& options, double tol) {
  QuietSink log;
  Mesh mesh;
  try {
    generateMesh(model, options, 2, mesh, log);
  } catch (const std::exception& e) {
    ADD_FAILURE() << c.name << ": " << e.what();
    return mesh;
  }
  const MeshCheckReport report = checkMesh(model, mesh);
  EXPECT_TRUE(report.ok()) << c.name << ":\n" << report.summary();
  const double area = exactArea(c.shape);
  EXPECT_NEAR(totalArea(mesh), area, tol * area) << c.name;
  return mesh;
}

std::vector<Case> surfaceCases() {
  return {{"revolved_ring", revolvedRing(), true},
          {"revolved_spindle", revolvedSpindle(), false},
          {"elliptic_prism", ellipticPrism(), true},
          {"bumpy_prism", bumpyPrism(), true},
          {"bumpy_prism_with_holes", bumpyPrismWithHoles(), true},
          {"bezier_face", bezierFace(), false},
          {"offset_face", offsetFace(), false}};
}

TEST(OccSurfaceKinds, ShapesAreOfTheIntendedKinds) {
  EXPECT_TRUE(hasFaceOf<Geom_SurfaceOfRevolution>(revolvedRing()));
  EXPECT_TRUE(hasFaceOf<Geom_SurfaceOfRevolution>(revolvedSpindle()));
  EXPECT_TRUE(hasFaceOf<Geom_SurfaceOfLinearExtrusion>(ellipticPrism()));
  EXPECT_TRUE(hasFaceOf<Geom_BSplineSurface>(bumpyPrism()));
  EXPECT_TRUE(hasFaceOf<Geom_SurfaceOfLinearExtrusion>(bumpyPrism()));
  EXPECT_TRUE(hasFaceOf<Geom_BSplineSurface>(bumpyPrismWithHoles()));
  EXPECT_TRUE(hasFaceOf<Geom_BezierSurface>(bezierFace()));
  EXPECT_TRUE(hasFaceOf<Geom_OffsetSurface>(offsetFace()));
}

// Every 2D algorithm on every kind: a valid mesh whose area is the surface's.
TEST(OccSurfaceKinds, EveryAlgorithmMeshesEveryKind) {
  for (const Case& c : surfaceCases()) {
    const Model model = modelOf(c.shape, c.name);
    for (int algorithm : {6, 5, 1, 2, 8}) {
      SCOPED_TRACE(c.name + ", Mesh.Algorithm " + std::to_string(algorithm));
      MeshOptions options;
      options.sizeMax = 0.08;
      options.algorithm2D = algorithm;
      const Mesh mesh = surfaceMesh(model, c, options, 0.01);
      const double area = exactArea(c.shape);
      const double ideal = area / (std::sqrt(3.0) / 4 * 0.08 * 0.08);
      const double triangles = static_cast<double>(countOf(mesh, 2, ElementType::Triangle3));
      EXPECT_GT(triangles, 0.5 * ideal);
      EXPECT_LT(triangles, 2.0 * ideal);
    }
  }
}

// Algorithm 3 (the initial mesh only: the boundary nodes triangulated in the parameter plane,
// no node inside) cannot follow a curved surface; it either gives a valid mesh or stops with
// the surface named, never writes an inverted triangle (the reference crashes on a sphere).
TEST(OccSurfaceKinds, InitialMeshOnlyIsValidOrRefused) {
  for (const Case& c : surfaceCases()) {
    SCOPED_TRACE(c.name);
    const Model model = modelOf(c.shape, c.name);
    MeshOptions options;
    options.sizeMax = 0.08;
    options.algorithm2D = 3;
    QuietSink log;
    Mesh mesh;
    try {
      generateMesh(model, options, 2, mesh, log);
    } catch (const MeshError& e) {
      EXPECT_EQ(e.entity.dim, 2) << e.what();
      continue;
    }
    const MeshCheckReport report = checkMesh(model, mesh);
    EXPECT_TRUE(report.ok()) << report.summary();
    for (const auto& [tag, surface] : model.surfaces()) {
      const EntityMesh* em = mesh.find({2, tag});
      ASSERT_NE(em, nullptr);
      if (surface.geometry->isPlane()) {
        EXPECT_TRUE(em->nodes.empty()) << "plane " << tag;
      }
    }
  }
}

// Recombined: mostly quadrangles, every element valid, the same area.
TEST(OccSurfaceKinds, RecombinedOnEveryKind) {
  for (const Case& c : surfaceCases()) {
    Model model = modelOf(c.shape, c.name);
    for (const auto& [tag, surface] : model.surfaces())
      model.meshConstraints().recombinedSurfaces[tag] = 45;
    for (int algorithm : {6, 8}) {
      SCOPED_TRACE(c.name + ", recombined, Mesh.Algorithm " + std::to_string(algorithm));
      MeshOptions options;
      options.sizeMax = 0.08;
      options.algorithm2D = algorithm;
      const Mesh mesh = surfaceMesh(model, c, options, 0.01);
      const std::size_t quads = countOf(mesh, 2, ElementType::Quad4);
      const std::size_t triangles = countOf(mesh, 2, ElementType::Triangle3);
      EXPECT_GT(quads, 4 * triangles);
    }
  }
}

// A four-sided B-spline face, transfinite: exactly the grid, quadrangles when recombined.
TEST(OccSurfaceKinds, TransfiniteBSplineFace) {
  const Case c{"bumpy_face", bumpyFace(), false};
  Model model = modelOf(c.shape, c.name);
  ASSERT_EQ(model.surfaces().size(), 1u);
  ASSERT_EQ(model.curves().size(), 4u);
  for (const auto& [tag, curve] : model.curves())
    model.meshConstraints().transfiniteCurves[tag] = TransfiniteCurve{21};
  const int face = model.surfaces().begin()->first;
  model.meshConstraints().transfiniteSurfaces[face] = TransfiniteSurface{};
  Mesh mesh = surfaceMesh(model, c, {}, 0.01);
  EXPECT_EQ(countOf(mesh, 2, ElementType::Triangle3), 2u * 20 * 20);
  EXPECT_EQ(mesh.nodeCount(), 21u * 21);
  model.meshConstraints().recombinedSurfaces[face] = 45;
  mesh = surfaceMesh(model, c, {}, 0.01);
  EXPECT_EQ(countOf(mesh, 2, ElementType::Quad4), 20u * 20);
  EXPECT_EQ(countOf(mesh, 2, ElementType::Triangle3), 0u);
}

// The solids filled with tetrahedra: the volume is the shape's.
TEST(OccSurfaceKinds, SolidsBoundedByEveryKindFillWithTetrahedra) {
  for (const Case& c : surfaceCases()) {
    if (!c.solid) continue;
    SCOPED_TRACE(c.name);
    const Model model = modelOf(c.shape, c.name);
    MeshOptions options;
    options.sizeMax = 0.1;
    QuietSink log;
    Mesh mesh;
    generateMesh(model, options, 3, mesh, log);
    const MeshCheckReport report = checkMesh(model, mesh);
    EXPECT_TRUE(report.ok()) << report.summary();
    const double volume = exactVolume(c.shape);
    EXPECT_NEAR(totalVolume(mesh), volume, 0.01 * volume);
    EXPECT_GT(countOf(mesh, 3, ElementType::Tet4), 1000u);
  }
}

// Sizes far larger than a bend: a slender cylinder (radius 0.02, size 0.1) and a thin elliptic
// tube (tips of radius 0.01). With the sizes asked for, a triangle would wrap round the girth
// or the tip; a few elements per turn keep every one facing out, on the seam too.
TEST(OccSurfaceKinds, SlenderShapesKeepAFewElementsPerTurn) {
  const TopoDS_Shape rod = BRepPrimAPI_MakeCylinder(0.02, 1.0).Shape();
  const gp_Elips ellipse(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 1.0, 0.1);
  const TopoDS_Shape tube =
      BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeEdge(new Geom_Ellipse(ellipse)).Edge(),
                            gp_Vec(0, 0, 1))
          .Shape();
  for (const Case& c : {Case{"slender_rod", rod, true}, Case{"thin_tube", tube, false}}) {
    SCOPED_TRACE(c.name);
    const Model model = modelOf(c.shape, c.name);
    MeshOptions options;
    options.sizeMax = 0.1;
    options.sizeMin = 0.05;  // the bend's bound holds below Mesh.MeshSizeMin too
    const Mesh mesh = surfaceMesh(model, c, options, 0.05);
    EXPECT_GT(countOf(mesh, 2, ElementType::Triangle3), 50u);
    if (!c.solid) continue;
    QuietSink log;
    Mesh volume;
    generateMesh(model, options, 3, volume, log);
    EXPECT_TRUE(checkMesh(model, volume).ok());
    // The end disks are heptagons (Mesh.MinimumCircleNodes = 7), 13% short of the circles.
    const double exact = exactVolume(c.shape);
    EXPECT_NEAR(totalVolume(volume), exact, 0.15 * exact);
  }
}

// A sphere squashed to an ellipsoid (1, 1, 0.5) by a non-uniform scaling is a B-spline surface
// closing on a pole at each end. The curvature there is the ellipsoid's (0.5 / 1 = 0.5 both
// ways), not the blow-up of a derivative that vanishes at the pole.
TEST(OccSurfaceKinds, CurvatureAtAPoleIsTheSurfacesOwn) {
  gp_GTrsf squash;
  squash.SetValue(3, 3, 0.5);
  const TopoDS_Shape ellipsoid =
      BRepBuilderAPI_GTransform(BRepPrimAPI_MakeSphere(1.0).Shape(), squash, true).Shape();
  ASSERT_TRUE(hasFaceOf<Geom_BSplineSurface>(ellipsoid));
  const Model model = modelOf(ellipsoid, "ellipsoid");
  ASSERT_EQ(model.surfaces().size(), 1u);
  const SurfaceGeometry& g = *model.surfaces().begin()->second.geometry;
  const ParamBox box = g.bounds();
  const double u = 0.5 * (box.u.min + box.u.max);
  for (double v : {box.v.min, box.v.max}) {
    const Vec3 p = g.point({u, v});
    ASSERT_NEAR(std::abs(p.z), 0.5, 1e-6);  // a pole
    EXPECT_NEAR(surfaceCurvature(g, {u, v}), 0.5, 0.025);
  }
  // Sized by curvature, the seam from pole to pole is meshed at once (it used to ask for more
  // than a billion segments there).
  MeshOptions options;
  options.sizeFromCurvature = 16;
  QuietSink log;
  Mesh mesh;
  generateMesh(model, options, 2, mesh, log);
  EXPECT_TRUE(checkMesh(model, mesh).ok());
  EXPECT_LT(mesh.nodeCount(), 5000u);
}

// Ellipse, Bezier, offset and trimmed curves: every node on its curve, and the polyline's
// length converging to the curves' as h^2 (chords fall short by about h^2 k^2 / 24).
TEST(OccSurfaceKinds, EveryCurveKindKeepsItsLength) {
  const TopoDS_Shape curves = looseCurves();
  OccFactory occ;
  const std::string path = scratch::path("loose_curves.brep").string();
  BRepTools::Write(curves, path.c_str());
  occ.importShapes(path, true);
  Model model;
  occ.synchronize(model);
  ASSERT_EQ(model.curves().size(), 4u);
  const double exact = exactLength(curves);
  QuietSink log;
  auto shortfall = [&](double h) {
    MeshOptions options;
    options.sizeMax = h;
    Mesh mesh;
    generateMesh(model, options, 1, mesh, log);
    const MeshCheckReport report = checkMesh(model, mesh);
    EXPECT_TRUE(report.ok()) << report.summary();
    EXPECT_NEAR(static_cast<double>(countOf(mesh, 1, ElementType::Line2)), exact / h,
                0.05 * exact / h);
    return exact - totalLength(mesh);
  };
  const double coarse = shortfall(0.05), fine = shortfall(0.0125);
  EXPECT_GT(coarse, 0);
  EXPECT_LT(coarse, 1e-2 * exact);
  EXPECT_GT(fine, 0);
  EXPECT_LT(fine, coarse / 10);  // 16 for h^2

  // Sized by curvature alone (N = 20 elements per radian turned times 2 pi): the ellipse turns
  // a full turn and the trimmed circle three quarters, so about 20 and 15 segments.
  MeshOptions options;
  options.sizeMax = 1.0;
  options.sizeFromCurvature = 20;
  Mesh curved;
  generateMesh(model, options, 1, curved, log);
  EXPECT_TRUE(checkMesh(model, curved).ok());
  for (const auto& [tag, curve] : model.curves()) {
    const std::size_t lines = curved.find({1, tag})->findBlock(ElementType::Line2)->size();
    const bool closed = curve.startPoint == curve.endPoint;
    const Vec3 start = curve.geometry->point(curve.geometry->range().min);
    if (closed) {
      EXPECT_GE(lines, 20u) << "ellipse";
    } else if (start.x > 4) {
      EXPECT_GE(lines, 15u) << "three quarters of a circle";
    }
  }
}

}  // namespace
}  // namespace geomesh
