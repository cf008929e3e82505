// GeoFactory: points, lines, curve loops chained as Gmsh does, surfaces, volumes and tags.
#include "kernel/geo/geo_factory.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "kernel/geo/geo_detail.h"

namespace geomesh {

namespace {

using geo_detail::fail;
using geo_detail::requireNew;

// The curves of a loop are reordered so that each one starts where the previous one ends; the
// first curve stays first and no curve is reversed (a wrongly signed curve is an error). As in
// Gmsh, a loop may hold several closed chains (a boundary and its holes), one after the other.
template <class EndsOf>
std::vector<int> chainLoop(int loopTag, std::vector<int> remaining, const EndsOf& endsOf) {
  std::vector<int> chain{remaining.front()};
  std::size_t chainStart = 0;  // where the chain being followed begins
  remaining.erase(remaining.begin());
  auto closes = [&] { return endsOf(chain.back())[1] == endsOf(chain[chainStart])[0]; };
  while (!remaining.empty()) {
    const int end = endsOf(chain.back())[1];
    auto next = std::find_if(remaining.begin(), remaining.end(),
                             [&](int c) { return endsOf(c)[0] == end; });
    if (next == remaining.end() && closes()) {
      chainStart = chain.size();
      next = remaining.begin();
    } else if (next == remaining.end()) {
      fail("Curve loop ", loopTag, " is not a chain: curve ", chain.back(), " ends at point ",
           end, " and no other curve of the loop starts there");
    }
    chain.push_back(*next);
    remaining.erase(next);
  }
  if (!closes())
    fail("Curve loop ", loopTag, " does not close: gap between point ", endsOf(chain.back())[1],
         " (end of curve ", chain.back(), ") and point ", endsOf(chain[chainStart])[0],
         " (start of curve ", chain[chainStart], ")");
  return chain;
}

// The closed chains a chained loop is made of, in order.
template <class EndsOf>
std::vector<std::vector<int>> closedChains(const std::vector<int>& loop, const EndsOf& endsOf) {
  std::vector<std::vector<int>> chains;
  for (int c : loop) {
    if (chains.empty() || endsOf(chains.back().back())[1] == endsOf(chains.back().front())[0])
      chains.emplace_back();
    chains.back().push_back(c);
  }
  return chains;
}

}  // namespace

void GeoFactory::addPoint(int tag, Vec3 xyz, double meshSize) {
  requireNew(points_, tag, "Point");
  if (!std::isfinite(xyz.x) || !std::isfinite(xyz.y) || !std::isfinite(xyz.z))
    fail("Point ", tag, ": its coordinates are not finite numbers");
  points_[tag] = ModelPoint{tag, xyz, meshSize};
  bounds_.include(xyz);
  noteTag(0, tag);
}

void GeoFactory::addLine(int tag, int startPoint, int endPoint) {
  requireNew(curves_, tag, "Curve");
  for (int p : {startPoint, endPoint})
    if (!hasPoint(p)) fail("Line ", tag, ": point ", p, " is not defined");
  // A line from a point to itself makes no curve; its tag counts as used, as the script's
  // later tags (newl) expect.
  if (startPoint == endPoint) return noteTag(1, tag);
  if (distance(points_.at(startPoint).xyz, points_.at(endPoint).xyz) <= absoluteTolerance())
    fail("Line ", tag, ": points ", startPoint, " and ", endPoint, " coincide");
  curves_[tag] = Curve{tag, CurveKind::Line, {startPoint, endPoint}};
  noteTag(1, tag);
}

void GeoFactory::addCurveLoop(int tag, std::vector<int> curves) {
  requireNew(curveLoops_, tag, "Curve loop");
  if (curves.empty()) fail("Curve loop ", tag, " is empty");
  for (int c : curves)
    if (!curves_.contains(std::abs(c)))
      fail("Curve loop ", tag, ": curve ", std::abs(c), " is not defined");
  curveLoops_[tag] = chainLoop(tag, std::move(curves), [this](int c) { return curveEnds(c); });
  noteTag(kCurveLoop, tag);
}

std::vector<std::vector<int>> GeoFactory::surfaceLoopsOf(int tag,
                                                         const std::vector<int>& curveLoops,
                                                         const char* what) const {
  if (curveLoops.empty()) fail(what, " ", tag, " has no curve loop");
  std::vector<std::vector<int>> loops;
  for (int l : curveLoops) {
    if (!curveLoops_.contains(std::abs(l)))
      fail(what, " ", tag, ": curve loop ", std::abs(l), " is not defined");
    // Holes run against the direction they were given in, as the built-in kernel of Gmsh
    // stores them (whatever that direction was).
    const std::vector<int> curves = loopCurves(loops.empty() ? l : -l);
    for (int c : curves)
      if (!curves_.contains(std::abs(c)))
        fail(what, " ", tag, ": curve ", std::abs(c), " of curve loop ", std::abs(l),
             " has been deleted");
    for (std::vector<int>& chain :
         closedChains(curves, [this](int c) { return curveEnds(c); }))
      loops.push_back(std::move(chain));
  }
  return loops;
}

void GeoFactory::addPlaneSurface(int tag, std::vector<int> curveLoops) {
  requireNew(surfaces_, tag, "Surface");
  auto loops = surfaceLoopsOf(tag, curveLoops, "Plane surface");
  // Loops a little off their mean plane are meshed on it (planeDeviation says by how much);
  // loops far from any plane are an error.
  const double deviation = fitPlaneSurface(tag, loops).second;
  BoundingBox box;
  for (Vec3 xyz : loopSamples(loops.front())) box.include(xyz);
  const double size = distance(box.min, box.max);
  if (deviation > absoluteTolerance() && deviation > kPlaneDeviationLimit * size)
    fail("Plane surface ", tag, " is not plane: its loops pass ", deviation,
         " away from their mean plane, more than ", 100 * kPlaneDeviationLimit,
         "% of the outer loop's size ", size);
  surfaces_[tag] = Surface{tag, SurfaceKind::Plane, std::move(loops), std::move(curveLoops)};
  noteTag(2, tag);
}

void GeoFactory::addFillingSurface(int tag, std::vector<int> curveLoops,
                                   const std::vector<int>& /*through*/) {
  requireNew(surfaces_, tag, "Surface");
  auto loops = surfaceLoopsOf(tag, curveLoops, "Surface");
  if (loops.size() != 1) fail("Surface ", tag, ": a filling surface cannot have holes");
  if (loops[0].size() != 3 && loops[0].size() != 4)
    fail("Surface ", tag, ": curve loop ", std::abs(curveLoops[0]), " has ", loops[0].size(),
         " curves; a filling surface needs 3 or 4");
  surfaces_[tag] = Surface{tag, SurfaceKind::Filling, std::move(loops), std::move(curveLoops)};
  noteTag(2, tag);
}

void GeoFactory::addSurfaceLoop(int tag, std::vector<int> surfaces) {
  requireNew(surfaceLoops_, tag, "Surface loop");
  if (surfaces.empty()) fail("Surface loop ", tag, " is empty");
  for (int s : surfaces)
    if (!surfaces_.contains(std::abs(s)))
      fail("Surface loop ", tag, ": surface ", std::abs(s), " is not defined");
  // Closure is checked by the volume: as in the reference, a volume's loops need only be
  // closed together (an outer shell and an inner one may share their edges).
  surfaceLoops_[tag] = std::move(surfaces);
  noteTag(kSurfaceLoop, tag);
}

void GeoFactory::addVolume(int tag, std::vector<int> surfaceLoops) {
  requireNew(volumes_, tag, "Volume");
  if (surfaceLoops.empty()) fail("Volume ", tag, " has no surface loop");
  Volume volume{tag, {}, surfaceLoops};
  for (int l : surfaceLoops) {
    if (!surfaceLoops_.contains(std::abs(l)))
      fail("Volume ", tag, ": surface loop ", std::abs(l), " is not defined");
    std::vector<int> shell = surfaceLoops_.at(std::abs(l));
    for (int s : shell)
      if (!surfaces_.contains(std::abs(s)))
        fail("Volume ", tag, ": surface ", std::abs(s), " of surface loop ", std::abs(l),
             " has been deleted");
    if (l < 0)
      for (int& s : shell) s = -s;
    volume.shells.push_back(std::move(shell));
  }
  std::vector<int> all;
  for (const auto& shell : volume.shells) all.insert(all.end(), shell.begin(), shell.end());
  checkShellClosed(tag, surfaceLoops, all);
  volumes_[tag] = std::move(volume);
  noteTag(3, tag);
}

void GeoFactory::addPhysicalGroup(int dim, int tag, const std::string& name,
                                  const std::vector<int>& entities) {
  if (dim < 0 || dim > 3) fail("Physical group ", tag, ": invalid dimension ", dim);
  PhysicalGroup& group = physicals_[{dim, tag}];
  group.dim = dim;
  group.tag = tag;
  if (!name.empty()) group.name = name;
  // As in Gmsh, a group holds each entity once, in ascending tags.
  group.entities.insert(group.entities.end(), entities.begin(), entities.end());
  std::sort(group.entities.begin(), group.entities.end());
  group.entities.erase(std::unique(group.entities.begin(), group.entities.end()),
                       group.entities.end());
}

void GeoFactory::removeFromPhysicalGroup(int dim, int tag, const std::vector<int>& entities) {
  auto it = physicals_.find({dim, tag});
  if (it == physicals_.end()) return;
  std::erase_if(it->second.entities, [&](int e) {
    return std::find(entities.begin(), entities.end(), e) != entities.end();
  });
  if (it->second.entities.empty()) physicals_.erase(it);
}

void GeoFactory::setMeshSize(const std::vector<int>& points, double size) {
  for (int p : points)
    if (!hasPoint(p)) fail("MeshSize: point ", p, " is not defined");
  for (int p : points) points_.at(p).meshSize = size;
}

void GeoFactory::addCompound(int dim, const std::vector<int>& tags) {
  for (int t : tags)
    if (!contains({dim, t})) fail("Compound: ", dim == 1 ? "curve " : "surface ", t,
                                  " is not defined");
  for (int t : tags) {
    if (dim == 1) curves_.at(t).compound = tags;
    if (dim == 2) surfaces_.at(t).compound = tags;
  }
}

std::vector<int> GeoFactory::tags(int dim) const {
  std::vector<int> tags;
  auto collect = [&](const auto& map) {
    for (const auto& entry : map) tags.push_back(entry.first);
  };
  if (dim == 0) collect(points_);
  if (dim == 1) collect(curves_);
  if (dim == 2) collect(surfaces_);
  if (dim == 3) collect(volumes_);
  return tags;
}

bool GeoFactory::contains(EntityId e) const {
  switch (e.dim) {
    case 0: return points_.contains(e.tag);
    case 1: return curves_.contains(e.tag);
    case 2: return surfaces_.contains(e.tag);
    case 3: return volumes_.contains(e.tag);
    default: return false;
  }
}

Vec3 GeoFactory::pointCoordinates(int tag) const {
  auto it = points_.find(tag);
  if (it == points_.end()) fail("Point ", tag, " is not defined");
  return it->second.xyz;
}

int GeoFactory::maxTag(int kind) const {
  return kind >= 0 && kind < 6 ? highWater_[static_cast<std::size_t>(kind)] : 0;
}

void GeoFactory::noteTag(int kind, int tag) {
  int& mark = highWater_[static_cast<std::size_t>(kind)];
  mark = std::max(mark, tag);
}

int GeoFactory::newPointTag() { return ++highWater_[0]; }

int GeoFactory::newRegionTag(int kind) {
  int region = 0;
  for (int k = 1; k < 6; ++k) region = std::max(region, maxTag(k));
  for (const auto& [id, group] : physicals_) region = std::max(region, id.tag);
  noteTag(kind, region + 1);
  return region + 1;
}

int GeoFactory::newVolumeTag() { return ++highWater_[3]; }

// Entities go; the options (tolerance, coherence, extrusion settings) stay.
void GeoFactory::clear() {
  GeoFactory empty;
  empty.tolerance_ = tolerance_;
  empty.autoCoherence_ = autoCoherence_;
  empty.returnLaterals_ = returnLaterals_;
  empty.twistSteps_ = twistSteps_;
  *this = std::move(empty);
}

double GeoFactory::absoluteTolerance() const {
  const double size = bounds_.empty() ? 0.0 : distance(bounds_.min, bounds_.max);
  return tolerance_ * (size > 0 ? size : 1.0);
}

std::array<int, 2> GeoFactory::curveEnds(int signedCurve) const {
  const Curve& c = curves_.at(std::abs(signedCurve));
  return signedCurve >= 0 ? std::array{c.start(), c.end()} : std::array{c.end(), c.start()};
}

std::vector<int> GeoFactory::loopCurves(int signedLoop) const {
  const std::vector<int>& loop = curveLoops_.at(std::abs(signedLoop));
  return signedLoop >= 0 ? loop : geo_detail::reversedChain(loop);
}

// A closed shell uses each curve of its surfaces' boundaries exactly twice.
void GeoFactory::checkShellClosed(int volume, const std::vector<int>& loops,
                                  const std::vector<int>& surfaces) const {
  std::map<int, std::vector<int>> surfacesOfCurve;
  for (int s : surfaces)
    for (const auto& loop : surfaces_.at(std::abs(s)).loops)
      for (int c : loop) surfacesOfCurve[std::abs(c)].push_back(s);
  for (const auto& [curve, users] : surfacesOfCurve)
    if (users.size() != 2)
      fail(loops.size() == 1 ? "Surface loop " + std::to_string(std::abs(loops[0]))
                             : "Volume " + std::to_string(volume) + ": its surface loops",
           loops.size() == 1 ? " is not closed" : " are not closed", ": curve ", curve, " bounds ",
           users.size(),
           users.size() == 1 ? " of its surfaces (surface " : " of its surfaces (surfaces ",
           std::abs(users.front()), users.size() == 1 ? ")" : ", ...)");
}

}  // namespace geomesh
