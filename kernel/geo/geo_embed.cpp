// Embedded entities and periodicity constraints of the built-in kernel.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <utility>

#include "kernel/geo/geo_detail.h"
#include "kernel/geo/geo_factory.h"

namespace geomesh {

using geo_detail::fail;

namespace {

void appendAll(std::vector<int>& to, const std::vector<int>& tags) {
  for (int t : tags)
    if (std::find(to.begin(), to.end(), std::abs(t)) == to.end()) to.push_back(std::abs(t));
}

// An orthonormal frame from three points that are not collinear: the first axis along b - a,
// the second in the plane of the three.
std::array<Vec3, 3> frameOf(Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 e1 = (b - a) / norm(b - a);
  const Vec3 side = (c - a) - dot(c - a, e1) * e1;
  const Vec3 e2 = side / norm(side);
  return {e1, e2, cross(e1, e2)};
}

// The rigid motion taking each pair's first point onto its second, or nullopt when there is
// none (within `tolerance`): a translation when all the displacements agree, else the motion
// fixed by three pairs far from collinear, checked on all of them.
std::optional<AffineMap> rigidMotion(const std::vector<std::pair<Vec3, Vec3>>& pairs,
                                     double tolerance) {
  if (pairs.empty()) return std::nullopt;
  const Vec3 shift = pairs[0].second - pairs[0].first;
  AffineMap map = AffineMap::translation(shift);
  auto fits = [&] {
    return std::all_of(pairs.begin(), pairs.end(), [&](const auto& p) {
      return distance(map.apply(p.first), p.second) <= tolerance;
    });
  };
  if (fits()) return map;
  const Vec3 a = pairs[0].first;
  std::size_t far = 0, wide = 0;
  for (std::size_t k = 1; k < pairs.size(); ++k)
    if (distance(pairs[k].first, a) > distance(pairs[far].first, a)) far = k;
  const Vec3 axis = pairs[far].first - a;
  auto offAxis = [&](std::size_t k) { return norm(cross(pairs[k].first - a, axis)); };
  for (std::size_t k = 1; k < pairs.size(); ++k)
    if (offAxis(k) > offAxis(wide)) wide = k;
  if (!(offAxis(wide) > tolerance * norm(axis))) return std::nullopt;
  const auto from = frameOf(a, pairs[far].first, pairs[wide].first);
  const auto to = frameOf(pairs[0].second, pairs[far].second, pairs[wide].second);
  // Rotation R = sum over axes of to[i] from[i]^T; translation takes a onto its image.
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      double sum = 0;
      for (int i = 0; i < 3; ++i) {
        const double t[3] = {to[i].x, to[i].y, to[i].z}, f[3] = {from[i].x, from[i].y, from[i].z};
        sum += t[r] * f[c];
      }
      map.m[static_cast<std::size_t>(4 * r + c)] = sum;
    }
  map.m[3] = map.m[7] = map.m[11] = 0;
  const Vec3 moved = map.apply(a);
  map.m[3] = pairs[0].second.x - moved.x;
  map.m[7] = pairs[0].second.y - moved.y;
  map.m[11] = pairs[0].second.z - moved.z;
  if (!fits()) return std::nullopt;
  return map;
}

}  // namespace

void GeoFactory::setPeriodicByCurves(int slave, const std::vector<int>& slaveCurves, int master,
                                     const std::vector<int>& masterCurves) {
  requireShape({2, slave}, "Periodic");
  requireShape({2, master}, "Periodic");
  if (slaveCurves.size() != masterCurves.size() || slaveCurves.empty())
    fail("Periodic Surface ", slave, ": ", slaveCurves.size(), " curves cannot match ",
         masterCurves.size());
  std::map<int, int> imageOf;  // master point -> slave point
  for (std::size_t k = 0; k < slaveCurves.size(); ++k) {
    requireShape({1, slaveCurves[k]}, "Periodic");
    requireShape({1, masterCurves[k]}, "Periodic");
    const auto s = curveEnds(slaveCurves[k]), m = curveEnds(masterCurves[k]);
    for (int end = 0; end < 2; ++end) {
      const auto [it, inserted] = imageOf.emplace(m[end], s[end]);
      if (!inserted && it->second != s[end])
        fail("Periodic Surface ", slave, ": point ", m[end], " of surface ", master,
             " would go to both point ", it->second, " and point ", s[end]);
    }
  }
  std::vector<std::pair<Vec3, Vec3>> pairs;
  for (const auto& [from, to] : imageOf)
    pairs.emplace_back(points_.at(from).xyz, points_.at(to).xyz);
  const std::optional<AffineMap> map = rigidMotion(pairs, absoluteTolerance());
  if (!map)
    fail("Periodic Surface ", slave, ": its curves are not the image of those of surface ", master,
         " by a translation or a rotation");
  setPeriodic(2, {slave}, {master}, *map);
}

void GeoFactory::embed(int dim, const std::vector<int>& tags, int hostDim, int hostTag) {
  if (dim < 0 || hostDim > 3 || dim >= hostDim || hostDim < 1)
    fail("In: cannot embed entities of dimension ", dim, " in dimension ", hostDim);
  requireShape({hostDim, hostTag}, "In");
  for (int t : tags) requireShape({dim, t}, "In");
  hostTag = std::abs(hostTag);
  if (hostDim == 1) {
    appendAll(curves_.at(hostTag).embeddedPoints, tags);
  } else if (hostDim == 2) {
    Surface& s = surfaces_.at(hostTag);
    appendAll(dim == 0 ? s.embeddedPoints : s.embeddedCurves, tags);
  } else {
    Volume& v = volumes_.at(hostTag);
    appendAll(dim == 0 ? v.embeddedPoints : dim == 1 ? v.embeddedCurves : v.embeddedSurfaces,
              tags);
  }
}

void GeoFactory::setPeriodic(int dim, const std::vector<int>& slaves,
                             const std::vector<int>& masters, const AffineMap& map) {
  if (dim != 1 && dim != 2) fail("Periodic: only curves and surfaces can be periodic");
  if (slaves.size() != masters.size())
    fail("Periodic: ", slaves.size(), " entities cannot match ", masters.size());
  for (std::size_t i = 0; i < slaves.size(); ++i) {
    requireShape({dim, slaves[i]}, "Periodic");
    requireShape({dim, masters[i]}, "Periodic");
    const auto h = map.homogeneous();
    Periodicity periodic{std::abs(masters[i]), std::vector<double>(h.begin(), h.end())};
    if (dim == 1) curves_.at(std::abs(slaves[i])).periodic = periodic;
    else surfaces_.at(std::abs(slaves[i])).periodic = periodic;
  }
}

}  // namespace geomesh
