// GeoFactory: the built-in geometry kernel of .geo scripts, checked one definition at a time.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "kernel/affine_map.h"
#include "kernel/discrete_entities.h"
#include "kernel/extrusion_motion.h"
#include "kernel/geometry_factory.h"
#include "kernel/model.h"

namespace geomesh {

// The built-in geometry kernel (the default factory of .geo scripts). Entities are defined
// one call at a time, as a script states them, and checked immediately (an undefined point or
// curve throws GeometryError naming its tag); synchronize() builds the Model from them.
// As in Gmsh, a tag cannot be redefined: reusing one throws ("Point 1 already exists").
class GeoFactory final : public GeometryFactory, public DiscreteEntities {
 public:
  std::string name() const override { return "Built-in"; }

  void addPoint(int tag, Vec3 xyz, double meshSize) override;
  void addLine(int tag, int startPoint, int endPoint) override;
  // An arc of circle around `centerPoint`, of angle at most pi (Circle(tag) = {start, center,
  // end}). The two ends must be at about the same distance from the center (within 10%, as the
  // built-in kernel allows; the radius then varies along the arc so that it joins both).
  void addCircleArc(int tag, int startPoint, int centerPoint, int endPoint) override;
  // An arc of ellipse (Ellipse(tag) = {start, center, majorAxisPoint, end}), less than half a
  // turn; see makeEllipseArc.
  void addEllipseArc(int tag, int startPoint, int centerPoint, int majorAxisPoint,
                     int endPoint) override;
  // Spline(tag) = {..}: an interpolating spline through the points (closed when the first
  // point is also the last).
  void addSpline(int tag, const std::vector<int>& points) override;
  // BSpline(tag) = {..}: a uniform cubic B-spline of these control points (clamped at its
  // ends; periodic when the first point is also the last).
  void addBSpline(int tag, const std::vector<int>& points) override;
  // Bezier(tag) = {..}: a Bezier curve of these control points.
  void addBezier(int tag, const std::vector<int>& points) override;
  void addCircleArcAbout(int tag, int startPoint, int centerPoint, int endPoint,
                         Vec3 normal) override;
  void addPolyline(int tag, const std::vector<int>& points) override;
  void addNurbs(int tag, const std::vector<int>& points, const std::vector<double>& knots,
                int degree) override;
  // Splits Spline, BSpline, Bezier and polyline curves (kernel/geo/geo_split.cpp).
  std::vector<int> splitCurve(int tag, const std::vector<int>& points) override;
  // Crossings found by sampling each curve's signed distance to the surface and bisecting
  // where it changes sign (kernel/geo/geo_split.cpp).
  std::vector<int> intersectCurvesWithSurface(const std::vector<int>& curves,
                                              int surface) override;
  // The loops of a plane surface need not be exactly plane: the surface lies on the plane
  // fitted to them by least squares, and this is the largest distance of the loops from it.
  double planeDeviation(int tag) const override;
  // Beyond this fraction of the outer loop's size, the loops of a plane surface are not plane.
  static constexpr double kPlaneDeviationLimit = 0.05;
  // A closed chain of curves; signed tags (negative: reversed). Curves given in any order
  // and orientation are chained as the built-in kernel does; a loop that does not close
  // throws, naming the gap.
  void addCurveLoop(int tag, std::vector<int> curves) override;
  // First loop: outer boundary; others: holes.
  void addPlaneSurface(int tag, std::vector<int> curveLoops) override;
  void addSurfaceLoop(int tag, std::vector<int> surfaces) override;
  void addVolume(int tag, std::vector<int> surfaceLoops) override;
  // Creates the group or, if (dim, tag) exists, appends to it. An empty name keeps the old one.
  void addPhysicalGroup(int dim, int tag, const std::string& name,
                        const std::vector<int>& entities) override;

  // A surface of a merged mesh file (`file`): it has no geometry, only the file's triangles,
  // and lies in `box`; `loops` are its boundary curves (signed, first the outer one), none
  // for a surface as merged. Surface loops and volumes may use it; it cannot be moved, copied
  // or extruded. The unrolled script merges the file again.
  void addDiscreteSurface(int tag, const BoundingBox& box, const std::string& file,
                          std::vector<std::vector<int>> loops) override;
  // A corner of a merged triangulation, and a curve along its edges through `trace` (the
  // triangulation's vertices, from the start point's to the end point's; the same point at
  // both ends of a closed curve). Both cannot be moved, copied or extruded either.
  void addDiscretePoint(int tag, Vec3 xyz) override;
  void addDiscreteCurve(int tag, int startPoint, int endPoint, std::vector<Vec3> trace) override;
  // CreateGeometry: the discrete curve gets the polyline through its trace as its geometry and
  // the discrete surface `geometry` (a map of its triangles to the plane); both are then
  // meshed anew like any other entity.
  void setDiscreteCurveGeometry(int tag) override;
  void setDiscreteSurfaceGeometry(int tag,
                                  std::shared_ptr<const SurfaceGeometry> geometry) override;
  bool isDiscrete(EntityId e) const override;
  // The file each discrete surface comes from.
  const std::map<int, std::string>& discreteFiles() const { return discreteFiles_; }
  // Statements that changed the merged triangulations since they were merged
  // (ClassifySurfaces, CreateGeometry...), in order, as the unrolled script repeats them.
  void noteDiscreteStatement(std::string statement) override {
    discreteStatements_.push_back(std::move(statement));
  }
  const std::vector<std::string>& discreteStatements() const { return discreteStatements_; }

