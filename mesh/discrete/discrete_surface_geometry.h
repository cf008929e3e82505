// DiscreteSurfaceGeometry: a patch of a triangulation as a parametric surface, through the map
// of its triangles to the plane that parametrizePatch made.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "kernel/geometry.h"
#include "mesh/discrete/parametrization.h"

namespace geomesh {

// How a boundary curve runs through the parameter plane: its triangulation vertices, each with
// the curve's parameter there and its uv.
struct CurveTrace {
  std::vector<double> t;  // ascending (the curve's own parameter at each of its vertices)
  std::vector<Vec2> uv;
};

// The surface of a mapped patch, piecewise linear over its uv triangles.
//
// On a plane patch with its frame (PatchMap::origin, axisU, axisV), point(uv) and
// firstDerivatives(uv) are those of the plane. Otherwise point(uv) finds the uv triangle
// holding uv (the closest one when uv lies outside every triangle, e.g. inside a filled hole
// or just past the boundary) and maps uv by that triangle's affine map to space;
// firstDerivatives(uv) is that map's constant Jacobian.
// project(p) finds the closest point on the 3D triangles and returns its uv by barycentric
// interpolation. curveParameters(signedCurve, t) interpolates the CurveTrace of |signedCurve|
// linearly (the sign is ignored), clamped to its ends. curvature(uv) interpolates
// `vertexCurvature` (per local vertex; no value when it is empty).
//
// Safe to use from several threads at once: the last triangle found, where the next search
// starts, is kept per thread.
class DiscreteSurfaceGeometry final : public SurfaceGeometry {
 public:
  // `points`: the position of each local vertex of `map`. Throws std::invalid_argument when
  // the map has no triangle or the sizes of points, map.uv and vertexCurvature disagree.
  DiscreteSurfaceGeometry(std::vector<Vec3> points, PatchMap map,
                          std::map<int, CurveTrace> curves,
                          std::vector<double> vertexCurvature = {});
  ~DiscreteSurfaceGeometry() override;

  ParamBox bounds() const override { return bounds_; }
  Vec3 point(Vec2 uv) const override;
  SurfaceDerivatives firstDerivatives(Vec2 uv) const override;
  Vec2 project(Vec3 p) const override;
  SurfaceKind kind() const override { return SurfaceKind::Other; }
  bool isPlane() const override { return map_.planar; }
  std::optional<Vec2> curveParameters(int signedCurve, double t) const override;
  std::optional<double> curvature(Vec2 uv) const override;

  // The local index (into map().triangles) of the triangle closest to p in space.
  std::uint32_t closestTriangle(Vec3 p) const;
  const PatchMap& map() const { return map_; }
  std::span<const Vec3> points() const { return points_; }

 private:
  struct Located;
  struct Search;  // the spatial indices (uv grid, CGAL trees)

  Located locate(Vec2 uv) const;
  bool hasPlaneFrame() const { return map_.planar && dot(map_.axisU, map_.axisU) > 0; }

  std::vector<Vec3> points_;
  PatchMap map_;
  std::map<int, CurveTrace> curves_;
  std::vector<double> vertexCurvature_;
  ParamBox bounds_;
  std::unique_ptr<const Search> search_;
};

}  // namespace geomesh
