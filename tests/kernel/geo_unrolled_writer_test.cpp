// Tests of the .geo_unrolled writer: entities, sizes, loops, physicals and mesh constraints.
#include "kernel/geo/geo_unrolled_writer.h"

#include <gtest/gtest.h>

#include <sstream>

#include "kernel/geo/geo_factory.h"
#include "tests/kernel/kernel_test_helpers.h"

namespace geomesh {
namespace {

TEST(GeoUnrolledWriter, WritesEntitiesSizesLoopsAndPhysicals) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 0.1);
  geo.addPoint(2, {1, 0, 0}, 0.2);
  geo.addPoint(3, {1, 1, 0}, 0.1);
  geo.addPoint(4, {0, 1, 0}, 0);
  geo.addPoint(5, {0.2, 0.2, 0}, 0.05);
  geo.addPoint(6, {0.4, 0.2, 0}, 0.05);
  geo.addPoint(7, {0.4, 0.4, 0}, 0.05);
  for (int i = 1; i <= 4; ++i) geo.addLine(i, i, i % 4 + 1);
  geo.addLine(5, 5, 6);
  geo.addLine(6, 6, 7);
  geo.addLine(7, 7, 5);
  geo.addBezier(8, {1, 6, 7});
  geo.addCurveLoop(1, {1, 2, 3, 4});
  geo.addCurveLoop(2, {5, 6, 7});
  geo.addPlaneSurface(1, {1, 2});
  geo.addFillingSurface(2, {2}, {});
  geo.addPhysicalGroup(2, 5, "plate", {1});
  geo.addPhysicalGroup(1, 3, "", {1, 2});
  std::ostringstream out;
  writeUnrolledGeo(geo, out);
  EXPECT_EQ(out.str(),
            "cl__1 = 0.1;\ncl__2 = 0.2;\ncl__3 = 1e+22;\ncl__4 = 0.05;\n"
            "Point(1) = {0, 0, 0, cl__1};\nPoint(2) = {1, 0, 0, cl__2};\n"
            "Point(3) = {1, 1, 0, cl__1};\nPoint(4) = {0, 1, 0, cl__3};\n"
            "Point(5) = {0.2, 0.2, 0, cl__4};\nPoint(6) = {0.4, 0.2, 0, cl__4};\n"
            "Point(7) = {0.4, 0.4, 0, cl__4};\n"
            "Line(1) = {1, 2};\nLine(2) = {2, 3};\nLine(3) = {3, 4};\nLine(4) = {4, 1};\n"
            "Line(5) = {5, 6};\nLine(6) = {6, 7};\nLine(7) = {7, 5};\nBezier(8) = {1, 6, 7};\n"
            "Curve Loop(1) = {1, 2, 3, 4, -7, -6, -5};\nPlane Surface(1) = {1};\n"
            "Curve Loop(2) = {5, 6, 7};\nSurface(2) = {2};\n"
            "Physical Curve(3) = {1, 2};\nPhysical Surface(\"plate\") = {1};\n");
}

TEST(GeoUnrolledWriter, HooksAddStatementsAfterEntities) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 0);
  geo.addPoint(2, {1, 0, 0}, 0);
  geo.addLine(1, 1, 2);
  UnrolledGeoHooks hooks;
  hooks.afterEntity = [](EntityId e, std::ostream& out) {
    if (e.dim == 1) out << "Transfinite Curve {" << e.tag << "} = 10 Using Progression 1;\n";
  };
  hooks.atEnd = [](std::ostream& out) { out << "Mesh.Algorithm = 6;\n"; };
  std::ostringstream out;
  writeUnrolledGeo(geo, out, hooks);
  EXPECT_EQ(out.str(),
            "cl__1 = 1e+22;\nPoint(1) = {0, 0, 0, cl__1};\nPoint(2) = {1, 0, 0, cl__1};\n"
            "Line(1) = {1, 2};\nTransfinite Curve {1} = 10 Using Progression 1;\n"
            "Mesh.Algorithm = 6;\n");
}

