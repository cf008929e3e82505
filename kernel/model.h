// Model: the boundary representation of points, curves, surfaces, volumes; mesh constraints.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kernel/extrusion_motion.h"
#include "kernel/geometry.h"

namespace geomesh {

// Identifies a model entity: its dimension (0..3) and its tag within that dimension.
struct EntityId {
  int dim = 0;
  int tag = 0;
  friend auto operator<=>(const EntityId&, const EntityId&) = default;
};

// How an extruded entity is to be meshed (Layers{...} and Recombine inside Extrude): one
// layer per entry, `elements[i]` elements thick, ending at the normalized height heights[i].
// Empty `elements`: the extrusion is meshed without layers.
struct ExtrusionLayers {
  std::vector<int> elements;
  std::vector<double> heights;
  bool recombine = false;
  friend bool operator==(const ExtrusionLayers&, const ExtrusionLayers&) = default;
};

// Where an extruded entity comes from: the entity one dimension lower that was swept to make
// it (a curve from a point, a surface from a curve, a volume from a surface), its image at the
// end of the sweep (`top`, same dimension as the source), the layers, and the motion of the
// sweep, which places the nodes of a layered mesh. The motion is shared: every entity has
// room for a record, and most are not extruded.
struct ExtrusionRecord {
  int source = 0;
  ExtrusionLayers layers = {};
  int top = 0;
  std::shared_ptr<const ExtrusionMotion> motion = nullptr;
};

// Periodic Curve/Surface{slave} = {master} Translate/Rotate{..}: the slave is the image of the
// master by `affine` (row-major 4x4, as Gmsh reports it).
struct Periodicity {
  int master = 0;
  std::vector<double> affine = {};
};

// Transfinite Curve{t} = nodes Using Progression|Bump|Beta coefficient: the curve gets exactly
// `nodes` nodes, spaced by the law (Progression: each segment `coefficient` times the previous
// one; Bump: refined towards both ends, the end size `coefficient` times the middle one; Beta:
// Roberts' boundary-layer stretching towards the start). `reversed` (a negative tag in the
// script) runs the law from the curve's end.
struct TransfiniteCurve {
  enum class Law { Progression, Bump, Beta };
  int nodes = 2;
  Law law = Law::Progression;
  double coefficient = 1;
  bool reversed = false;
};

// Transfinite Surface{t} = {corners} Left|Right|Alternate...: a structured mesh of a surface of
// 3 or 4 sides; `corners` (point tags) are empty when the surface's boundary gives them.
struct TransfiniteSurface {
  enum class Arrangement { Left, Right, AlternateLeft, AlternateRight };
  std::vector<int> corners = {};
  Arrangement arrangement = Arrangement::Left;
};

// Field[tag] = type; Field[tag].option = value: a mesh size field as the script defined it.
struct SizeFieldDefinition {
  std::string type;
  std::map<std::string, std::vector<double>> numbers = {};
  std::map<std::string, std::string> strings = {};
};

// Mesh constraints set by scripts on entity tags. As in Gmsh, they may be given before the
// entities are synchronized into the model, so Model::clear() keeps them.
struct MeshConstraints {
  std::map<int, TransfiniteCurve> transfiniteCurves = {};
  std::map<int, TransfiniteSurface> transfiniteSurfaces = {};
  // Transfinite Volume{t} = {8 corners}: tag -> corners (empty: found from the volume's shape).
  std::map<int, std::vector<int>> transfiniteVolumes = {};
  std::map<int, double> recombinedSurfaces = {};  // tag -> Recombine Surface{t} = angle (deg)
  std::map<int, int> surfaceAlgorithms = {};      // tag -> MeshAlgorithm Surface{t} = n
  std::map<int, SizeFieldDefinition> sizeFields = {};
  int backgroundField = 0;  // Background Field = tag; 0: none
  int backgroundView = -1;  // Background Mesh View[index]; -1: none
  std::vector<int> boundaryLayerFields = {};  // BoundaryLayer Field = tag, in order
};

struct ModelPoint {
  int tag = 0;
  Vec3 xyz;
  double meshSize = 0;  // 0: no size prescribed at this point
  // A vertex of a merged triangulation (a corner ClassifySurfaces found): its node is the
  // triangulation's.
  bool discrete = false;
};

struct ModelCurve {
  int tag = 0;
  int startPoint = 0;  // tags of the bounding points (equal for a closed curve)
  int endPoint = 0;
  std::shared_ptr<const CurveGeometry> geometry;
  std::optional<ExtrusionRecord> extrusion = std::nullopt;
  std::optional<Periodicity> periodic = std::nullopt;
  std::vector<int> embeddedPoints = {};
  std::vector<int> compound = {};  // Compound Curve{..}: the curves meshed together with this one
  // The built-in kernel's curves count in the model's size box by their points only (an arc
  // bulging past its ends does not widen it), as the reference measures its models.
  bool boxedByPoints = false;
  // A curve ClassifySurfaces found on a merged triangulation, not yet given a geometry by
  // CreateGeometry: its mesh is the triangulation's edges along it (its geometry, the polyline
  // through them, only locates it).
  bool discrete = false;
};

struct ModelSurface {
  int tag = 0;
  // Curve loops: the first is the outer boundary, the others are holes. Signed curve tags: a
  // negative tag means the curve is followed from its end to its start.
  std::vector<std::vector<int>> loops;
  std::shared_ptr<const SurfaceGeometry> geometry;
  std::vector<int> embeddedPoints;
  std::vector<int> embeddedCurves;
  std::optional<ExtrusionRecord> extrusion = std::nullopt;
  std::optional<Periodicity> periodic = std::nullopt;
  std::vector<int> compound = {};
  // From a merged mesh file (Merge "x.stl"), and not given a geometry by CreateGeometry: no
  // geometry; its mesh is the file's triangles.
  bool discrete = false;
};

struct ModelVolume {
  int tag = 0;
  // Surface loops (shells): the first is the outer one, the others are holes. Signed tags.
  std::vector<std::vector<int>> shells;
  std::optional<ExtrusionRecord> extrusion = std::nullopt;
  std::vector<int> embeddedPoints = {};
  std::vector<int> embeddedCurves = {};
  std::vector<int> embeddedSurfaces = {};
};

struct PhysicalGroup {
  int dim = 0;
  int tag = 0;
  std::string name;
  std::vector<int> entities;  // tags of entities of dimension `dim`
};

// The topological model: a boundary representation of points, curves, surfaces and volumes,
// with adjacencies both ways and physical groups. Geometry factories fill it on synchronize().
class Model {
 public:
  void clear();

