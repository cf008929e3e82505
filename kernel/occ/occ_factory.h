// OccFactory: the OpenCASCADE kernel behind a plain interface (SetFactory("OpenCASCADE")).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "kernel/affine_map.h"
#include "kernel/extrusion_motion.h"
#include "kernel/geometry_factory.h"
#include "kernel/model.h"
#include "kernel/solid_modeling.h"

namespace geomesh {

struct OccShapes;  // the shapes and their tags (kernel/occ/occ_shapes.h)

// The OpenCASCADE geometry kernel (SetFactory("OpenCASCADE") in scripts). Shapes are built
// one call at a time; synchronize() exports them, with every vertex, edge, face and solid, to
// the Model with OpenCASCADE-backed geometry. OpenCASCADE itself stays behind this interface.
// Tags follow Gmsh's OpenCASCADE kernel: a shape's sub-shapes not known yet get the next free
// tags of their dimensions, depth first; tag < 0 asks for the next free tag. Failures throw
// GeometryError naming the entity and the reason; OpenCASCADE's exceptions never escape.
// Not offered (handed to the built-in factory): physical groups and Geometry.Tolerance (kept
// by the built-in factory).
class OccFactory final : public GeometryFactory, public SolidModeling {
 public:
  OccFactory();
  ~OccFactory();
  OccFactory(OccFactory&&) noexcept;
  OccFactory& operator=(OccFactory&&) noexcept;

  std::string name() const override { return "OpenCASCADE"; }
  SolidModeling* solidModeling() override { return this; }
  bool owns(EntityId e) const override { return contains({e.dim, e.tag < 0 ? -e.tag : e.tag}); }

  // Elementary entities (kernel/occ/occ_curves.cpp, occ_surfaces.cpp), as the built-in
  // factory takes them. Curves join the vertices of their points; loops are wires.
  void addPoint(int tag, Vec3 xyz, double meshSize) override;
  void addLine(int tag, int startPoint, int endPoint) override;
  void addCircleArc(int tag, int startPoint, int centerPoint, int endPoint) override;
  void addEllipseArc(int tag, int startPoint, int centerPoint, int majorAxisPoint,
                     int endPoint) override;
  void addSpline(int tag, const std::vector<int>& points) override;   // interpolating
  void addBSpline(int tag, const std::vector<int>& points) override;  // cubic, clamped
  void addBezier(int tag, const std::vector<int>& points) override;
  void addCurveLoop(int tag, std::vector<int> curves) override;
  // Circle(tag) = {x, y, z, r <, angle1, angle2>}, Ellipse(tag) = {x, y, z, rx, ry <, ..>}:
  // whole curves or arcs in the plane z, from the x axis. Return the tag.
  int addCircle(int tag, Vec3 center, double radius, const std::vector<double>& angles) override;
  int addEllipse(int tag, Vec3 center, double rx, double ry,
                 const std::vector<double>& angles) override;
  // Wire(tag) = {curves}: a chain of curves, closed or not (tags shared with curve loops).
  void addWire(int tag, const std::vector<int>& curves) override;
  // First loop outer, others holes.
  void addPlaneSurface(int tag, std::vector<int> curveLoops) override;
  void addFillingSurface(int tag, std::vector<int> curveLoops,
                         const std::vector<int>& through) override;
  void addCurveFilling(int tag, int curveLoop, bool bezier) override;
  void addSurfaceLoop(int tag, std::vector<int> surfaces) override;
  void addVolume(int tag, std::vector<int> surfaceLoops) override;
  // MeshSize{points} = size: the prescribed mesh size at the points.
  void setMeshSize(const std::vector<int>& points, double size) override;