TEST(GeoUnrolledWriter, WritesTransfiniteAndRecombineConstraints) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 0);
  geo.addPoint(2, {1, 0, 0}, 0);
  geo.addPoint(3, {1, 1, 0}, 0);
  for (int i = 1; i <= 3; ++i) geo.addLine(i, i, i % 3 + 1);
  geo.addCurveLoop(1, {1, 2, 3});
  geo.addPlaneSurface(1, {1});
  MeshConstraints constraints;
  constraints.transfiniteCurves[1] = {30, TransfiniteCurve::Law::Progression, 1.2, true};
  constraints.transfiniteCurves[2] = {5, TransfiniteCurve::Law::Bump, 0.25, false};
  constraints.transfiniteSurfaces[1] = {{1, 2, 3}, TransfiniteSurface::Arrangement::Right};
  constraints.recombinedSurfaces[1] = 45;
  std::ostringstream out;
  writeUnrolledGeo(geo, out, meshConstraintHooks(constraints));
  const std::string text = out.str();
  EXPECT_NE(text.find("Line(1) = {1, 2};\nTransfinite Curve {-1} = 30 Using Progression 1.2;\n"
                      "Line(2) = {2, 3};\nTransfinite Curve {2} = 5 Using Bump 0.25;\n"
                      "Line(3)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("Plane Surface(1) = {1};\nTransfinite Surface {1} = {1,2,3};\n"
                      "Recombine Surface {1};\n"),
            std::string::npos)
      << text;
}

// The unit square extruded along z, as the reference writes it after the same script.
TEST(GeoUnrolledWriter, WritesAnExtrudedCubeAsTheReferenceDoes) {
  GeoFactory geo;
  addUnitSquareSurface(geo);
  geo.extrude({{2, 1}}, ExtrusionMotion::translate({0, 0, 1}), {});
  std::ostringstream out;
  writeUnrolledGeo(geo, out);
  EXPECT_EQ(out.str(),
            "cl__1 = 1;\n"
            "Point(1) = {0, 0, 0, cl__1};\n"
            "Point(2) = {1, 0, 0, cl__1};\n"
            "Point(3) = {1, 1, 0, cl__1};\n"
            "Point(4) = {0, 1, 0, cl__1};\n"
            "Point(5) = {0, 0, 1, cl__1};\n"
            "Point(6) = {1, 0, 1, cl__1};\n"
            "Point(10) = {1, 1, 1, cl__1};\n"
            "Point(14) = {0, 1, 1, cl__1};\n"
            "Line(1) = {1, 2};\n"
            "Line(2) = {2, 3};\n"
            "Line(3) = {3, 4};\n"
            "Line(4) = {4, 1};\n"
            "Line(6) = {5, 6};\n"
            "Line(7) = {6, 10};\n"
            "Line(8) = {10, 14};\n"
            "Line(9) = {14, 5};\n"
            "Line(11) = {1, 5};\n"
            "Line(12) = {2, 6};\n"
            "Line(16) = {3, 10};\n"
            "Line(20) = {4, 14};\n"
            "Curve Loop(1) = {1, 2, 3, 4};\n"
            "Plane Surface(1) = {1};\n"
            "Curve Loop(13) = {1, 12, -6, -11};\n"
            "Surface(13) = {13};\n"
            "Curve Loop(17) = {2, 16, -7, -12};\n"
            "Surface(17) = {17};\n"
            "Curve Loop(21) = {3, 20, -8, -16};\n"
            "Surface(21) = {21};\n"
            "Curve Loop(25) = {4, 11, -9, -20};\n"
            "Surface(25) = {25};\n"
            "Curve Loop(26) = {6, 7, 8, 9};\n"
            "Plane Surface(26) = {26};\n"
            "Surface Loop(1) = {1, 26, 13, 17, 21, 25};\n"
            "Volume(1) = {1};\n");
}

}  // namespace
}  // namespace geomesh
