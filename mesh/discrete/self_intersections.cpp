// selfIntersections: CGAL's box intersection, then an exact triangle-triangle test per pair.
#include "mesh/discrete/self_intersections.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <vector>

namespace geomesh {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::uint32_t>;

Kernel::Point_3 cgal(Vec3 p) { return {p.x, p.y, p.z}; }
Vec3 ours(const Kernel::Point_3& p) { return {p.x(), p.y(), p.z()}; }

bool shareVertex(const TriangleVertices& a, const TriangleVertices& b) {
  for (std::uint32_t v : a)
    if (std::find(b.begin(), b.end(), v) != b.end()) return true;
  return false;
}

// A point of the intersection of two triangles known to intersect.
Vec3 meetingPoint(const Kernel::Triangle_3& a, const Kernel::Triangle_3& b) {
  const auto meet = CGAL::intersection(a, b);
  if (!meet) return ours(CGAL::centroid(a));
  if (const auto* p = boost::get<Kernel::Point_3>(&*meet)) return ours(*p);
  if (const auto* s = boost::get<Kernel::Segment_3>(&*meet))
    return ours(CGAL::midpoint(s->source(), s->target()));
  if (const auto* t = boost::get<Kernel::Triangle_3>(&*meet)) return ours(CGAL::centroid(*t));
  const auto* polygon = boost::get<std::vector<Kernel::Point_3>>(&*meet);
  if (polygon && !polygon->empty()) return ours(polygon->front());
  return ours(CGAL::centroid(a));
}

}  // namespace

SelfIntersections selfIntersections(const Triangulation& t, std::size_t keep) {
  std::vector<Kernel::Triangle_3> triangles;
  std::vector<Box> boxes;  // of the triangles that are not degenerate, which cross nothing
  triangles.reserve(t.triangles.size());
  boxes.reserve(t.triangles.size());
  for (std::uint32_t k = 0; k < t.triangles.size(); ++k) {
    const TriangleVertices& v = t.triangles[k];
    triangles.emplace_back(cgal(t.points[v[0]]), cgal(t.points[v[1]]), cgal(t.points[v[2]]));
    if (!triangles.back().is_degenerate()) boxes.emplace_back(triangles.back().bbox(), k);
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> crossing;
  auto test = [&](const Box& a, const Box& b) {
    const std::uint32_t i = std::min(a.info(), b.info()), j = std::max(a.info(), b.info());
    if (shareVertex(t.triangles[i], t.triangles[j])) return;
    if (CGAL::do_intersect(triangles[i], triangles[j])) crossing.emplace_back(i, j);
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), test);
  std::sort(crossing.begin(), crossing.end());
  SelfIntersections out;
  out.count = crossing.size();
  for (std::size_t k = 0; k < crossing.size() && k < keep; ++k) {
    out.pairs.push_back(crossing[k]);
    out.points.push_back(
        meetingPoint(triangles[crossing[k].first], triangles[crossing[k].second]));
  }
  return out;
}

}  // namespace geomesh
