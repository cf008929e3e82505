// Small models for the mesher tests: segments, arcs, planes, sphere patches, polygon builder.
#pragma once

// Small models for the mesher tests, built directly (no script, no geometry kernel): straight
// segments and the plane z = 0.

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include "kernel/model.h"
#include "kernel/plane_geometry.h"
#include "mesh/core/mesh.h"

namespace geomesh::testing {

class SegmentGeometry final : public CurveGeometry {
 public:
  SegmentGeometry(Vec3 a, Vec3 b) : a_(a), b_(b) {}
  Interval range() const override { return {0, 1}; }
  Vec3 point(double t) const override { return a_ + t * (b_ - a_); }
  Vec3 firstDerivative(double) const override { return b_ - a_; }
  Vec3 secondDerivative(double) const override { return {}; }

 private:
  Vec3 a_, b_;
};

// A circular arc of the given radius around `center` in the plane z = center.z, between two
// angles (by default the full circle from angle 0).
class CircleGeometry final : public CurveGeometry {
 public:
  CircleGeometry(Vec3 center, double radius, double from = 0, double to = 2 * kPi)
      : c_(center), r_(radius), from_(from), to_(to) {}
  Interval range() const override { return {from_, to_}; }
  Vec3 point(double t) const override { return c_ + Vec3{r_ * std::cos(t), r_ * std::sin(t), 0}; }
  Vec3 firstDerivative(double t) const override { return {-r_ * std::sin(t), r_ * std::cos(t), 0}; }
  Vec3 secondDerivative(double t) const override {
    return {-r_ * std::cos(t), -r_ * std::sin(t), 0};
  }
  static constexpr double kPi = 3.14159265358979323846;

 private:
  Vec3 c_;
  double r_, from_, to_;
};

// The plane z = 0, parametrized by (u, v) -> (u, sign * v, 0): its normal is sign * z.
class FlatGeometry final : public SurfaceGeometry {
 public:
  explicit FlatGeometry(double sign = 1) : sign_(sign) {}
  ParamBox bounds() const override { return {{-1e3, 1e3}, {-1e3, 1e3}}; }
  Vec3 point(Vec2 uv) const override { return {uv.u, sign_ * uv.v, 0}; }
  SurfaceDerivatives firstDerivatives(Vec2) const override { return {{1, 0, 0}, {0, sign_, 0}}; }
  Vec2 project(Vec3 p) const override { return {p.x, sign_ * p.y}; }
  bool isPlane() const override { return true; }

 private:
  double sign_;
};

// The unit sphere, (u, v) -> (cos v cos u, cos v sin u, sin v): longitude u, latitude v. Its
// normal du x dv points outwards.
class SphereGeometry final : public SurfaceGeometry {
 public:
  ParamBox bounds() const override { return {{-kPi, kPi}, {-kPi / 2, kPi / 2}}; }
  Vec3 point(Vec2 uv) const override {
    return {std::cos(uv.v) * std::cos(uv.u), std::cos(uv.v) * std::sin(uv.u), std::sin(uv.v)};
  }
  SurfaceDerivatives firstDerivatives(Vec2 uv) const override {
    const double cu = std::cos(uv.u), su = std::sin(uv.u), cv = std::cos(uv.v), sv = std::sin(uv.v);
    return {{-cv * su, cv * cu, 0}, {-sv * cu, -sv * su, cv}};
  }
  Vec2 project(Vec3 p) const override {
    return {std::atan2(p.y, p.x), std::asin(std::clamp(p.z / norm(p), -1.0, 1.0))};
  }
  static constexpr double kPi = 3.14159265358979323846;
};

// The image on a surface of the parameter segment from a to b.
class IsoCurve final : public CurveGeometry {
 public:
  IsoCurve(std::shared_ptr<const SurfaceGeometry> s, Vec2 a, Vec2 b)
      : s_(std::move(s)), a_(a), b_(b) {}
  Interval range() const override { return {0, 1}; }
  Vec3 point(double t) const override { return s_->point(at(t)); }
  Vec3 firstDerivative(double t) const override {
    const SurfaceDerivatives d = s_->firstDerivatives(at(t));
    return (b_.u - a_.u) * d.du + (b_.v - a_.v) * d.dv;
  }
  Vec3 secondDerivative(double t) const override {
    constexpr double kStep = 1e-6;
    return (firstDerivative(t + kStep) - firstDerivative(t - kStep)) / (2 * kStep);
  }

