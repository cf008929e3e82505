// spatialOrder: a Hilbert-sorted biased randomized insertion order, by CGAL's spatial_sort.
#include "mesh/core/spatial_sort.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <numeric>

namespace geomesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

// The order of CGAL points by spatial_sort (its BRIO rounds use a fixed seed: deterministic).
template <class Traits, class CgalPoint>
std::vector<std::uint32_t> sortedOrder(std::vector<CgalPoint>& cgalPoints) {
  std::vector<std::size_t> order(cgalPoints.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  CGAL::spatial_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(cgalPoints)));
  std::vector<std::uint32_t> result(order.size());
  std::copy(order.begin(), order.end(), result.begin());
  return result;
}

}  // namespace

std::vector<std::uint32_t> spatialOrder(std::span<const Vec2> points) {
  using Traits =
      CGAL::Spatial_sort_traits_adapter_2<Kernel,
                                          CGAL::Pointer_property_map<Kernel::Point_2>::type>;
  std::vector<Kernel::Point_2> cgalPoints;
  cgalPoints.reserve(points.size());
  for (Vec2 p : points) cgalPoints.emplace_back(p.u, p.v);
  return sortedOrder<Traits>(cgalPoints);
}

std::vector<std::uint32_t> spatialOrder(std::span<const Vec3> points) {
  using Traits =
      CGAL::Spatial_sort_traits_adapter_3<Kernel,
                                          CGAL::Pointer_property_map<Kernel::Point_3>::type>;
  std::vector<Kernel::Point_3> cgalPoints;
  cgalPoints.reserve(points.size());
  for (const Vec3& p : points) cgalPoints.emplace_back(p.x, p.y, p.z);
  return sortedOrder<Traits>(cgalPoints);
}

}  // namespace geomesh
