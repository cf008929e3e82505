#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "kernel/model.h"

namespace geomesh {

// The built-in geometry kernel (the default factory of .geo scripts). Entities are defined
// one call at a time, as a script states them, and checked immediately (an undefined point or
// curve throws GeometryError naming its tag); synchronize() builds the Model from them.
// As in Gmsh, a tag cannot be redefined: reusing one throws ("Point 1 already exists").
class GeoFactory {
 public:
  void addPoint(int tag, Vec3 xyz, double meshSize);
  void addLine(int tag, int startPoint, int endPoint);
  // An arc of circle around `centerPoint`, of angle at most pi (Circle(tag) = {start, center,
  // end}). The two ends must be at about the same distance from the center (within 10%, as the
  // built-in kernel allows; the radius then varies along the arc so that it joins both).
  void addCircleArc(int tag, int startPoint, int centerPoint, int endPoint);
  // An arc of ellipse (Ellipse(tag) = {start, center, majorAxisPoint, end}), less than half a
  // turn; see makeEllipseArc.
  void addEllipseArc(int tag, int startPoint, int centerPoint, int majorAxisPoint, int endPoint);
  // Spline(tag) = {..}: an interpolating spline through the points (closed when the first
  // point is also the last).
  void addSpline(int tag, const std::vector<int>& points);
  // BSpline(tag) = {..}: a uniform cubic B-spline of these control points (clamped at its
  // ends; periodic when the first point is also the last).
  void addBSpline(int tag, const std::vector<int>& points);
  // Bezier(tag) = {..}: a Bezier curve of these control points.
  void addBezier(int tag, const std::vector<int>& points);
  // A closed chain of curves; signed tags (negative: reversed). Curves given in any order
  // and orientation are chained as the built-in kernel does; a loop that does not close
  // throws, naming the gap.
  void addCurveLoop(int tag, std::vector<int> curves);
  // First loop: outer boundary; others: holes.
  void addPlaneSurface(int tag, std::vector<int> curveLoops);
  void addSurfaceLoop(int tag, std::vector<int> surfaces);
  void addVolume(int tag, std::vector<int> surfaceLoops);
  // Creates the group or, if (dim, tag) exists, appends to it. An empty name keeps the old one.
  void addPhysicalGroup(int dim, int tag, const std::string& name,
                        const std::vector<int>& entities);

  bool hasPoint(int tag) const;
  Vec3 pointCoordinates(int tag) const;  // throws if undefined
  // Largest tag in use; dim 0..3 for entities, 4 for curve loops, 5 for surface loops.
  // 0 when none.
  int maxTag(int kind) const;
  enum : int { kCurveLoop = 4, kSurfaceLoop = 5 };

  // Geometry.Tolerance: coincident points and non-planar plane surfaces are detected
  // relative to this fraction of the model's size (the diagonal of its bounding box).
  void setTolerance(double relativeTolerance) { tolerance_ = relativeTolerance; }
  double tolerance() const { return tolerance_; }

  // Replaces the model's geometry with this factory's entities.
  void synchronize(Model& model) const;
  void clear();

 private:
  enum class CurveKind { Line, CircleArc, EllipseArc, Spline, BSpline, Bezier };
  struct Curve {
    int tag;
    CurveKind kind = CurveKind::Line;
    // Points defining the shape: both ends for a line, {start, center, end} for a circle arc,
    // {start, center, major-axis point, end} for an ellipse arc, else the control points.
    std::vector<int> points;
    int start() const { return points.front(); }
    int end() const { return points.back(); }
  };
  struct Surface {
    int tag;
    std::vector<int> loops;
    std::shared_ptr<const SurfaceGeometry> geometry;
  };
  struct Volume {
    int tag;
    std::vector<int> shells;
  };
  std::map<int, ModelPoint> points_;
  std::map<int, Curve> curves_;
  std::map<int, std::vector<int>> curveLoops_;
  std::map<int, Surface> surfaces_;
  std::map<int, std::vector<int>> surfaceLoops_;
  std::map<int, Volume> volumes_;
  std::map<EntityId, PhysicalGroup> physicals_;
  double tolerance_ = 1e-8;
  BoundingBox bounds_;  // of the points, kept as they are added

  double absoluteTolerance() const;
  std::array<int, 2> curveEnds(int signedCurve) const;
  std::shared_ptr<const CurveGeometry> curveGeometry(const Curve& c) const;
  void addControlPointCurve(int tag, CurveKind kind, const std::vector<int>& points,
                            const char* what);
  // Points along a loop, in its direction: each curve's start, and inner points of arcs.
  std::vector<Vec3> loopSamples(int signedLoop) const;
  std::vector<int> loopCurves(int signedLoop) const;
  std::shared_ptr<const SurfaceGeometry> fitPlaneSurface(int tag,
                                                       const std::vector<int>& loops) const;
  void checkShellClosed(int tag, const std::vector<int>& surfaces) const;
};

}  // namespace geomesh