  // Primitives (kernel/occ/occ_primitives.cpp). Each returns its tag.
  // An axis-aligned box with a corner at `corner` and the opposite corner at corner + extent
  // (extents may be negative, not zero). Its 8 points, 12 curves and 6 surfaces get the next
  // free tags of their dimensions.
  int addBox(int tag, Vec3 corner, Vec3 extent) override;
  // Sphere{xc, yc, zc, r, polar angle min, polar angle max, azimuthal opening}.
  int addSphere(int tag, Vec3 center, double radius, double angle1 = -1.5707963267948966,
                double angle2 = 1.5707963267948966, double angle3 = 6.283185307179586) override;
  // Cylinder{x, y, z, dx, dy, dz, r, angle}: base centre, axis (its length is the height).
  int addCylinder(int tag, Vec3 base, Vec3 axis, double radius,
                  double angle = 6.283185307179586) override;
  // Cone{x, y, z, dx, dy, dz, r1, r2, angle}: r1 at the base, r2 at the top (either may be 0).
  int addCone(int tag, Vec3 base, Vec3 axis, double radius1, double radius2,
              double angle = 6.283185307179586) override;
  // Torus{x, y, z, r1, r2, angle}: around the z axis.
  int addTorus(int tag, Vec3 center, double radius1, double radius2,
               double angle = 6.283185307179586) override;
  // Wedge{x, y, z, dx, dy, dz, ltx}: a right-angled wedge, its top `ltx` long along x.
  int addWedge(int tag, Vec3 corner, Vec3 extent, double topX = 0) override;
  // Rectangle{x, y, z, dx, dy, r}: in the plane z, corners rounded with radius r.
  int addRectangle(int tag, Vec3 corner, double dx, double dy, double roundedRadius = 0) override;
  // Disk{xc, yc, zc, rx, ry}: an elliptic disk in the plane z (rx >= ry).
  int addDisk(int tag, Vec3 center, double rx, double ry) override;

  // Booleans (kernel/occ/occ_booleans.cpp) on (dim, tag) shapes of any dimension. The result
  // lists the entities of the result, in OpenCASCADE's order; tags follow Gmsh: an input left
  // untouched keeps its tags; a deleted input turned into one shape gives it its tag; a
  // deleted tool of a cut, an intersection or a union that left no piece of its own keeps the
  // tags of its faces (or curves) kept whole; the other shapes of the result get new tags,
  // those of the shapes that took an input's tag last. Deleted inputs go, with their
  // sub-shapes that nothing else uses. With tag >= 0 (or Geometry.OCCBooleanPreserveNumbering
  // off) the result is numbered anew: every deleted input goes, then the result is bound like
  // a new shape (its one entity of the highest dimension under `tag`).
  std::vector<EntityId> boolean(BooleanOperation operation, const std::vector<EntityId>& objects,
                                const std::vector<EntityId>& tools, bool deleteObjects,
                                bool deleteTools, int tag = -1) override;
  // Coherence: the entities of the highest dimension present, fragmented together.
  void coherence() override;
  void setBooleanOptions(const BooleanOptions& options) override { booleanOptions_ = options; }
  const std::vector<Replacement>& lastReplacements() const override { return replacements_; }

  // Extrude{..}{shapes} (kernel/occ/occ_extrude.cpp): a translation or a rotation (not a
  // twist) of points, curves and surfaces. For each shape: its top, the entity swept, then the
  // lateral entities (swept by a curve's start then end point, or by a surface's curves in the
  // order the surface stores them). New entities are numbered as OpenCASCADE's result holds
  // them. Layers are recorded on the swept and lateral entities.
  std::vector<EntityId> extrude(const std::vector<EntityId>& shapes, const ExtrusionMotion& motion,
                                const ExtrusionLayers& layers) override;

  // Lofts, fillets and chamfers (kernel/occ/occ_lofts_and_fillets.cpp).
  // ThruSections(tag) = {wires}: the volume (or, makeSolid false, the surfaces) through the
  // sections; ruled: plane faces between consecutive sections. Returns what it made.
  std::vector<EntityId> addThruSections(int tag, const std::vector<int>& wires, bool ruled,
                                        bool makeSolid = true) override;
  // Fillet{volumes}{curves}{radii}: rounds the curves of the volumes (one radius, one per
  // curve, or two per curve for a varying one); the volumes are replaced by new ones.
  std::vector<EntityId> fillet(const std::vector<int>& volumes, const std::vector<int>& curves,
                               const std::vector<double>& radii) override;
  // Chamfer{volumes}{curves}{surfaces}{distances}: bevels the curves, the first distance
  // measured on the surface given with each curve.
  std::vector<EntityId> chamfer(const std::vector<int>& volumes, const std::vector<int>& curves,
                                const std::vector<int>& surfaces,
                                const std::vector<double>& distances) override;

