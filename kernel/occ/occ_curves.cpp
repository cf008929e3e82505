// The OpenCASCADE factory's points, curves and curve loops.
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <ElCLib.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Ellipse.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Precision.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"
#include "kernel/occ/occ_shapes.h"

namespace geomesh {

namespace {

gp_Pnt toPnt(Vec3 p) { return {p.x, p.y, p.z}; }

TopoDS_Vertex vertexOf(const OccShapes& s, int tag) { return TopoDS::Vertex(s.find(0, tag)); }

Vec3 coordinates(const TopoDS_Vertex& v) {
  const gp_Pnt p = BRep_Tool::Pnt(v);
  return {p.X(), p.Y(), p.Z()};
}

// The edge of `curve` between the vertices `first` and `last`; throws when they are not on it.
TopoDS_Edge edgeBetween(const Handle(Geom_Curve) & curve, const TopoDS_Vertex& first,
                        const TopoDS_Vertex& last, const std::string& what) {
  BRepBuilderAPI_MakeEdge maker(curve, first, last);
  if (!maker.IsDone())
    throw GeometryError(what + ": its end points are not on the curve it defines");
  return maker.Edge();
}

}  // namespace

void OccFactory::addPoint(int tag, Vec3 xyz, double meshSize) {
  tag = primitiveTag(0, tag, "Point");
  if (!std::isfinite(xyz.x) || !std::isfinite(xyz.y) || !std::isfinite(xyz.z))
    throw GeometryError(entityName(0, tag) + ": its coordinates are not finite");
  const TopoDS_Shape vertex = BRepBuilderAPI_MakeVertex(toPnt(xyz)).Vertex();
  shapes_->bindTree(0, tag, vertex);
  if (meshSize > 0) meshSizes_[tag] = meshSize;
}

void OccFactory::setMeshSize(const std::vector<int>& points, double size) {
  for (int p : points) {
    shapes_->find(0, std::abs(p));
    meshSizes_[std::abs(p)] = size;
  }
}

void OccFactory::addLine(int tag, int startPoint, int endPoint) {
  tag = primitiveTag(1, tag, "Line");
  const std::string what = "Line " + std::to_string(tag);
  if (startPoint == endPoint) throw GeometryError(what + " starts and ends at the same point");
  const TopoDS_Vertex a = vertexOf(*shapes_, startPoint), b = vertexOf(*shapes_, endPoint);
  if (distance(coordinates(a), coordinates(b)) == 0)
    throw GeometryError(what + ": its end points coincide");
  const TopoDS_Shape edge = guarded(what, [&] { return BRepBuilderAPI_MakeEdge(a, b).Edge(); });
  shapes_->bindTree(1, tag, edge);
}

void OccFactory::addCircleArc(int tag, int startPoint, int centerPoint, int endPoint) {
  tag = primitiveTag(1, tag, "Circle");
  const std::string what = "Circle " + std::to_string(tag);
  const TopoDS_Vertex a = vertexOf(*shapes_, startPoint), b = vertexOf(*shapes_, endPoint);
  const Vec3 c = pointCoordinates(centerPoint);
  const Vec3 u = coordinates(a) - c, v = coordinates(b) - c;
  Vec3 normal = cross(u, v);
  const double radius = norm(u);
  if (!(radius > 0)) throw GeometryError(what + ": its start point is its center");
  // As in the reference, only ends exactly opposite (a cross product that vanishes, not one
  // that is merely small, as Sin(Pi) leaves it) make a half circle of undefined plane. The
  // reference draws it in the plane z = constant of its center, clockwise seen from +z, and
  // fails when its ends are not in that plane.
  if (!(norm(normal) > std::numeric_limits<double>::min())) {
    if (std::abs(u.z) > Precision::Confusion())
      throw GeometryError(what +
                          ": its ends are opposite on a diameter that leaves the plane "
                          "z = constant of its center, so its plane is undefined");
    normal = {0, 0, -1};
  }
  const TopoDS_Shape edge = guarded(what, [&] {
    // Parametrized as in the reference: the circle's x axis opposite to the one OpenCASCADE
    // picks for the normal, the arc from its start's angle. A filling samples its loop at
    // parameters, and the way its plate faces (so the order in which its curves are listed)
    // can hang on the rounding of those samples.
    const gp_Dir axisNormal(normal.x, normal.y, normal.z);
    const gp_Dir xAxis = gp_Ax2(toPnt(c), axisNormal).XDirection().Reversed();
    Handle(Geom_Circle) circle = new Geom_Circle(gp_Ax2(toPnt(c), axisNormal, xAxis), radius);
    const double first = ElCLib::Parameter(circle->Circ(), toPnt(c + u));
    double last = ElCLib::Parameter(circle->Circ(), toPnt(c + v));
    while (last <= first) last += 2 * std::numbers::pi;
    return edgeBetween(new Geom_TrimmedCurve(circle, first, last), a, b, what);
  });
  shapes_->bindTree(1, tag, edge);
}

// The ellipse has its major axis along `majorAxisPoint`; its radii are those for which both
// end points lie on it.
void OccFactory::addEllipseArc(int tag, int startPoint, int centerPoint, int majorAxisPoint,
                               int endPoint) {
  tag = primitiveTag(1, tag, "Ellipse");
  const std::string what = "Ellipse " + std::to_string(tag);
  const TopoDS_Vertex a = vertexOf(*shapes_, startPoint), b = vertexOf(*shapes_, endPoint);
  const Vec3 c = pointCoordinates(centerPoint);
  const Vec3 major = pointCoordinates(majorAxisPoint) - c;
  const Vec3 u = coordinates(a) - c, v = coordinates(b) - c;
  Vec3 normal = cross(u, v);
  if (!(norm(normal) > 0)) normal = cross(major, u);
  if (!(norm(major) > 0) || !(norm(normal) > 0))
    throw GeometryError(what + ": its points are aligned; the arc's plane is undefined");
  const Vec3 xDir = normalized(major), yDir = normalized(cross(normalized(normal), xDir));
  // x^2 p + y^2 q = 1 at both ends, with p = 1/a^2, q = 1/b^2.
  const double x1 = dot(u, xDir), y1 = dot(u, yDir), x2 = dot(v, xDir), y2 = dot(v, yDir);
  const double det = x1 * x1 * y2 * y2 - x2 * x2 * y1 * y1;
  double p = 0, q = 0;
  if (std::abs(det) > 1e-14 * std::pow(norm(u) * norm(v), 2)) {
    p = (y2 * y2 - y1 * y1) / det;
    q = (x1 * x1 - x2 * x2) / det;
  } else if (std::abs(y1) < 1e-12 * norm(u)) {
    p = 1 / (x1 * x1);
    q = (1 - x2 * x2 * p) / (y2 * y2);
  } else {
    p = 1 / (x2 * x2);
    q = (1 - x1 * x1 * p) / (y1 * y1);
  }
  if (!(p > 0) || !(q > 0) || !std::isfinite(p) || !std::isfinite(q))
    throw GeometryError(what + ": no ellipse with this major axis passes through both ends");
  double ra = 1 / std::sqrt(p), rb = 1 / std::sqrt(q);
  const TopoDS_Shape edge = guarded(what, [&] {
    // OpenCASCADE wants the larger radius first, along the axis' x direction.
    const Vec3 axisX = ra >= rb ? xDir : yDir;
    if (ra < rb) std::swap(ra, rb);
    const gp_Ax2 axis(toPnt(c), gp_Dir(normal.x, normal.y, normal.z),
                      gp_Dir(axisX.x, axisX.y, axisX.z));
    Handle(Geom_Ellipse) ellipse = new Geom_Ellipse(axis, ra, rb);
    const double t1 = ElCLib::Parameter(ellipse->Elips(), toPnt(u + c));
    double t2 = ElCLib::Parameter(ellipse->Elips(), toPnt(v + c));
    while (t2 <= t1) t2 += 2 * std::numbers::pi;
    return edgeBetween(new Geom_TrimmedCurve(ellipse, t1, t2), a, b, what);
  });
  shapes_->bindTree(1, tag, edge);
}

namespace {

// A whole curve (no angles) or its arc between two angles, in the plane z = center.z.
TopoDS_Edge conicEdge(const Handle(Geom_Curve) & conic, const std::vector<double>& angles,
                      const std::string& what) {
  if (angles.empty()) return BRepBuilderAPI_MakeEdge(conic).Edge();
  if (angles.size() != 2 || !(angles[1] > angles[0]) ||
      angles[1] - angles[0] > 2 * std::numbers::pi + 1e-12)
    throw GeometryError(what + ": its angles must increase by at most 2 Pi");
  if (angles[1] - angles[0] >= 2 * std::numbers::pi - 1e-12)
    return BRepBuilderAPI_MakeEdge(conic).Edge();
  return BRepBuilderAPI_MakeEdge(new Geom_TrimmedCurve(conic, angles[0], angles[1])).Edge();
}

}  // namespace

int OccFactory::addCircle(int tag, Vec3 center, double radius, const std::vector<double>& angles) {
  tag = primitiveTag(1, tag, "Circle");
  const std::string what = "Circle " + std::to_string(tag);
  if (!(radius > 0) || !std::isfinite(radius))
    throw GeometryError(what + ": its radius must be positive");
  const TopoDS_Shape edge = guarded(what, [&] {
    Handle(Geom_Circle) circle = new Geom_Circle(gp_Ax2(toPnt(center), gp::DZ(), gp::DX()), radius);
    return conicEdge(circle, angles, what);
  });
  shapes_->bindTree(1, tag, edge);
  return tag;
}

int OccFactory::addEllipse(int tag, Vec3 center, double rx, double ry,
                           const std::vector<double>& angles) {
  tag = primitiveTag(1, tag, "Ellipse");
  const std::string what = "Ellipse " + std::to_string(tag);
  if (!(rx > 0) || !(ry > 0) || !std::isfinite(rx) || !std::isfinite(ry))
    throw GeometryError(what + ": its radii must be positive");
  if (ry > rx) throw GeometryError(what + ": its radius along x must not be smaller than along y");
  const TopoDS_Shape edge = guarded(what, [&] {
    const gp_Ax2 axis(toPnt(center), gp::DZ(), gp::DX());
    Handle(Geom_Curve) conic = rx == ry ? Handle(Geom_Curve)(new Geom_Circle(axis, rx))
                                        : Handle(Geom_Curve)(new Geom_Ellipse(axis, rx, ry));
    return conicEdge(conic, angles, what);
  });
  shapes_->bindTree(1, tag, edge);
  return tag;
}

// Wire(tag) = {curves}: an open or closed chain of curves, for pipes and lofts.
void OccFactory::addWire(int tag, const std::vector<int>& curves) {
  addChain(tag, curves, false);
}

namespace {

TColgp_Array1OfPnt poles(const OccFactory& f, const std::vector<int>& points) {
  TColgp_Array1OfPnt out(1, static_cast<int>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    out.SetValue(static_cast<int>(i) + 1, toPnt(f.pointCoordinates(points[i])));
  return out;
}

void requireCount(const std::vector<int>& points, std::size_t minimum, const std::string& what) {
  if (points.size() < minimum)
    throw GeometryError(what + " needs at least " + std::to_string(minimum) + " points");
}

// Uniform knots, clamped at both ends: the curve starts at its first pole and ends at its last.
Handle(Geom_BSplineCurve) clampedBSpline(const TColgp_Array1OfPnt& p, int degree) {
  const int knots = p.Length() - degree + 1;
  TColStd_Array1OfReal k(1, knots);
  TColStd_Array1OfInteger m(1, knots);
  for (int i = 1; i <= knots; ++i) {
    k.SetValue(i, i - 1);
    m.SetValue(i, i == 1 || i == knots ? degree + 1 : 1);
  }
  return new Geom_BSplineCurve(p, k, m, degree);
}

// Uniform periodic knots over the distinct poles (the last one repeats the first): at
// parameter 0 the curve is near its second pole, not at its first.
Handle(Geom_BSplineCurve) periodicBSpline(const TColgp_Array1OfPnt& all, int degree) {
  TColgp_Array1OfPnt p(1, all.Length() - 1);
  for (int i = 1; i < all.Length(); ++i) p.SetValue(i, all.Value(i));
  const int knots = p.Length() + 1;
  TColStd_Array1OfReal k(1, knots);
  TColStd_Array1OfInteger m(1, knots);
  for (int i = 1; i <= knots; ++i) {
    k.SetValue(i, i - 1);
    m.SetValue(i, 1);
  }
  return new Geom_BSplineCurve(p, k, m, degree, true);
}

}  // namespace

void OccFactory::addSpline(int tag, const std::vector<int>& points) {
  tag = primitiveTag(1, tag, "Spline");
  const std::string what = "Spline " + std::to_string(tag);
  requireCount(points, 2, what);
  const bool closed = points.front() == points.back();
  const TopoDS_Vertex a = vertexOf(*shapes_, points.front()), b = vertexOf(*shapes_, points.back());
  const TopoDS_Shape edge = guarded(what, [&] {
    const TColgp_Array1OfPnt all = poles(*this, points);
    const int n = closed ? all.Length() - 1 : all.Length();
    Handle(TColgp_HArray1OfPnt) through = new TColgp_HArray1OfPnt(1, n);
    for (int i = 1; i <= n; ++i) through->SetValue(i, all.Value(i));
    GeomAPI_Interpolate interpolation(through, closed, 1e-9);
    interpolation.Perform();
    if (!interpolation.IsDone())
      throw GeometryError(what + ": no spline passes through these points (repeated points?)");
    return edgeBetween(interpolation.Curve(), a, b, what);
  });
  shapes_->bindTree(1, tag, edge);
}

void OccFactory::addBSpline(int tag, const std::vector<int>& points) {
  tag = primitiveTag(1, tag, "BSpline");
  const std::string what = "BSpline " + std::to_string(tag);
  requireCount(points, 2, what);
  // A closed control polygon (its first point repeated last) makes a periodic curve, as in the
  // reference. That curve does not pass through its points: it gets a vertex of its own where
  // its parameter starts (the next free point tag), and the repeated point stays apart.
  const bool closed = points.front() == points.back() && points.size() > 2;
  const TopoDS_Vertex a = vertexOf(*shapes_, points.front()), b = vertexOf(*shapes_, points.back());
  const TopoDS_Shape edge = guarded(what, [&] {
    const TColgp_Array1OfPnt p = poles(*this, points);
    const int degree = std::min(3, p.Length() - 1);
    if (closed) return TopoDS_Edge(BRepBuilderAPI_MakeEdge(periodicBSpline(p, degree)).Edge());
    return edgeBetween(clampedBSpline(p, degree), a, b, what);
  });
  shapes_->bindTree(1, tag, edge);
  // The reference gives the curve's own vertex the mesh size the repeated point has now.
  const auto size = meshSizes_.find(points.front());
  if (closed && size != meshSizes_.end())
    meshSizes_[shapes_->tagOf(0, TopExp::FirstVertex(TopoDS::Edge(edge)))] = size->second;
}

void OccFactory::addBezier(int tag, const std::vector<int>& points) {
  tag = primitiveTag(1, tag, "Bezier");
  const std::string what = "Bezier " + std::to_string(tag);
  requireCount(points, 2, what);
  // Refused as the reference refuses it, so that a script that relies on one fails here too.
  if (points.front() == points.back())
    throw GeometryError(what +
                        " starts and ends at the same point; closed Bezier curves are "
                        "not supported");
  const TopoDS_Vertex a = vertexOf(*shapes_, points.front()), b = vertexOf(*shapes_, points.back());
  const TopoDS_Shape edge = guarded(what, [&] {
    Handle(Geom_BezierCurve) curve = new Geom_BezierCurve(poles(*this, points));
    return edgeBetween(curve, a, b, what);
  });
  shapes_->bindTree(1, tag, edge);
}

namespace {

// The wire run the other way: its edges stored last to first, each turned. Reversing only the
// wire's orientation would leave its edges stored from the first, which is where the listing
// of a face's loop starts.
TopoDS_Wire reversedAsAWhole(const TopoDS_Wire& wire) {
  std::vector<TopoDS_Shape> edges;
  for (TopoDS_Iterator it(wire, false, false); it.More(); it.Next()) edges.push_back(it.Value());
  BRep_Builder builder;
  TopoDS_Wire reversed;
  builder.MakeWire(reversed);
  for (auto it = edges.rbegin(); it != edges.rend(); ++it) builder.Add(reversed, it->Reversed());
  reversed.Closed(wire.Closed());
  return TopoDS::Wire(reversed.Oriented(wire.Orientation()));
}

}  // namespace

// Curves in any order and orientation; OpenCASCADE chains them into a loop that runs the way
// its first curve goes. A negative first curve turns it round, as in the reference, where a
// plane surface bounded by it then faces the other way. A loop that does not close is refused.
void OccFactory::addCurveLoop(int tag, std::vector<int> curves) { addChain(tag, curves, true); }

void OccFactory::addChain(int tag, const std::vector<int>& curves, bool closed) {
  if (tag < 0) tag = maxTag(kCurveLoop) + 1;
  const std::string what = (closed ? "Curve Loop " : "Wire ") + std::to_string(tag);
  if (shapes_->wires.contains(tag)) throw GeometryError(what + " already exists");
  if (curves.empty()) throw GeometryError(what + " has no curve");
  const TopoDS_Wire wire = guarded(what, [&] {
    BRepBuilderAPI_MakeWire maker;
    for (int c : curves) {
      maker.Add(TopoDS::Edge(shapes_->find(1, std::abs(c))));
      if (maker.Error() != BRepBuilderAPI_WireDone)
        throw GeometryError(what + ": curve " + std::to_string(std::abs(c)) +
                            " does not connect to the curves before it");
    }
    return maker.Wire();
  });
  if (closed && !BRep_Tool::IsClosed(wire)) throw GeometryError(what + " is not closed");
  shapes_->wires[tag] = closed && curves.front() < 0 ? reversedAsAWhole(wire) : wire;
}

}  // namespace geomesh
