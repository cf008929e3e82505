// SizeFields: the mesh size fields a script defines, compiled once and evaluated per point.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <memory>
#include <span>
#include <string_view>
#include <string>
#include <vector>

#include "kernel/messages.h"
#include "kernel/model.h"
#include "mesh/core/mesh_options.h"
#include "mesh/sizes/math_expression.h"

namespace geomesh {

class PointCloud;
class BoundaryExtension;
class AutomaticSize;
class ViewSize;
class AdaptSize;
struct BoundaryLayerParameters;
class CurveDistance;

// The mesh size fields a script defined (Field[n] = Type; Field[n].Option = v), compiled for
// evaluation, and the background field (Background Field = n) that the meshers follow. Each
// type takes the reference's option names and defaults; older option names are accepted
// (NodesList, EdgesList, FacesList, NNodesByEdge/NumPointsPerCurve, IField, LcMin, LcMax,
// lMinTangent..., R1_inner...). An unknown type or option is reported once to the log and
// ignored; a field reading an undefined field, or a cycle of fields, reads 1e22 there.
//
// Types: Constant, Box, Ball, Cylinder, Distance (alias Attractor), Threshold, MathEval, Min,
// Max, Restrict, and:
//  - Frustum: between the inner and outer radii of a cone frustum from (X1,Y1,Z1) to
//    (X2,Y2,Z2), the sizes InnerV*/OuterV* interpolated bilinearly along the axis (u) and
//    across the shell (v); 1e22 off the shell (inside the inner radius, beyond the outer one,
//    or past either end).
//  - Param: Field[InField] at (FX, FY, FZ), three MathEval formulas in x, y, z (and F<n>);
//    a formula left empty stands for its own coordinate (the reference stops on it).
//  - Gradient (Kind 0, 1, 2: the x, y or z component, 3: the norm), Curvature (the divergence
//    of the unit gradient), Laplacian, MaxEigenHessian (the largest, signed, eigenvalue of
//    the Hessian) and Mean (of the point and its six neighbours at distance Delta): central
//    finite differences of Field[InField] with step Delta, as the reference takes them.
//  - Octree: Field[InField], evaluated directly (the reference samples it on an octree and
//    reads cell values; geomesh evaluates the field itself at every point).
//  - Extend: the sizes of the mesh on the listed curves (in a surface) or surfaces (in a
//    volume) carried inwards, F = f SizeBnd + (1 - f) SizeMax with f = ((DistMax - d) /
//    DistMax)^Power within DistMax of the nearest boundary edge (SizeBnd its length), SizeMax
//    beyond; 1e22 on points and curves. The curves' edges are placed as the 1D stage places
//    nodes from the end points' sizes and the Mesh.* options given at construction (not
//    measured on the mesh, which the fields do not see); a listed surface's edges are taken
//    for the sizes the same formula gives there from the surface's own curves.
//  - AutomaticMeshSizeField: see automatic_size.h.
//  - ExternalProcess: refused (geomesh does not run external programs): a warning, and the
//    field reads 1e22.
//  - PostView: the sizes of a view of options.views (ViewTag when >= 0, else ViewIndex,
//    alias IView), as view_size.h reads them (CropNegativeValues, UseClosest); a missing
//    view: a warning naming the field and the view, and the field reads 1e22.
//  - Adapt (geomesh's own): sizes equidistributing the error estimates of a view over the
//    current mesh, for TargetElements or TargetError (View, Order, Dimension, SizeMin,
//    SizeMax); see adapt_size.h.
//  - BoundaryLayer: the options of a 2D boundary layer (boundary_layer_field.h), which the
//    surface mesher builds for the fields named by BoundaryLayer Field = n; read as a size
//    field, the layer's cell height at the distance from its curves, capped by SizeFar.
// Background Mesh View[n] (MeshConstraints::backgroundView) reads view n as a PostView field
// with the default options does.
// Anisotropic types: our meshers are isotropic, and follow an anisotropic field through the
// smallest size its metric gives at a point, with no warning:
//  - MathEvalAniso: the metric M (M11 ... M23, MathEval formulas) asks for size 1/sqrt(e'Me)
//    along a unit direction e; the field reads 1/sqrt(largest eigenvalue of M) (1e22 where
//    M has no positive eigenvalue). The reference's isotropic meshers read M11 as the size.
//  - AttractorAnisoCurve: at distance d from the curves (sampled by Sampling points each),
//    the tangent size goes from SizeMinTangent (d <= DistMin) to SizeMaxTangent (d >= DistMax)
//    linearly, the normal size likewise; the field reads the smaller of the two. The
//    reference's isotropic meshers read the distance itself as the size.
class SizeFields {
 public:
  // `options` are the Mesh.* options of the run, which Extend's 1D meshes of its curves use.
  SizeFields(const Model& model, MessageSink& log, const MeshOptions& options = {});
  ~SizeFields();
  SizeFields(SizeFields&&) noexcept;
  SizeFields& operator=(SizeFields&&) noexcept;

