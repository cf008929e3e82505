// The operations of a solid modeler (the OpenCASCADE factory) that the built-in kernel lacks.
#pragma once

#include <string>
#include <vector>

#include "kernel/model.h"
#include "kernel/vec3.h"

namespace geomesh {

// Primitives, Booleans, lofts, fillets and CAD files, as the OpenCASCADE statements of scripts
// state them. A factory offers them through GeometryFactory::solidModeling() (null when it
// has none). Tags < 0 ask for the next free tag; failures throw GeometryError with the reason.
class SolidModeling {
 public:
  virtual ~SolidModeling() = default;

  // Whether the entity is one of this modeler's (and not, say, the built-in kernel's).
  virtual bool owns(EntityId e) const = 0;

  // Sphere{xc, yc, zc, r <, polar angle min, polar angle max, azimuthal opening>}.
  virtual int addSphere(int tag, Vec3 center, double radius, double angle1, double angle2,
                        double angle3) = 0;
  // Cylinder{x, y, z, dx, dy, dz, r <, angle>}: base centre, axis (its length is the height).
  virtual int addCylinder(int tag, Vec3 base, Vec3 axis, double radius, double angle) = 0;
  // Cone{x, y, z, dx, dy, dz, r1, r2 <, angle>}: r1 at the base, r2 at the top.
  virtual int addCone(int tag, Vec3 base, Vec3 axis, double radius1, double radius2,
                      double angle) = 0;
  // Torus{x, y, z, r1, r2 <, angle>}: around the z axis.
  virtual int addTorus(int tag, Vec3 center, double radius1, double radius2, double angle) = 0;
  // Wedge{x, y, z, dx, dy, dz <, ltx>}: right-angled, its top `ltx` long along x.
  virtual int addWedge(int tag, Vec3 corner, Vec3 extent, double topX) = 0;
  // Rectangle{x, y, z, dx, dy <, r>}: in the plane z, corners rounded with radius r.
  virtual int addRectangle(int tag, Vec3 corner, double dx, double dy, double roundedRadius) = 0;
  // Disk{xc, yc, zc, rx <, ry>}: an elliptic disk in the plane z (rx >= ry).
  virtual int addDisk(int tag, Vec3 center, double rx, double ry) = 0;
  // Circle{x, y, z, r <, angle1, angle2>}, Ellipse{x, y, z, rx, ry <, angle1, angle2>}: whole
  // curves or arcs in the plane z.
  virtual int addCircle(int tag, Vec3 center, double radius, const std::vector<double>& angles) = 0;
  virtual int addEllipse(int tag, Vec3 center, double rx, double ry,
                         const std::vector<double>& angles) = 0;
  // Wire(tag) = {curves}: a chain of curves, closed or not.
  virtual void addWire(int tag, const std::vector<int>& curves) = 0;

  // BooleanUnion/Intersection/Difference/Fragments{objects}{tools}, each list with or without
  // Delete. Returns the entities of the result. tag >= 0 (BooleanUnion(tag) = ..): the result,
  // which must then be one entity of its dimension, takes that tag.
  enum class BooleanOperation { Union, Intersection, Difference, Fragments };
  virtual std::vector<EntityId> boolean(BooleanOperation operation,
                                        const std::vector<EntityId>& objects,
                                        const std::vector<EntityId>& tools, bool deleteObjects,
                                        bool deleteTools, int tag) = 0;
  // What the last Boolean made of each input it deleted and did not keep as it was: the
  // entities that took its place (none when it is gone), in the result's order.
  struct Replacement {
    EntityId input;
    std::vector<EntityId> images;
  };
  virtual const std::vector<Replacement>& lastReplacements() const = 0;
  // Geometry.ToleranceBoolean (the fuzzy value, 0: exact), Geometry.OCCBooleanSimplify (a
  // union merges the faces and edges that lie on one surface or curve) and
  // Geometry.OCCBooleanPreserveNumbering (a deleted input turned into one shape passes its tag
  // on).
  struct BooleanOptions {
    double tolerance = 0;
    bool unifyUnion = true;
    bool preserveNumbering = true;
  };
  virtual void setBooleanOptions(const BooleanOptions& options) = 0;