  // ShapeFromFile("x.step"), Merge "x.step" (kernel/occ/occ_import.cpp): the shapes of a
  // STEP, IGES or BREP file, with new tags; returns those of the highest dimension. A missing
  // or unreadable file is a GeometryError naming the path.
  // Read with the import options (scaling, target unit, healing). A .xao file written by
  // exportShapes gives every entity its tag back; one written elsewhere is read as a BREP.
  std::vector<EntityId> importShapes(const std::string& path,
                                     bool allDimensions = false) override;
  // Save "x.brep" / "x.step" / "x.xao": every entity that is not part of another one (the XAO
  // file, written atomically, also lists every entity with its tag).
  void exportShapes(const std::string& path) const override;
  void setImportOptions(const ImportOptions& options) override { importOptions_ = options; }
  const std::vector<PhysicalGroup>& importedGroups() const override { return importedGroups_; }
  bool hasShapes() const override;

  // HealShapes (kernel/occ/occ_healing.cpp).
  std::vector<EntityId> healShapes(const std::vector<EntityId>& shapes,
                                   const HealingOptions& options) override;

  // The unrolled script's lines for this factory's entities, after the line merging their
  // XAO file: mesh sizes at points, then the hooks' constraints of each curve, surface and
  // volume.
  void writeUnrolled(std::ostream& out, const UnrolledGeoHooks& hooks) const override;

  // Mesh constraints on its entities (kernel/occ/occ_constraints.cpp), recorded by tag as the
  // built-in factory records them on its own.
  void setPeriodic(int dim, const std::vector<int>& slaves, const std::vector<int>& masters,
                   const AffineMap& map) override;
  // Periodic Surface s {curves} = m {curves}: the rigid motion taking the master's curves
  // onto the slave's (whichever way each curve runs).
  void setPeriodicByCurves(int slave, const std::vector<int>& slaveCurves, int master,
                           const std::vector<int>& masterCurves) override;
  void embed(int dim, const std::vector<int>& tags, int hostDim, int hostTag) override;
  void addCompound(int dim, const std::vector<int>& tags) override;

  // Extrude{shapes} Using Wire{w}: the shapes swept along the wire (a pipe). Returns the
  // volumes (or surfaces) the sweep made, new tags in OpenCASCADE's order.
  std::vector<EntityId> extrudeAlongWire(const std::vector<EntityId>& shapes,
                                         int wireTag) override;

  // Queries and operations (kernel/occ/occ_queries.cpp), as the built-in factory offers them.
  void transform(const std::vector<EntityId>& shapes, const AffineMap& map) override;
  std::vector<EntityId> duplicate(const std::vector<EntityId>& shapes) override;
  void remove(const std::vector<EntityId>& shapes, bool recursive) override;
  std::vector<EntityId> boundary(const std::vector<EntityId>& shapes, bool combined) const override;
  std::vector<int> pointsOf(const std::vector<EntityId>& shapes) const override;
  // As the reference gives it: OpenCASCADE's box, which holds the shape's tolerance (1e-7).
  BoundingBox boundingBox(EntityId shape) const override;
  // Entities of `dim` whose tight box is inside `box` (to 1e-8 of the box's diagonal).
  std::vector<int> entitiesInBox(int dim, const BoundingBox& box) const override;
  std::vector<EntityId> closest(Vec3 point, const std::vector<EntityId>& shapes) const override;
  bool contains(EntityId e) const override;
  std::vector<int> tags(int dim) const override;  // ascending
  Vec3 pointCoordinates(int tag) const override;

  double volume(int tag) const;  // of the volume `tag`; throws GeometryError if undefined
  double area(int tag) const;    // of the surface `tag`
  double length(int tag) const;  // of the curve `tag`
  // The largest tag in use (as in the reference, removing the entity of the largest tag frees
  // it); dim 0..3 for entities, 4 for curve loops, 5 for surface loops.
  int maxTag(int kind) const override;

  // Adds (or replaces) this factory's entities in the model; other entities are kept.
  void synchronize(Model& model) const override;
  void clear() override;

 private:
  std::unique_ptr<OccShapes> shapes_;
  std::map<int, double> meshSizes_;  // at points
  BooleanOptions booleanOptions_;
  std::vector<Replacement> replacements_;  // of the last Boolean
  ImportOptions importOptions_;
  std::vector<PhysicalGroup> importedGroups_;  // of the last file read

  int primitiveTag(int dim, int tag, const char* what) const;
  void addChain(int tag, const std::vector<int>& curves, bool closed);
};

}  // namespace geomesh