  // Surface(tag) = {loop}: a surface filling a loop of 3 or 4 curves by transfinite
  // interpolation of its sides.
  void addFillingSurface(int tag, std::vector<int> curveLoops,
                         const std::vector<int>& through) override;
  // Compound Curve{..} / Compound Surface{..}: meshed as one; recorded on each entity.
  void addCompound(int dim, const std::vector<int>& tags) override;
  // Physical X(tag) -= {..}: removes entities from a group (the group goes when emptied).
  void removeFromPhysicalGroup(int dim, int tag, const std::vector<int>& entities) override;
  // MeshSize{points} = size; (Characteristic Length): the prescribed mesh size at the points.
  void setMeshSize(const std::vector<int>& points, double size) override;
  // Delete Physicals;
  void clearPhysicalGroups() override { physicals_.clear(); }

  bool contains(EntityId e) const override;  // dims 0..3
  Vec3 pointCoordinates(int tag) const override;  // throws if undefined
  // Largest tag given so far; dim 0..3 for entities, 4 for curve loops, 5 for surface loops.
  // Deleting the entity of the largest tag lowers it by one; Coherence resets it to the
  // largest tag in use. 0 when none.
  int maxTag(int kind) const override;
  std::vector<int> tags(int dim) const override;
  const std::map<EntityId, PhysicalGroup>& physicalGroups() const override { return physicals_; }

  // Transformations (kernel/geo/geo_transform.cpp). Shapes are (dim, tag) pairs; a negative
  // tag is accepted (orientation is ignored). Every point of the shapes, down to the control
  // points of their curves, moves once; then coincident entities are merged (Coherence).
  void transform(const std::vector<EntityId>& shapes, const AffineMap& map) override;
  // Duplicata{..}: copies with new tags, numbered as the built-in kernel of Gmsh numbers
  // them (a surface: the surface first, then its curves with their points; a negative curve
  // tag copies the reversed curve). Returns the copies' (dim, tag) in the order of `shapes`.
  std::vector<EntityId> duplicate(const std::vector<EntityId>& shapes) override;
  // Delete{..}: removes the shapes that nothing else uses (silently keeps the others);
  // recursive: then also their boundaries, down to points, when no longer used.
  void remove(const std::vector<EntityId>& shapes, bool recursive) override;
  // Boundary{..}: the boundary of each shape, one dimension lower, as Gmsh gives it: a
  // curve's ends in its direction (reversed for a negative tag); a surface's curves and a
  // volume's surfaces in loop order, as positive tags. Combined: entities shared by two of
  // the shapes cancel out; the others come in ascending tags.
  std::vector<EntityId> boundary(const std::vector<EntityId>& shapes, bool combined) const override;
  // PointsOf{..}: every point of the shapes, once each, in order of appearance.
  std::vector<int> pointsOf(const std::vector<EntityId>& shapes) const override;
  BoundingBox boundingBox(EntityId shape) const override;
  // Point/Curve/Surface/Volume In BoundingBox{..}: entities of `dim` inside the box (to the
  // geometric tolerance), ascending tags.
  std::vector<int> entitiesInBox(int dim, const BoundingBox& box) const override;
  // Coherence: merges points closer than the tolerance (the lowest tag stays), then the
  // curves and surfaces that have become identical.
  void coherence() override;
  void coherePoints(const std::vector<int>& points) override;

  // Extrude{..}{shapes} (kernel/geo/geo_extrude.cpp): for each shape in turn, its top (its
  // image at the end of the motion), the entity swept (one dimension higher), then the
  // lateral entities (for a curve: swept by its end then its start point, as the swept
  // surface's loop runs; for a surface: one per boundary curve, in loop order). Tags are
  // given as the built-in kernel of Gmsh gives them, merging coincident entities after
  // each shape. Layers are recorded on every swept entity. A point on the rotation axis
  // sweeps nothing (the surface of a curve touching the axis has three sides; a curve on
  // the axis sweeps no surface).
  std::vector<EntityId> extrude(const std::vector<EntityId>& shapes, const ExtrusionMotion& motion,
                                const ExtrusionLayers& layers) override;