  // Whether a background is defined: a Background Field, or a Background Mesh View (the
  // view of options.views at MeshConstraints::backgroundView); with both, the smaller size.
  bool hasBackground() const;
  // The background field's sizes at `points`, which lie on entity `where` (some fields,
  // Restrict, Constant and Extend, depend on it).
  void evaluate(std::span<const Vec3> points, EntityId where, std::span<double> sizes) const;
  double at(Vec3 point, EntityId where) const;
  // Field `tag` at a point (1e22 if undefined).
  double value(int tag, Vec3 point, EntityId where) const;
  // The anisotropic metric the background asks for at a point: the symmetric M (xx, xy, xz,
  // yy, yz, zz) such that the size along a unit direction e is 1/sqrt(e'Me). From a tensor
  // background view (directly or through a PostView field) or a MathEvalAniso background
  // field; I/h^2 from an isotropic background of size h. Eigenvalues are bounded so that no
  // aspect ratio exceeds Mesh.AnisoMax. nullopt where no background is defined.
  std::optional<std::array<double, 6>> metric(Vec3 point, EntityId where) const;
  // Whether the background carries anisotropy (a tensor view, MathEvalAniso...).
  bool hasAnisotropicBackground() const;
  // The BoundaryLayer fields that BoundaryLayer Field = n named, in order (others are
  // reported when the fields are read, and left out).
  std::vector<const BoundaryLayerParameters*> boundaryLayers() const;
  // A warning of the meshers that read the fields (the layers'), to the run's log.
  void warning(std::string_view message) const;

  enum class Type {
    Constant, Box, Ball, Cylinder, Distance, Threshold, MathEval, Min, Max, Restrict,
    Frustum, Param, Gradient, Curvature, Laplacian, MaxEigenHessian, Mean, Octree, Extend,
    MathEvalAniso, AttractorAnisoCurve, Automatic, ExternalProcess, PostView, Adapt,
    BoundaryLayer
  };
  // Numeric options, by position (each type uses some of them).
  enum class Slot : std::uint8_t {
    VIn, VOut, XMin, XMax, YMin, YMax, ZMin, ZMax, Thickness, Radius, XCenter, YCenter,
    ZCenter, XAxis, YAxis, ZAxis, Sampling, InField, SizeMin, SizeMax, DistMin, DistMax,
    Sigmoid, StopAtDistMax, IncludeBoundary,
    Delta, Kind, X1, Y1, Z1, X2, Y2, Z2, InnerR1, OuterR1, InnerR2, OuterR2, InnerV1, OuterV1,
    InnerV2, OuterV2, Power, SizeMinTangent, SizeMaxTangent, SizeMinNormal, SizeMaxNormal,
    HBulk, HMin, HMax, Gradation, Features, PointsPerCircle, PointsPerGap, Smoothing,
    ViewIndex, ViewTag, CropNegativeValues, UseClosest, View, Order, Dimension, TargetElements,
    TargetError
  };
  static constexpr int kSlotCount = 63;
  struct Field {
    Type type = Type::Constant;
    std::array<double, kSlotCount> slots = {};
    std::vector<int> fieldsList;             // Min, Max (FieldsList)
    std::vector<EntityId> entities;          // Distance, Constant, Restrict, Extend... lists
    std::unique_ptr<MathExpression> expression;               // MathEval
    std::vector<std::unique_ptr<MathExpression>> expressions;  // MathEvalAniso, Param
    std::unique_ptr<PointCloud> samples;     // Distance, AttractorAnisoCurve
    std::unique_ptr<BoundaryExtension> extension;  // Extend
    std::unique_ptr<AutomaticSize> automatic;      // AutomaticMeshSizeField
    std::unique_ptr<ViewSize> view;                // PostView
    std::unique_ptr<AdaptSize> adapt;              // Adapt
    std::unique_ptr<BoundaryLayerParameters> layer;  // BoundaryLayer
    std::unique_ptr<CurveDistance> wallDistance;     // BoundaryLayer
    double number(Slot s) const { return slots[static_cast<std::size_t>(s)]; }
    int inField() const;
  };

 private:
  double evaluateField(const Field& f, Vec3 p, EntityId where, int depth) const;
  double evaluateDerived(const Field& f, Vec3 p, EntityId where, int depth) const;
  double valueAtDepth(int tag, Vec3 p, EntityId where, int depth) const;
  double formula(const MathExpression& e, Vec3 p, EntityId where, int depth) const;
  bool inEntities(const std::vector<EntityId>& list, EntityId where, bool withBoundary) const;
  std::array<double, 6> fieldMetric(const Field& f, Vec3 p, EntityId where) const;
  bool hasBackgroundField() const;

  const Model* model_;
  std::map<int, Field> fields_;
  int background_ = 0;
  std::unique_ptr<ViewSize> backgroundView_;  // Background Mesh View
  double anisoMax_ = 1e33;                    // Mesh.AnisoMax
  std::vector<int> layerFields_;              // BoundaryLayer Field = n, checked
  MessageSink* log_ = nullptr;
};

}  // namespace geomesh