  ModelPoint& addPoint(ModelPoint p);
  ModelCurve& addCurve(ModelCurve c);
  ModelSurface& addSurface(ModelSurface s);
  ModelVolume& addVolume(ModelVolume v);
  void addPhysicalGroup(PhysicalGroup g);

  const std::map<int, ModelPoint>& points() const { return points_; }
  const std::map<int, ModelCurve>& curves() const { return curves_; }
  const std::map<int, ModelSurface>& surfaces() const { return surfaces_; }
  const std::map<int, ModelVolume>& volumes() const { return volumes_; }
  // Ordered by (dim, tag).
  const std::map<EntityId, PhysicalGroup>& physicalGroups() const { return physicals_; }

  // The box whose diagonal sets the default mesh size: every point, and the curves not
  // boxedByPoints.
  BoundingBox sizeBox() const;
  // Widens sizeBox() by `box`: a model made from another, with fewer entities, keeps the
  // other's default size.
  void widenSizeBox(const BoundingBox& box) { sizeBoxExtra_.include(box); }
  const ModelPoint* point(int tag) const;
  const ModelCurve* curve(int tag) const;
  const ModelSurface* surface(int tag) const;
  const ModelVolume* volume(int tag) const;
  bool contains(EntityId e) const;
  std::vector<EntityId> entities(int dim) const;  // ascending tags; dim -1: all
  int maxTag(int dim) const;

  // Boundary of an entity: signed tags of entities one dimension lower, in loop order.
  std::vector<int> boundary(EntityId e) const;
  // Entities one dimension higher whose boundary contains e (ascending tags).
  std::vector<int> upward(EntityId e) const;
  // Physical groups of dimension e.dim that contain e (ascending tags).
  std::vector<int> physicalTagsOf(EntityId e) const;

  BoundingBox boundingBox(EntityId e) const;
  BoundingBox boundingBox() const;

  // Kept by clear(); see MeshConstraints.
  MeshConstraints& meshConstraints() { return meshConstraints_; }
  const MeshConstraints& meshConstraints() const { return meshConstraints_; }

 private:
  std::map<int, ModelPoint> points_;
  std::map<int, ModelCurve> curves_;
  std::map<int, ModelSurface> surfaces_;
  std::map<int, ModelVolume> volumes_;
  std::map<EntityId, PhysicalGroup> physicals_;
  BoundingBox sizeBoxExtra_;
  std::map<EntityId, std::vector<int>> upward_;  // maintained as entities are added
  MeshConstraints meshConstraints_;
};

}  // namespace geomesh