 private:
  Vec2 at(double t) const { return {a_.u + t * (b_.u - a_.u), a_.v + t * (b_.v - a_.v)}; }
  std::shared_ptr<const SurfaceGeometry> s_;
  Vec2 a_, b_;
};

// Surface 1: a patch of the unit sphere from the equator to latitude 1.2, a quarter turn wide,
// bounded by four iso-parameter curves with mesh size h at its corners. In the parameter plane
// its top side is 2.8x shorter on the surface than the bottom one.
inline Model spherePatchModel(double h) {
  constexpr double kPi = SphereGeometry::kPi;
  Model model;
  const auto sphere = std::make_shared<SphereGeometry>();
  const std::vector<Vec2> corners{{0, 0}, {kPi / 2, 0}, {kPi / 2, 1.2}, {0, 1.2}};
  ModelSurface patch{1, {{}}, sphere, {}, {}};
  for (int k = 0; k < 4; ++k) model.addPoint({k + 1, sphere->point(corners[k]), h});
  for (int k = 0; k < 4; ++k) {
    model.addCurve({k + 1, k + 1, (k + 1) % 4 + 1,
                    std::make_shared<IsoCurve>(sphere, corners[k], corners[(k + 1) % 4])});
    patch.loops[0].push_back(k + 1);
  }
  model.addSurface(patch);
  return model;
}

// Builds polygonal plane surfaces in z = 0 point by point.
class PolygonModelBuilder {
 public:
  Model model;

  int point(double x, double y, double size = 0) {
    const int tag = ++points_;
    model.addPoint({tag, {x, y, 0}, size});
    return tag;
  }
  int line(int a, int b) {
    const int tag = ++curves_;
    model.addCurve(
        {tag, a, b, std::make_shared<SegmentGeometry>(model.point(a)->xyz, model.point(b)->xyz)});
    return tag;
  }
  // A closed polygon through the given corners (x, y pairs), all with mesh size `size`.
  std::vector<int> polygon(const std::vector<Vec2>& corners, double size) {
    std::vector<int> pts, loop;
    for (Vec2 c : corners) pts.push_back(point(c.u, c.v, size));
    for (std::size_t k = 0; k < pts.size(); ++k)
      loop.push_back(line(pts[k], pts[(k + 1) % pts.size()]));
    return loop;
  }
  std::vector<int> circle(Vec2 center, double radius, double size) {
    const int p = point(center.u + radius, center.v, size);
    const int tag = ++curves_;
    model.addCurve(
        {tag, p, p, std::make_shared<CircleGeometry>(Vec3{center.u, center.v, 0}, radius)});
    return {tag};
  }
  int arc(Vec2 center, double radius, double from, double to, double size) {
    const int a =
        point(center.u + radius * std::cos(from), center.v + radius * std::sin(from), size);
    const int b = point(center.u + radius * std::cos(to), center.v + radius * std::sin(to), size);
    const int tag = ++curves_;
    model.addCurve(
        {tag, a, b,
         std::make_shared<CircleGeometry>(Vec3{center.u, center.v, 0}, radius, from, to)});
    return tag;
  }
  // Loops: the outer one first. The plane's normal is +z, or -z when `flipped`.
  ModelSurface& surface(std::vector<std::vector<int>> loops, bool flipped = false) {
    ModelSurface s;
    s.tag = ++surfaces_;
    s.loops = std::move(loops);
    s.geometry = std::make_shared<FlatGeometry>(flipped ? -1.0 : 1.0);
    return model.addSurface(std::move(s));
  }

 private:
  int points_ = 0, curves_ = 0, surfaces_ = 0;
};

// Sum of the triangle areas of a surface's mesh.
inline double meshArea(const Mesh& mesh, int surfaceTag) {
  const ElementBlock* block = mesh.find({2, surfaceTag})->findBlock(ElementType::Triangle3);
  double area = 0;
  for (std::size_t e = 0; e < block->size(); ++e) {
    const auto n = block->element(e);
    const Vec3 a = mesh.node(n[0]), b = mesh.node(n[1]), c = mesh.node(n[2]);
    area += 0.5 * norm(cross(b - a, c - a));
  }
  return area;
}

// The unit cube: 8 points, 12 lines, 6 planes with outward normals, one volume.
inline Model cubeModel(double h) {
  Model model;
  const Vec3 corners[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                           {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int k = 0; k < 8; ++k) model.addPoint({k + 1, corners[k], h});
  const int faces[6][4] = {{1, 4, 3, 2}, {5, 6, 7, 8}, {1, 2, 6, 5},
                           {3, 4, 8, 7}, {1, 5, 8, 4}, {2, 3, 7, 6}};
  std::map<std::pair<int, int>, int> lines;
  auto line = [&](int a, int b) {
    if (auto it = lines.find({b, a}); it != lines.end()) return -it->second;
    const int tag = static_cast<int>(lines.size()) + 1;
    lines[{a, b}] = tag;
    model.addCurve({tag, a, b, std::make_shared<SegmentGeometry>(corners[a - 1], corners[b - 1])});
    return tag;
  };
  ModelVolume volume{1, {{}}};
  for (int f = 0; f < 6; ++f) {
    std::vector<Vec3> polygon;
    std::vector<int> loop;
    for (int k = 0; k < 4; ++k) {
      polygon.push_back(corners[faces[f][k] - 1]);
      loop.push_back(line(faces[f][k], faces[f][(k + 1) % 4]));
    }
    const PlaneFit fit = fitPlane(polygon);
    auto plane = std::make_shared<PlaneGeometry>(fit.origin, fit.normal);
    for (Vec3 p : polygon) plane->include(p);
    model.addSurface({f + 1, {loop}, plane, {}, {}});
    volume.shells[0].push_back(f + 1);
  }
  model.addVolume(volume);
  return model;
}

}  // namespace geomesh::testing
