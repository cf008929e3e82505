// Swept surfaces, Coons patches of 3 or 4 sides, spherical patches, and projection onto them.
#include "kernel/geo/swept_surface_geometry.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "kernel/geometry_error.h"

namespace geomesh {

SweptSurfaceGeometry::SweptSurfaceGeometry(std::shared_ptr<const CurveGeometry> curve,
                                           ExtrusionMotion motion, bool reversed)
    : curve_(std::move(curve)), motion_(motion), reversed_(reversed) {}

ParamBox SweptSurfaceGeometry::bounds() const { return {curve_->range(), {0, 1}}; }

double SweptSurfaceGeometry::curveParameter(double u) const {
  const Interval r = curve_->range();
  return reversed_ ? r.min + r.max - u : u;
}

Vec3 SweptSurfaceGeometry::point(Vec2 uv) const {
  return motion_.apply(curve_->point(curveParameter(uv.u)), uv.v);
}

SurfaceDerivatives SweptSurfaceGeometry::firstDerivatives(Vec2 uv) const {
  const double t = curveParameter(uv.u);
  const Vec3 along = curve_->firstDerivative(t);
  return {motion_.rotateVector(reversed_ ? -along : along, uv.v),
          motion_.velocity(curve_->point(t), uv.v)};
}

Vec2 SweptSurfaceGeometry::project(Vec3 p) const { return projectOnSurface(*this, p); }

CoonsSurfaceGeometry::CoonsSurfaceGeometry(std::vector<Side> sides) : sides_(std::move(sides)) {
  if (sides_.size() != 3 && sides_.size() != 4)
    throw GeometryError("a transfinite surface needs 3 or 4 sides, not " +
                        std::to_string(sides_.size()));
  for (std::size_t i = 0; i < 4; ++i) corners_[i] = sidePoint(i % sides_.size(), 0);
  if (sides_.size() == 3) corners_[3] = corners_[0];
}

Vec3 CoonsSurfaceGeometry::sidePoint(std::size_t i, double s) const {
  if (i >= sides_.size()) return corners_[0];
  const Side& side = sides_[i];
  const Interval r = side.curve->range();
  const double f = side.reversed ? 1 - s : s;
  return side.curve->point(r.min + f * (r.max - r.min));
}

Vec3 CoonsSurfaceGeometry::sideDerivative(std::size_t i, double s) const {
  if (i >= sides_.size()) return {};
  const Side& side = sides_[i];
  const Interval r = side.curve->range();
  const double f = side.reversed ? 1 - s : s;
  const double scale = (side.reversed ? -1 : 1) * (r.max - r.min);
  return scale * side.curve->firstDerivative(r.min + f * (r.max - r.min));
}

Vec3 CoonsSurfaceGeometry::deviation(std::size_t i, double s) const {
  const Vec3 a = corners_[i], b = corners_[(i + 1) % sides_.size()];
  return sidePoint(i, s) - (a + s * (b - a));
}

Vec3 CoonsSurfaceGeometry::deviationDerivative(std::size_t i, double s) const {
  return sideDerivative(i, s) - (corners_[(i + 1) % sides_.size()] - corners_[i]);
}

namespace {

// Where each side's deviation is read for a point (u, v) of the triangle, and how much of it is
// taken. With the barycentric coordinates b0 = 1 - u, b1 = u - v, b2 = v of the corners,
// side i (from corner i to corner i + 1) is read at s_i = b_{i+1} / (b_i + b_{i+1}), its own
// fraction on it, an end of it on the two other sides; its deviation is scaled by 1 - b_k,
// k the opposite corner, which is 1 on the side and 0 at that corner, so that the surface is
// continuous there whatever the direction it is approached from.
struct TriangleFractions {
  double s[3];
  Vec2 ds[3];      // derivatives of s with respect to u and v
  double w[3];     // the scale 1 - b_k
  Vec2 dw[3];      // its derivatives
};

TriangleFractions triangleFractions(double u, double v) {
  constexpr double kTiny = 1e-14;
  TriangleFractions f{};
  const double d0 = 1 - v, d2 = 1 - u + v;
  f.s[0] = d0 > kTiny ? (u - v) / d0 : 1;
  f.ds[0] = d0 > kTiny ? Vec2{1 / d0, (u - 1) / (d0 * d0)} : Vec2{};
  f.s[1] = u > kTiny ? v / u : 0;
  f.ds[1] = u > kTiny ? Vec2{-v / (u * u), 1 / u} : Vec2{};
  f.s[2] = d2 > kTiny ? (1 - u) / d2 : 0;
  f.ds[2] = d2 > kTiny ? Vec2{-v / (d2 * d2), -(1 - u) / (d2 * d2)} : Vec2{};
  f.w[0] = d0, f.dw[0] = {0, -1};  // opposite corner 2: b2 = v
  f.w[1] = u, f.dw[1] = {1, 0};    // opposite corner 0: b0 = 1 - u
  f.w[2] = d2, f.dw[2] = {-1, 1};  // opposite corner 1: b1 = u - v
  return f;
}

}  // namespace

Vec3 CoonsSurfaceGeometry::trianglePoint(Vec2 uv) const {
  const TriangleFractions f = triangleFractions(uv.u, uv.v);
  Vec3 p = corners_[0] + uv.u * (corners_[1] - corners_[0]) + uv.v * (corners_[2] - corners_[1]);
  for (std::size_t i = 0; i < 3; ++i) p += f.w[i] * deviation(i, f.s[i]);
  return p;
}

SurfaceDerivatives CoonsSurfaceGeometry::triangleDerivatives(Vec2 uv) const {
  const TriangleFractions f = triangleFractions(uv.u, uv.v);
  SurfaceDerivatives d{corners_[1] - corners_[0], corners_[2] - corners_[1]};
  for (std::size_t i = 0; i < 3; ++i) {
    const Vec3 dev = deviation(i, f.s[i]), dd = deviationDerivative(i, f.s[i]);
    d.du += f.dw[i].u * dev + f.w[i] * f.ds[i].u * dd;
    d.dv += f.dw[i].v * dev + f.w[i] * f.ds[i].v * dd;
  }
  return d;
}

// S = (1-v) B(u) + v T(u) + (1-u) L(v) + u R(v) - bilinear interpolation of the corners, with
// B = side 0, R = side 1, T(u) = side 2 at 1-u, L(v) = side 3 at 1-v.
Vec3 CoonsSurfaceGeometry::point(Vec2 uv) const {
  if (sides_.size() == 3) return trianglePoint(uv);
  const double u = uv.u, v = uv.v;
  const Vec3 bottom = sidePoint(0, u), right = sidePoint(1, v), top = sidePoint(2, 1 - u);
  const Vec3 left = sidePoint(3, 1 - v);
  const Vec3 bilinear = (1 - u) * (1 - v) * corners_[0] + u * (1 - v) * corners_[1] +
                        u * v * corners_[2] + (1 - u) * v * corners_[3];
  return (1 - v) * bottom + v * top + (1 - u) * left + u * right - bilinear;
}

SurfaceDerivatives CoonsSurfaceGeometry::firstDerivatives(Vec2 uv) const {
  if (sides_.size() == 3) return triangleDerivatives(uv);
  const double u = uv.u, v = uv.v;
  const Vec3 du = (1 - v) * sideDerivative(0, u) - v * sideDerivative(2, 1 - u) -
                  sidePoint(3, 1 - v) + sidePoint(1, v) -
                  ((v - 1) * corners_[0] + (1 - v) * corners_[1] + v * corners_[2] -
                   v * corners_[3]);
  const Vec3 dv = -sidePoint(0, u) + sidePoint(2, 1 - u) - (1 - u) * sideDerivative(3, 1 - v) +
                  u * sideDerivative(1, v) -
                  ((u - 1) * corners_[0] - u * corners_[1] + u * corners_[2] +
                   (1 - u) * corners_[3]);
  return {du, dv};
}

Vec2 CoonsSurfaceGeometry::project(Vec3 p) const {
  return projectOnSurface(*this, p, sides_.size() == 3);
}

SphericalPatchGeometry::SphericalPatchGeometry(std::vector<Vec3> corners, Vec3 center,
                                               double radius)
    : corners_(std::move(corners)), center_(center), radius_(radius) {}

Vec3 SphericalPatchGeometry::flatPoint(Vec2 uv) const {
  const double u = uv.u, v = uv.v;
  const std::vector<Vec3>& c = corners_;
  if (c.size() == 3) return c[0] + u * (c[1] - c[0]) + v * (c[2] - c[1]);
  return (1 - u) * (1 - v) * c[0] + u * (1 - v) * c[1] + u * v * c[2] + (1 - u) * v * c[3];
}

SurfaceDerivatives SphericalPatchGeometry::flatDerivatives(Vec2 uv) const {
  const double u = uv.u, v = uv.v;
  const std::vector<Vec3>& c = corners_;
  if (c.size() == 3) return {c[1] - c[0], c[2] - c[1]};
  return {(1 - v) * (c[1] - c[0]) + v * (c[2] - c[3]), (1 - u) * (c[3] - c[0]) + u * (c[2] - c[1])};
}

Vec3 SphericalPatchGeometry::point(Vec2 uv) const {
  const Vec3 q = flatPoint(uv) - center_;
  return center_ + (radius_ / norm(q)) * q;
}

// d(r q/|q|) = (r/|q|) (dq - n (n . dq)), n = q/|q|.
SurfaceDerivatives SphericalPatchGeometry::firstDerivatives(Vec2 uv) const {
  const Vec3 q = flatPoint(uv) - center_;
  const double length = norm(q);
  const Vec3 n = q / length;
  const SurfaceDerivatives d = flatDerivatives(uv);
  auto radial = [&](Vec3 dq) { return (radius_ / length) * (dq - dot(n, dq) * n); };
  return {radial(d.du), radial(d.dv)};
}

Vec2 SphericalPatchGeometry::project(Vec3 p) const {
  return projectOnSurface(*this, p, corners_.size() == 3);
}

Vec2 projectOnSurface(const SurfaceGeometry& surface, Vec3 p, bool triangle) {
  const ParamBox box = surface.bounds();
  constexpr int kGrid = 16;
  Vec2 best{box.u.min, box.v.min};
  double bestDistance = 1e300;
  for (int i = 0; i <= kGrid; ++i)
    for (int j = 0; j <= kGrid; ++j) {
      const Vec2 uv{box.u.min + (box.u.max - box.u.min) * i / kGrid,
                    box.v.min + (box.v.max - box.v.min) * j / kGrid};
      if (triangle && uv.v > uv.u) continue;
      const double d = distance(surface.point(uv), p);
      if (d < bestDistance) {
        bestDistance = d;
        best = uv;
      }
    }
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Vec3 r = surface.point(best) - p;
    const SurfaceDerivatives d = surface.firstDerivatives(best);
    const double a = dot(d.du, d.du), b = dot(d.du, d.dv), c = dot(d.dv, d.dv);
    const double det = a * c - b * b;
    if (!(std::abs(det) > 0)) break;
    const double gu = dot(d.du, r), gv = dot(d.dv, r);
    const Vec2 step{(c * gu - b * gv) / det, (a * gv - b * gu) / det};
    best = {std::clamp(best.u - step.u, box.u.min, box.u.max),
            std::clamp(best.v - step.v, box.v.min, box.v.max)};
    if (triangle) best.v = std::min(best.v, best.u);
    if (std::abs(step.u) + std::abs(step.v) < 1e-14) break;
  }
  return best;
}

}  // namespace geomesh