  // Extrude{shapes} Using Wire{w}: the entities the sweep along the wire makes.
  virtual std::vector<EntityId> extrudeAlongWire(const std::vector<EntityId>& shapes,
                                                 int wireTag) = 0;

  // BSpline Surface(tag) = {loop}; / Bezier Surface(tag) = {loop};: the surface bounded by a
  // loop of 2 to 4 B-spline (Bezier) curves, by OpenCASCADE's curved filling style.
  virtual void addCurveFilling(int tag, int curveLoop, bool bezier) = 0;

  // (Ruled) ThruSections(tag) = {wires}; Fillet{volumes}{curves}{radii};
  // Chamfer{volumes}{curves}{surfaces}{distances}.
  virtual std::vector<EntityId> addThruSections(int tag, const std::vector<int>& wires,
                                                bool ruled, bool makeSolid) = 0;
  virtual std::vector<EntityId> fillet(const std::vector<int>& volumes,
                                       const std::vector<int>& curves,
                                       const std::vector<double>& radii) = 0;
  virtual std::vector<EntityId> chamfer(const std::vector<int>& volumes,
                                        const std::vector<int>& curves,
                                        const std::vector<int>& surfaces,
                                        const std::vector<double>& distances) = 0;

  // Closest{x, y, z}{shapes}: the shapes by increasing distance to the point (0 inside a
  // volume); ties keep their order.
  virtual std::vector<EntityId> closest(Vec3 point, const std::vector<EntityId>& shapes) const = 0;

  // Shape healing (HealShapes; and files read with Geometry.OCCFixDegenerated, ...):
  // degenerated edges and faces repaired, edges and faces smaller than the tolerance removed,
  // faces sewn into shells, closed shells made solids. The tolerance is Geometry.Tolerance.
  struct HealingOptions {
    double tolerance = 1e-8;
    bool fixDegenerated = false;
    bool fixSmallEdges = false;
    bool fixSmallFaces = false;
    bool sewFaces = false;
    bool makeSolids = false;
    bool any() const {
      return fixDegenerated || fixSmallEdges || fixSmallFaces || sewFaces || makeSolids;
    }
  };
  // How files are read: Geometry.OCCScaling (a scale about the origin), Geometry.OCCTargetUnit
  // (the length unit STEP and IGES models are converted to: "M", "CM", "MM", ...; empty:
  // millimetres) and the healing applied to what is read.
  struct ImportOptions {
    double scaling = 1;
    std::string targetUnit;
    HealingOptions healing;
  };
  virtual void setImportOptions(const ImportOptions& options) = 0;
  // HealShapes: heals the shapes (every shape of the model when `shapes` is empty); they go,
  // and what healing made of them takes new tags (healing all of them renumbers the model
  // from 1, as the reference does). Returns the new shapes of the highest dimensions.
  virtual std::vector<EntityId> healShapes(const std::vector<EntityId>& shapes,
                                           const HealingOptions& options) = 0;

  // ShapeFromFile (allDimensions false: the shapes of the file's highest dimension) and Merge
  // (every shape, free faces, curves and points too) of a STEP, IGES, BREP or XAO file. An
  // XAO file written by geomesh gives its shapes back their tags. Save of a .brep, .step or
  // .xao file.
  virtual std::vector<EntityId> importShapes(const std::string& path,
                                             bool allDimensions = false) = 0;
  virtual void exportShapes(const std::string& path) const = 0;
  // The groups the last file read lists (an XAO file's <groups>), by the tags their entities
  // got: Merge makes them physical groups, as the reference does.
  virtual const std::vector<PhysicalGroup>& importedGroups() const = 0;
  // Whether the modeler holds any shape.
  virtual bool hasShapes() const = 0;
};

}  // namespace geomesh
