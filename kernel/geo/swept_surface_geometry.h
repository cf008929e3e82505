// SweptSurfaceGeometry, CoonsSurfaceGeometry, SphericalPatchGeometry and projectOnSurface.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "kernel/extrusion_motion.h"
#include "kernel/geometry.h"

namespace geomesh {

// The surface swept by a curve under an extrusion: point(u, v) = M_v(curve(u)), u over the
// curve's range, v in [0, 1]. Translations give ruled (cylindrical) surfaces, rotations
// surfaces of revolution. A reversed sweep runs the curve backwards (curve(min + max - u)),
// so that the surface's loop, which starts with the reversed curve, still runs
// counter-clockwise in the parameters.
class SweptSurfaceGeometry final : public SurfaceGeometry {
 public:
  SweptSurfaceGeometry(std::shared_ptr<const CurveGeometry> curve, ExtrusionMotion motion,
                       bool reversed = false);

  ParamBox bounds() const override;
  Vec3 point(Vec2 uv) const override;
  SurfaceDerivatives firstDerivatives(Vec2 uv) const override;
  Vec2 project(Vec3 p) const override;

 private:
  double curveParameter(double u) const;

  std::shared_ptr<const CurveGeometry> curve_;
  ExtrusionMotion motion_;
  bool reversed_;
};

// Transfinite (Coons) interpolation of three or four boundary curves. Each side is given with
// its direction along the loop. Four sides: over [0, 1]^2, running u = 0..1 at v = 0, then
// v = 0..1 at u = 1, then u = 1..0 at v = 1, then v = 1..0 at u = 0 (Gmsh's parametrization).
// Three sides: over the triangle 0 <= v <= u <= 1 (Gmsh's domain), running along v = 0, then
// u = 1, then the diagonal back to the origin; the surface is the affine map of the corners
// (as in Gmsh) plus each side's deviation from its chord, carried along lines that keep the
// other sides exact and faded out towards the opposite corner (inside, curved sides blend
// differently from Gmsh's formula).
class CoonsSurfaceGeometry final : public SurfaceGeometry {
 public:
  struct Side {
    std::shared_ptr<const CurveGeometry> curve;
    bool reversed = false;
  };
  explicit CoonsSurfaceGeometry(std::vector<Side> sides);

  ParamBox bounds() const override { return {{0, 1}, {0, 1}}; }
  Vec3 point(Vec2 uv) const override;
  SurfaceDerivatives firstDerivatives(Vec2 uv) const override;
  Vec2 project(Vec3 p) const override;

 private:
  // Point of side i at loop fraction s (0: its start along the loop), and its derivative.
  Vec3 sidePoint(std::size_t i, double s) const;
  Vec3 sideDerivative(std::size_t i, double s) const;
  // Side i's deviation from its chord at s, and the derivative of that deviation.
  Vec3 deviation(std::size_t i, double s) const;
  Vec3 deviationDerivative(std::size_t i, double s) const;
  Vec3 trianglePoint(Vec2 uv) const;
  SurfaceDerivatives triangleDerivatives(Vec2 uv) const;

  std::vector<Side> sides_;
  std::array<Vec3, 4> corners_;
};

// A filling surface whose sides are all circle arcs about one centre with one radius: arcs of
// great circles of that sphere. The surface is the patch of the sphere they bound: the flat
// interpolation of its corners (affine over the triangle 0 <= v <= u <= 1 for three sides,
// bilinear over [0, 1]^2 for four), projected from the centre onto the sphere. The straight
// sides of that interpolation project exactly onto the arcs.
class SphericalPatchGeometry final : public SurfaceGeometry {
 public:
  // corners: 3 or 4 points on the sphere, in the loop's order.
  SphericalPatchGeometry(std::vector<Vec3> corners, Vec3 center, double radius);

  ParamBox bounds() const override { return {{0, 1}, {0, 1}}; }
  Vec3 point(Vec2 uv) const override;
  SurfaceDerivatives firstDerivatives(Vec2 uv) const override;
  Vec2 project(Vec3 p) const override;
  SurfaceKind kind() const override { return SurfaceKind::Sphere; }

 private:
  Vec3 flatPoint(Vec2 uv) const;
  SurfaceDerivatives flatDerivatives(Vec2 uv) const;

  std::vector<Vec3> corners_;
  Vec3 center_;
  double radius_;
};

// The parameters of the point of `surface` closest to p: the best of a grid of samples,
// refined by Gauss-Newton steps, kept inside the bounds (and below the diagonal, v <= u, for
// a triangular domain).
Vec2 projectOnSurface(const SurfaceGeometry& surface, Vec3 p, bool triangle = false);

}  // namespace geomesh
