// The interface every geometry kernel (built-in, OpenCASCADE) offers to scripts and the app.
#pragma once

#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include "kernel/affine_map.h"
#include "kernel/extrusion_motion.h"
#include "kernel/geometry_error.h"
#include "kernel/model.h"
#include "kernel/solid_modeling.h"
#include "kernel/unrolled_geo_hooks.h"

namespace geomesh {

// A geometry kernel: entities are defined one call at a time, as a script states them, and
// synchronize() puts them into the Model. Shapes are (dim, tag) pairs. An operation a factory
// does not offer throws UnsupportedOperation naming it and the factory: that is what the
// defaults below do. The built-in factory (kernel/geo/) implements every operation; the
// OpenCASCADE factory (kernel/occ/) some. Code outside the kernel sees only this interface.
class GeometryFactory {
 public:
  virtual ~GeometryFactory() = default;

  // "Built-in", "OpenCASCADE": how scripts name the factory in SetFactory.
  virtual std::string name() const = 0;
  // The solid modeler's operations (primitives, Booleans, ...), or null when the factory has
  // none (the built-in one).
  virtual SolidModeling* solidModeling() { return nullptr; }

  // Entities. Tags are the script's; reusing one throws GeometryError.
  virtual void addPoint(int tag, Vec3 xyz, double meshSize);
  virtual void addLine(int tag, int startPoint, int endPoint);
  virtual void addCircleArc(int tag, int startPoint, int centerPoint, int endPoint);
  virtual void addEllipseArc(int tag, int startPoint, int centerPoint, int majorAxisPoint,
                             int endPoint);
  virtual void addSpline(int tag, const std::vector<int>& points);
  virtual void addBSpline(int tag, const std::vector<int>& points);
  virtual void addBezier(int tag, const std::vector<int>& points);
  // Circle(tag) = {start, center, end} Plane{nx, ny, nz}: the normal says which way a half
  // circle turns (about it, right-handed); other arcs take the shorter way, as without it.
  virtual void addCircleArcAbout(int tag, int startPoint, int centerPoint, int endPoint,
                                 Vec3 normal);
  // Line(tag) = {p1, p2, p3, ..}: one curve of straight segments through the points.
  virtual void addPolyline(int tag, const std::vector<int>& points);
  // Nurbs(tag) = {points} Knots {knots} Order degree: a B-spline curve of these control points
  // and knots (points.size() + degree + 1 of them, non-decreasing).
  virtual void addNurbs(int tag, const std::vector<int>& points, const std::vector<double>& knots,
                        int degree);
  // Split Curve{tag} Point{..}: the curve becomes the pieces between the given points among
  // its own, each of the curve's kind, with new tags (returned in order along the curve);
  // curve loops and surfaces that used it use the pieces instead.
  virtual std::vector<int> splitCurve(int tag, const std::vector<int>& points);
  // Intersect Curve{..} Surface{s}: a new point where each curve crosses the surface (curves
  // stay whole); returns the new points' tags, curve by curve, along each curve.
  virtual std::vector<int> intersectCurvesWithSurface(const std::vector<int>& curves,
                                                      int surface);
  // How far the loops of plane surface `tag` pass from the plane fitted to them (0 when the
  // surface is not a plane surface of this factory).
  virtual double planeDeviation(int tag) const;
  virtual void addCurveLoop(int tag, std::vector<int> curves);
  virtual void addPlaneSurface(int tag, std::vector<int> curveLoops);
  // A surface filling the curve loop; an OpenCASCADE filling also passes through the points
  // `through` (the built-in kernel ignores them).
  virtual void addFillingSurface(int tag, std::vector<int> curveLoops,
                                 const std::vector<int>& through);
  virtual void addSurfaceLoop(int tag, std::vector<int> surfaces);
  virtual void addVolume(int tag, std::vector<int> surfaceLoops);
  // Box(tag) = {x, y, z, dx, dy, dz}: an axis-aligned box with a corner at `corner` and the
  // opposite one at corner + extent. tag < 0: the next free volume tag. Returns the tag.
  virtual int addBox(int tag, Vec3 corner, Vec3 extent);

  // Physical groups: (dim, tag) -> name and entities.
  virtual void addPhysicalGroup(int dim, int tag, const std::string& name,
                                const std::vector<int>& entities);
  virtual void removeFromPhysicalGroup(int dim, int tag, const std::vector<int>& entities);
  virtual void clearPhysicalGroups();
  virtual const std::map<EntityId, PhysicalGroup>& physicalGroups() const;

  // Mesh constraints recorded on entities: sizes at points, compounds, embedding, periodicity.
  virtual void setMeshSize(const std::vector<int>& points, double size);
  virtual void addCompound(int dim, const std::vector<int>& tags);
  virtual void embed(int dim, const std::vector<int>& tags, int hostDim, int hostTag);
  virtual void setPeriodic(int dim, const std::vector<int>& slaves,
                           const std::vector<int>& masters, const AffineMap& map);
  virtual void setPeriodicByCurves(int slave, const std::vector<int>& slaveCurves, int master,
                                   const std::vector<int>& masterCurves);

  // Operations on shapes: Translate/Rotate/..., Duplicata, Delete, Boundary, Extrude,
  // Coherence.
  virtual void transform(const std::vector<EntityId>& shapes, const AffineMap& map);
  virtual std::vector<EntityId> duplicate(const std::vector<EntityId>& shapes);
  virtual void remove(const std::vector<EntityId>& shapes, bool recursive);
  virtual std::vector<EntityId> boundary(const std::vector<EntityId>& shapes,
                                         bool combined) const;
  virtual std::vector<EntityId> extrude(const std::vector<EntityId>& shapes,
                                        const ExtrusionMotion& motion,
                                        const ExtrusionLayers& layers);
  virtual void coherence();
  // Coherence Point{a, b, ..}: the points after the first become the first, wherever they are
  // used; curves and surfaces made identical by it then merge as in Coherence.
  virtual void coherePoints(const std::vector<int>& points);

  // Queries. maxTag: the largest tag given so far; dim 0..3 for entities, kCurveLoop and
  // kSurfaceLoop for loops; 0 when none.
  enum : int { kCurveLoop = 4, kSurfaceLoop = 5 };
  virtual int maxTag(int kind) const = 0;
  virtual bool contains(EntityId e) const = 0;  // dims 0..3
  bool hasPoint(int tag) const { return contains({0, tag}); }
  virtual std::vector<int> tags(int dim) const = 0;  // ascending
  virtual Vec3 pointCoordinates(int tag) const;
  virtual std::vector<int> pointsOf(const std::vector<EntityId>& shapes) const;  // PointsOf
  virtual BoundingBox boundingBox(EntityId shape) const;
  virtual std::vector<int> entitiesInBox(int dim, const BoundingBox& box) const;

  // Geometry.Tolerance, relative to the model's size.
  virtual void setTolerance(double relativeTolerance);
  virtual double tolerance() const;

  // Adds this factory's entities and physical groups to the model, replacing those of the
  // same tags; the other entities stay (the session clears the model first).
  virtual void synchronize(Model& model) const = 0;
  virtual void clear() = 0;
  // The definitions as a flat .geo script (what `-0` writes).
  virtual void writeUnrolled(std::ostream& out, const UnrolledGeoHooks& hooks) const;

 protected:
  [[noreturn]] void unsupported(const std::string& operation) const;
};

// CombinedBoundary: of the boundaries of several shapes, the entities bounding only one of
// them (those shared by two cancel out), in ascending (dim, tag).
std::vector<EntityId> cancelShared(const std::vector<EntityId>& boundaries);

}  // namespace geomesh
