// OccCurve and OccSurface: CurveGeometry and SurfaceGeometry over OpenCASCADE edges and faces.
#include "kernel/occ/occ_geometry.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_Surface.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>

#include <map>
#include <mutex>

namespace geomesh {

namespace {

Vec3 toVec3(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }

CurveKind curveKind(GeomAbs_CurveType type) {
  switch (type) {
    case GeomAbs_Line: return CurveKind::Line;
    case GeomAbs_Circle: return CurveKind::CircleArc;
    case GeomAbs_Ellipse: return CurveKind::EllipseArc;
    case GeomAbs_BSplineCurve: return CurveKind::BSpline;
    case GeomAbs_BezierCurve: return CurveKind::Bezier;
    default: return CurveKind::Other;
  }
}

SurfaceKind surfaceKind(GeomAbs_SurfaceType type) {
  switch (type) {
    case GeomAbs_Plane: return SurfaceKind::Plane;
    case GeomAbs_Cylinder: return SurfaceKind::Cylinder;
    case GeomAbs_Cone: return SurfaceKind::Cone;
    case GeomAbs_Sphere: return SurfaceKind::Sphere;
    case GeomAbs_Torus: return SurfaceKind::Torus;
    case GeomAbs_BSplineSurface: return SurfaceKind::BSpline;
    case GeomAbs_BezierSurface: return SurfaceKind::Bezier;
    default: return SurfaceKind::Other;
  }
}

class OccCurve final : public CurveGeometry {
 public:
  explicit OccCurve(const TopoDS_Edge& edge) : curve_(edge) {}

  Interval range() const override { return {curve_.FirstParameter(), curve_.LastParameter()}; }
  Vec3 point(double t) const override { return toVec3(curve_.Value(t).XYZ()); }
  Vec3 firstDerivative(double t) const override {
    gp_Pnt p;
    gp_Vec d1;
    curve_.D1(t, p, d1);
    return toVec3(d1.XYZ());
  }
  Vec3 secondDerivative(double t) const override {
    gp_Pnt p;
    gp_Vec d1, d2;
    curve_.D2(t, p, d1, d2);
    return toVec3(d2.XYZ());
  }
  // Circles and ellipses are parametrized by their angle: the default arcAngle() holds.
  CurveKind kind() const override { return curveKind(curve_.GetType()); }

 private:
  BRepAdaptor_Curve curve_;
};

// An edge collapsed to a point (BRep_Tool::Degenerated): its vertex over the edge's range.
class DegenerateOccCurve final : public CurveGeometry {
 public:
  explicit DegenerateOccCurve(const TopoDS_Edge& edge) {
    BRep_Tool::Range(edge, range_.min, range_.max);
    point_ = toVec3(BRep_Tool::Pnt(TopExp::FirstVertex(edge)).XYZ());
  }

  Interval range() const override { return range_; }
  Vec3 point(double) const override { return point_; }
  Vec3 firstDerivative(double) const override { return {}; }
  Vec3 secondDerivative(double) const override { return {}; }
  bool isDegenerate() const override { return true; }

 private:
  Interval range_;
  Vec3 point_;
};

// The curves on a face of its edges, by signed curve tag.
using CurvesOnFace = std::map<int, Geom2dAdaptor_Curve>;

CurvesOnFace curvesOnFace(const TopoDS_Face& face, const OccEdgeTag& edgeTag) {
  CurvesOnFace curves;
  if (!edgeTag) return curves;
  for (TopExp_Explorer it(face, TopAbs_EDGE); it.More(); it.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(it.Current());
    try {
      Standard_Real first = 0, last = 0;
      const Handle(Geom2d_Curve) curve = BRep_Tool::CurveOnSurface(edge, face, first, last);
      if (!curve.IsNull()) curves.try_emplace(edgeTag(edge), curve, first, last);
    } catch (const Standard_Failure&) {
      // no curve on the face: the mesher projects this edge's nodes instead
    }
  }
  return curves;
}

class OccSurface final : public SurfaceGeometry {
 public:
  OccSurface(const TopoDS_Face& face, const OccEdgeTag& edgeTag)
      : surface_(face), geom_(BRep_Tool::Surface(face)), curves_(curvesOnFace(face, edgeTag)) {
    BRepTools::UVBounds(face, bounds_.u.min, bounds_.u.max, bounds_.v.min, bounds_.v.max);
  }

  ParamBox bounds() const override { return bounds_; }
  Vec3 point(Vec2 uv) const override { return toVec3(surface_.Value(uv.u, uv.v).XYZ()); }
  SurfaceDerivatives firstDerivatives(Vec2 uv) const override {
    gp_Pnt p;
    gp_Vec du, dv;
    surface_.D1(uv.u, uv.v, p, du, dv);
    return {toVec3(du.XYZ()), toVec3(dv.XYZ())};
  }
  Vec2 project(Vec3 p) const override;
  SurfaceKind kind() const override { return surfaceKind(surface_.GetType()); }
  // An edge used once answers for both signs; a seam, used in both directions, has a curve
  // on the face for each.
  std::optional<Vec2> curveParameters(int signedCurve, double t) const override {
    auto it = curves_.find(signedCurve);
    if (it == curves_.end()) it = curves_.find(-signedCurve);
    if (it == curves_.end()) return std::nullopt;
    try {
      const gp_Pnt2d p = it->second.Value(t);
      return Vec2{p.X(), p.Y()};
    } catch (const Standard_Failure&) {
      return std::nullopt;
    }
  }

 private:
  BRepAdaptor_Surface surface_;
  Handle(Geom_Surface) geom_;  // with the face's location applied
  ParamBox bounds_;
  CurvesOnFace curves_;
  // The projector samples the surface on a grid when it is set up: done once per surface, not
  // once per projected point. Checks and meshers project many points on the same surface.
  mutable std::mutex projectorMutex_;
  mutable GeomAPI_ProjectPointOnSurf projector_;
  mutable bool projectorReady_ = false;
};

// The closest point of the underlying surface, searched within the face's parameter bounds;
// when the search fails (a degenerate input) the bounds' centre is returned.
Vec2 OccSurface::project(Vec3 p) const {
  const Vec2 centre{(bounds_.u.min + bounds_.u.max) / 2, (bounds_.v.min + bounds_.v.max) / 2};
  try {
    const std::lock_guard<std::mutex> lock(projectorMutex_);
    if (!projectorReady_) {
      projector_.Init(geom_, bounds_.u.min, bounds_.u.max, bounds_.v.min, bounds_.v.max);
      projectorReady_ = true;
    }
    projector_.Perform(gp_Pnt(p.x, p.y, p.z));
    if (!projector_.IsDone() || projector_.NbPoints() == 0) return centre;
    Standard_Real u = 0, v = 0;
    projector_.LowerDistanceParameters(u, v);
    return {u, v};
  } catch (const Standard_Failure&) {  // a degenerate surface: as when no point is found
    return centre;
  }
}

}  // namespace

std::shared_ptr<const CurveGeometry> makeOccCurve(const TopoDS_Edge& edge) {
  if (BRep_Tool::Degenerated(edge)) return std::make_shared<DegenerateOccCurve>(edge);
  return std::make_shared<OccCurve>(edge);
}

std::shared_ptr<const SurfaceGeometry> makeOccSurface(const TopoDS_Face& face,
                                                      const OccEdgeTag& edgeTag) {
  return std::make_shared<OccSurface>(face, edgeTag);
}

}  // namespace geomesh
