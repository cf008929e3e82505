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