  // Point{..} In Curve/Surface/Volume{t}; Curve{..} In Surface/Volume{t}; Surface{..} In
  // Volume{t} (kernel/geo/geo_embed.cpp).
  void embed(int dim, const std::vector<int>& tags, int hostDim, int hostTag) override;
  // Periodic Curve/Surface{slaves} = {masters} + the transform taking masters to slaves.
  void setPeriodic(int dim, const std::vector<int>& slaves, const std::vector<int>& masters,
                   const AffineMap& map) override;
  // Periodic Surface slave {curves} = master {curves}: the older form, without a transform. The
  // transform is the rigid motion that takes each master curve's end points onto those of the
  // slave curve given at the same place (negative tags: reversed curves).
  void setPeriodicByCurves(int slave, const std::vector<int>& slaveCurves, int master,
                           const std::vector<int>& masterCurves) override;

  // Geometry.Tolerance: coincident points and non-planar plane surfaces are detected
  // relative to this fraction of the model's size (the diagonal of its bounding box).
  void setTolerance(double relativeTolerance) override { tolerance_ = relativeTolerance; }
  double tolerance() const override { return tolerance_; }
  // Geometry.AutoCoherence (default on): transformations and extrusions end with Coherence.
  void setAutoCoherence(bool on) { autoCoherence_ = on; }
  // Geometry.ExtrudeReturnLateralEntities (default on): extrusions list their lateral
  // entities after the swept one.
  void setExtrudeReturnsLateralEntities(bool on) { returnLaterals_ = on; }
  // Geometry.ExtrudeSplinePoints (default 5): a twisted point sweeps a spline through this
  // many steps (at least 1).
  void setExtrudeSplineSteps(int steps) { twistSteps_ = steps < 1 ? 1 : steps; }

  // Adds this factory's entities and physical groups to the model (see GeometryFactory).
  // Physical groups keep only the entities the model holds: synchronize other factories first.
  void synchronize(Model& model) const override;
  void clear() override;
  // kernel/geo/geo_unrolled_writer.cpp
  void writeUnrolled(std::ostream& out, const UnrolledGeoHooks& hooks) const override;

  // The definitions, as the unrolled .geo writer lists them.
  using CurveKind = geomesh::CurveKind;  // all but Other
  enum class SurfaceKind { Plane, Filling, Swept, Discrete };
  struct Curve {
    int tag;
    CurveKind kind = CurveKind::Line;
    // Points defining the shape: both ends for a line, {start, center, end} for a circle arc,
    // {start, center, major-axis point, end} for an ellipse arc, else the control points.
    std::vector<int> points = {};
    std::optional<ExtrusionRecord> extrusion = std::nullopt;
    std::vector<int> compound = {};
    std::optional<Periodicity> periodic = std::nullopt;
    std::vector<int> embeddedPoints = {};
    std::vector<double> knots = {};  // a Nurbs curve's (then a BSpline of this degree)
    int degree = 0;
    std::optional<Vec3> normal = std::nullopt;  // a circle arc's, from Plane{..}
    // A discrete curve's vertices (kind Other; see addDiscreteCurve), and whether
    // CreateGeometry made it a geometric curve.
    std::vector<Vec3> trace = {};
    bool withGeometry = false;
    int start() const { return points.front(); }
    int end() const { return points.back(); }
  };
  struct Surface {
    int tag;
    SurfaceKind kind = SurfaceKind::Plane;
    // Curve loops as chained signed curves: the first is the outer boundary, the others are
    // holes, each run against the direction it was given in. loopTags: the tags they were
    // given by (the loops of generated surfaces have none).
    std::vector<std::vector<int>> loops = {};
    std::vector<int> loopTags = {};
    std::optional<ExtrusionRecord> extrusion = std::nullopt;
    std::optional<ExtrusionMotion> sweep = std::nullopt;  // Swept: the motion of the source
    std::vector<int> compound = {};
    std::optional<Periodicity> periodic = std::nullopt;
    std::vector<int> embeddedPoints = {};
    std::vector<int> embeddedCurves = {};
    // A discrete surface's, from CreateGeometry.
    std::shared_ptr<const SurfaceGeometry> discreteGeometry = nullptr;
  };
  struct Volume {
    int tag;
    std::vector<std::vector<int>> shells = {};  // signed surfaces; first outer
    std::vector<int> shellTags = {};
    std::optional<ExtrusionRecord> extrusion = std::nullopt;
    std::vector<int> embeddedPoints = {};
    std::vector<int> embeddedCurves = {};
    std::vector<int> embeddedSurfaces = {};
  };
  const std::map<int, ModelPoint>& points() const { return points_; }
  const std::map<int, Curve>& curves() const { return curves_; }
  const std::map<int, std::vector<int>>& curveLoops() const { return curveLoops_; }
  const std::map<int, Surface>& surfaces() const { return surfaces_; }
  const std::map<int, std::vector<int>>& surfaceLoops() const { return surfaceLoops_; }
  const std::map<int, Volume>& volumes() const { return volumes_; }

