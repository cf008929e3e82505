// The OpenCASCADE factory's primitives: sphere, cylinder, cone, torus, wedge, rectangle, disk.
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepPrimAPI_MakeWedge.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <GC_MakeSegment.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>
#include <gp_Elips.hxx>

#include <cmath>
#include <numbers>
#include <string>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"
#include "kernel/occ/occ_shapes.h"

namespace geomesh {

namespace {

gp_Pnt toPnt(Vec3 p) { return {p.x, p.y, p.z}; }

void require(bool condition, const std::string& what, const std::string& reason) {
  if (!condition) throw GeometryError(what + ": " + reason);
}

bool positive(double x) { return std::isfinite(x) && x > 0; }

// An axis through `origin` along `direction`; throws when the direction has no length.
gp_Ax2 axis(Vec3 origin, Vec3 direction, const std::string& what) {
  const double length = std::sqrt(dot(direction, direction));
  require(positive(length), what, "its axis has zero length");
  return gp_Ax2(toPnt(origin), gp_Dir(direction.x, direction.y, direction.z));
}

void requireOpening(double angle, const std::string& what) {
  require(std::isfinite(angle) && angle > 0 && angle <= 2 * std::numbers::pi + 1e-12, what,
          "its angle must be in (0, 2 Pi]");
}

}  // namespace

int OccFactory::addSphere(int tag, Vec3 center, double radius, double angle1, double angle2,
                          double angle3) {
  tag = primitiveTag(3, tag, "Sphere");
  const std::string what = "Sphere " + std::to_string(tag);
  require(positive(radius), what, "its radius must be positive");
  requireOpening(angle3, what);
  require(angle1 < angle2, what, "its first polar angle must be below the second");
  const TopoDS_Shape solid = guarded(what, [&] {
    BRepPrimAPI_MakeSphere maker(gp_Ax2(toPnt(center), gp::DZ()), radius, angle1, angle2, angle3);
    maker.Build();
    return maker.Shape();
  });
  shapes_->bindTree(3, tag, solid);
  return tag;
}

int OccFactory::addCylinder(int tag, Vec3 base, Vec3 axisVector, double radius, double angle) {
  tag = primitiveTag(3, tag, "Cylinder");
  const std::string what = "Cylinder " + std::to_string(tag);
  require(positive(radius), what, "its radius must be positive");
  requireOpening(angle, what);
  const gp_Ax2 ax = axis(base, axisVector, what);
  const double height = std::sqrt(dot(axisVector, axisVector));
  const TopoDS_Shape solid = guarded(what, [&] {
    BRepPrimAPI_MakeCylinder maker(ax, radius, height, angle);
    maker.Build();
    return maker.Shape();
  });
  shapes_->bindTree(3, tag, solid);
  return tag;
}

int OccFactory::addCone(int tag, Vec3 base, Vec3 axisVector, double radius1, double radius2,
                        double angle) {
  tag = primitiveTag(3, tag, "Cone");
  const std::string what = "Cone " + std::to_string(tag);
  require(radius1 >= 0 && radius2 >= 0 && (radius1 > 0 || radius2 > 0) &&
              std::isfinite(radius1) && std::isfinite(radius2),
          what, "its radii must not be negative, nor both zero");
  requireOpening(angle, what);
  const gp_Ax2 ax = axis(base, axisVector, what);
  const double height = std::sqrt(dot(axisVector, axisVector));
  const TopoDS_Shape solid = guarded(what, [&] {
    BRepPrimAPI_MakeCone maker(ax, radius1, radius2, height, angle);
    maker.Build();
    return maker.Shape();
  });
  shapes_->bindTree(3, tag, solid);
  return tag;
}

int OccFactory::addTorus(int tag, Vec3 center, double radius1, double radius2, double angle) {
  tag = primitiveTag(3, tag, "Torus");
  const std::string what = "Torus " + std::to_string(tag);
  require(positive(radius1) && positive(radius2), what, "its radii must be positive");
  requireOpening(angle, what);
  const TopoDS_Shape solid = guarded(what, [&] {
    BRepPrimAPI_MakeTorus maker(gp_Ax2(toPnt(center), gp::DZ()), radius1, radius2, angle);
    maker.Build();
    return maker.Shape();
  });
  shapes_->bindTree(3, tag, solid);
  return tag;
}

int OccFactory::addWedge(int tag, Vec3 corner, Vec3 extent, double topX) {
  tag = primitiveTag(3, tag, "Wedge");
  const std::string what = "Wedge " + std::to_string(tag);
  require(positive(extent.x) && positive(extent.y) && positive(extent.z), what,
          "its extents must be positive");
  require(std::isfinite(topX) && topX >= 0, what, "its top length must not be negative");
  const TopoDS_Shape solid = guarded(what, [&] {
    BRepPrimAPI_MakeWedge maker(gp_Ax2(toPnt(corner), gp::DZ(), gp::DX()), extent.x, extent.y,
                                extent.z, topX);
    maker.Build();
    return maker.Shape();
  });
  shapes_->bindTree(3, tag, solid);
  return tag;
}

namespace {

TopoDS_Edge segment(const gp_Pnt& a, const gp_Pnt& b) {
  return BRepBuilderAPI_MakeEdge(GC_MakeSegment(a, b).Value()).Edge();
}

TopoDS_Edge quarterArc(const gp_Pnt& center, double r, double startAngle) {
  gp_Circ circle(gp_Ax2(center, gp::DZ(), gp::DX()), r);
  return BRepBuilderAPI_MakeEdge(
             GC_MakeArcOfCircle(circle, startAngle, startAngle + std::numbers::pi / 2, true)
                 .Value())
      .Edge();
}

// The rectangle's outline counter-clockwise from its corner (x, y): four sides, with a quarter
// circle after each side when the corners are rounded.
TopoDS_Wire rectangleWire(Vec3 c, double dx, double dy, double r) {
  BRepBuilderAPI_MakeWire wire;
  const double x0 = c.x, y0 = c.y, x1 = c.x + dx, y1 = c.y + dy, z = c.z;
  if (r <= 0) {
    const gp_Pnt p1(x0, y0, z), p2(x1, y0, z), p3(x1, y1, z), p4(x0, y1, z);
    wire.Add(segment(p1, p2));
    wire.Add(segment(p2, p3));
    wire.Add(segment(p3, p4));
    wire.Add(segment(p4, p1));
    return wire.Wire();
  }
  const double h = std::numbers::pi / 2;
  wire.Add(segment({x0 + r, y0, z}, {x1 - r, y0, z}));
  wire.Add(quarterArc({x1 - r, y0 + r, z}, r, -h));
  wire.Add(segment({x1, y0 + r, z}, {x1, y1 - r, z}));
  wire.Add(quarterArc({x1 - r, y1 - r, z}, r, 0));
  wire.Add(segment({x1 - r, y1, z}, {x0 + r, y1, z}));
  wire.Add(quarterArc({x0 + r, y1 - r, z}, r, h));
  wire.Add(segment({x0, y1 - r, z}, {x0, y0 + r, z}));
  wire.Add(quarterArc({x0 + r, y0 + r, z}, r, 2 * h));
  return wire.Wire();
}

}  // namespace

int OccFactory::addRectangle(int tag, Vec3 corner, double dx, double dy, double roundedRadius) {
  tag = primitiveTag(2, tag, "Rectangle");
  const std::string what = "Rectangle " + std::to_string(tag);
  require(std::isfinite(dx) && std::isfinite(dy) && dx != 0 && dy != 0, what,
          "its sides must not be zero");
  if (dx < 0) corner.x += dx, dx = -dx;
  if (dy < 0) corner.y += dy, dy = -dy;
  require(std::isfinite(roundedRadius) && roundedRadius >= 0 &&
              2 * roundedRadius <= std::min(dx, dy),
          what, "its corner radius must be between 0 and half its shorter side");
  const TopoDS_Shape face = guarded(what, [&] {
    BRepBuilderAPI_MakeFace maker(rectangleWire(corner, dx, dy, roundedRadius), true);
    return maker.Face();
  });
  shapes_->bindTree(2, tag, face);
  return tag;
}

int OccFactory::addDisk(int tag, Vec3 center, double rx, double ry) {
  tag = primitiveTag(2, tag, "Disk");
  const std::string what = "Disk " + std::to_string(tag);
  require(positive(rx) && positive(ry), what, "its radii must be positive");
  require(ry <= rx, what, "its radius along x must not be smaller than the one along y");
  const TopoDS_Shape face = guarded(what, [&] {
    const gp_Ax2 ax(toPnt(center), gp::DZ(), gp::DX());
    const TopoDS_Edge edge = rx == ry ? BRepBuilderAPI_MakeEdge(gp_Circ(ax, rx)).Edge()
                                      : BRepBuilderAPI_MakeEdge(gp_Elips(ax, rx, ry)).Edge();
    BRepBuilderAPI_MakeFace maker(BRepBuilderAPI_MakeWire(edge).Wire(), true);
    return maker.Face();
  });
  shapes_->bindTree(2, tag, face);
  return tag;
}

}  // namespace geomesh