 private:
  std::map<int, ModelPoint> points_;
  std::map<int, Curve> curves_;
  std::map<int, std::vector<int>> curveLoops_;
  std::map<int, Surface> surfaces_;
  std::map<int, std::vector<int>> surfaceLoops_;
  std::map<int, Volume> volumes_;
  std::map<EntityId, PhysicalGroup> physicals_;
  std::map<int, BoundingBox> discreteBoxes_;  // discrete surface -> the box of its nodes
  std::map<int, std::string> discreteFiles_;  // discrete surface -> the file it comes from
  std::set<int> discretePoints_;
  std::vector<std::string> discreteStatements_;
  double tolerance_ = 1e-8;
  bool autoCoherence_ = true;
  bool returnLaterals_ = true;
  int twistSteps_ = 5;
  std::array<int, 6> highWater_{};  // maxTag() of each kind
  // Replacements made by Coherence since lastMerges_ was last cleared, per dimension (signed).
  std::array<std::map<int, int>, 4> lastMerges_;
  BoundingBox bounds_;  // of the points, kept as they are added
  // The points a boundary layer (an extrusion along normals) made: they stand where their
  // source does, so Coherence merges them only with the points made from the same source
  // point for the same index, never with the source. {source point, index} per point.
  std::map<int, std::pair<int, int>> layerPoints_;
  int layerCopyIndex_ = -1;  // while a boundary layer copies points: its index

  double absoluteTolerance() const;
  void noteTag(int kind, int tag);
  int newPointTag();
  int newRegionTag(int kind);  // curves, surfaces: shared numbering with loops and physicals
  int newVolumeTag();
  std::array<int, 2> curveEnds(int signedCurve) const;
  std::shared_ptr<const CurveGeometry> curveGeometry(const Curve& c) const;
  std::shared_ptr<const SurfaceGeometry> surfaceGeometry(const Surface& s) const;
  void addControlPointCurve(int tag, CurveKind kind, const std::vector<int>& points,
                            const char* what);
  std::vector<std::vector<int>> surfaceLoopsOf(int tag, const std::vector<int>& curveLoops,
                                               const char* what) const;
  // Points along a chain of signed curves: each curve's start, and inner points of curved ones.
  std::vector<Vec3> loopSamples(const std::vector<int>& curves) const;
  std::vector<int> loopCurves(int signedLoop) const;
  // The plane surface on the plane fitted to the loops, and how far the loops pass from it.
  std::pair<std::shared_ptr<const SurfaceGeometry>, double> fitPlaneSurface(
      int tag, const std::vector<std::vector<int>>& loops) const;
  void replaceCurveInLoops(int tag, const std::vector<int>& pieces);
  void checkShellClosed(int volume, const std::vector<int>& loops,
                        const std::vector<int>& surfaces) const;

  // geo_transform.cpp
  void requireShape(EntityId shape, const char* operation) const;
  // requireShape, and the shape holds no discrete surface (whose triangles cannot follow).
  void requireGeometric(EntityId shape, const char* operation) const;
  void collectPoints(EntityId shape, std::vector<int>& out) const;
  void checkArcsStayCircular(const std::map<int, Vec3>& image) const;
  std::vector<int> pointsUnder(const std::vector<EntityId>& shapes) const;  // sorted, unique
  int copyPoint(int tag);
  int copyCurve(int signedTag);
  static std::vector<int> reversedPoints(const Curve& c);
  int copySurface(int tag);
  int copyVolume(int tag);
  bool isUsed(EntityId e) const;
  void eraseEntity(EntityId e);
  // geo_coherence.cpp
  void mergePoints();
  void mergeCurves();
  void mergeSurfaces();
  void replaceTags(int dim, const std::map<int, int>& signedReplacement);
  void resetHighWater();
  // geo_extrude.cpp
  void mergeLayerPoints(const std::map<int, int>& merged);
  std::vector<EntityId> extrudePoint(int tag, const ExtrusionMotion& motion,
                                     const ExtrusionLayers& layers);
  std::vector<EntityId> extrudeCurve(int tag, const ExtrusionMotion& motion,
                                     const ExtrusionLayers& layers);
  std::vector<EntityId> extrudeSurface(int tag, const ExtrusionMotion& motion,
                                       const ExtrusionLayers& layers);
  void moveCopy(EntityId copy, const ExtrusionMotion& motion);
};

}  // namespace geomesh
