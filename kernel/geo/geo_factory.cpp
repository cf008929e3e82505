#include "kernel/geo/geo_factory.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "kernel/geo/geo_fail.h"
#include "kernel/plane_geometry.h"

namespace geomesh {

namespace {

using geo_detail::fail;
using geo_detail::requireNew;

// The curves of a loop are reordered so that each one starts where the previous one ends; the
// first curve stays first and no curve is reversed (a wrongly signed curve is an error).
template <class EndsOf>
std::vector<int> chainLoop(int loopTag, std::vector<int> remaining, const EndsOf& endsOf) {
  std::vector<int> chain{remaining.front()};
  remaining.erase(remaining.begin());
  while (!remaining.empty()) {
    const int end = endsOf(chain.back())[1];
    auto next = std::find_if(remaining.begin(), remaining.end(),
                             [&](int c) { return endsOf(c)[0] == end; });
    if (next == remaining.end())
      fail("Curve loop ", loopTag, " is not a chain: curve ", chain.back(), " ends at point ",
           end, " and no other curve of the loop starts there");
    chain.push_back(*next);
    remaining.erase(next);
  }
  const int last = endsOf(chain.back())[1], first = endsOf(chain.front())[0];
  if (last != first)
    fail("Curve loop ", loopTag, " does not close: gap between point ", last, " (end of curve ",
         chain.back(), ") and point ", first, " (start of curve ", chain.front(), ")");
  return chain;
}

std::vector<int> reversedLoop(std::vector<int> loop) {
  std::reverse(loop.begin(), loop.end());
  for (int& c : loop) c = -c;
  return loop;
}

}  // namespace

void GeoFactory::addPoint(int tag, Vec3 xyz, double meshSize) {
  requireNew(points_, tag, "Point");
  if (!std::isfinite(xyz.x) || !std::isfinite(xyz.y) || !std::isfinite(xyz.z))
    fail("Point ", tag, ": its coordinates are not finite numbers");
  points_[tag] = ModelPoint{tag, xyz, meshSize};
  bounds_.include(xyz);
}

void GeoFactory::addLine(int tag, int startPoint, int endPoint) {
  requireNew(curves_, tag, "Curve");
  for (int p : {startPoint, endPoint})
    if (!hasPoint(p)) fail("Line ", tag, ": point ", p, " is not defined");
  if (startPoint == endPoint)
    fail("Line ", tag, ": both ends are point ", startPoint);
  if (distance(points_.at(startPoint).xyz, points_.at(endPoint).xyz) <= absoluteTolerance())
    fail("Line ", tag, ": points ", startPoint, " and ", endPoint, " coincide");
  curves_[tag] = Curve{tag, CurveKind::Line, {startPoint, endPoint}};
}

void GeoFactory::addCurveLoop(int tag, std::vector<int> curves) {
  requireNew(curveLoops_, tag, "Curve loop");
  if (curves.empty()) fail("Curve loop ", tag, " is empty");
  for (int c : curves)
    if (!curves_.contains(std::abs(c)))
      fail("Curve loop ", tag, ": curve ", std::abs(c), " is not defined");
  curveLoops_[tag] = chainLoop(tag, std::move(curves), [this](int c) { return curveEnds(c); });
}

void GeoFactory::addPlaneSurface(int tag, std::vector<int> curveLoops) {
  requireNew(surfaces_, tag, "Surface");
  if (curveLoops.empty()) fail("Plane surface ", tag, " has no curve loop");
  for (int l : curveLoops)
    if (!curveLoops_.contains(std::abs(l)))
      fail("Plane surface ", tag, ": curve loop ", std::abs(l), " is not defined");
  auto geometry = fitPlaneSurface(tag, curveLoops);
  surfaces_[tag] = Surface{tag, std::move(curveLoops), std::move(geometry)};
}

void GeoFactory::addSurfaceLoop(int tag, std::vector<int> surfaces) {
  requireNew(surfaceLoops_, tag, "Surface loop");
  if (surfaces.empty()) fail("Surface loop ", tag, " is empty");
  for (int s : surfaces)
    if (!surfaces_.contains(std::abs(s)))
      fail("Surface loop ", tag, ": surface ", std::abs(s), " is not defined");
  checkShellClosed(tag, surfaces);
  surfaceLoops_[tag] = std::move(surfaces);
}

void GeoFactory::addVolume(int tag, std::vector<int> surfaceLoops) {
  requireNew(volumes_, tag, "Volume");
  if (surfaceLoops.empty()) fail("Volume ", tag, " has no surface loop");
  for (int l : surfaceLoops)
    if (!surfaceLoops_.contains(std::abs(l)))
      fail("Volume ", tag, ": surface loop ", std::abs(l), " is not defined");
  volumes_[tag] = Volume{tag, std::move(surfaceLoops)};
}

void GeoFactory::addPhysicalGroup(int dim, int tag, const std::string& name,
                                  const std::vector<int>& entities) {
  if (dim < 0 || dim > 3) fail("Physical group ", tag, ": invalid dimension ", dim);
  PhysicalGroup& group = physicals_[{dim, tag}];
  group.dim = dim;
  group.tag = tag;
  if (!name.empty()) group.name = name;
  for (int e : entities)
    if (std::find(group.entities.begin(), group.entities.end(), e) == group.entities.end())
      group.entities.push_back(e);
}

bool GeoFactory::hasPoint(int tag) const { return points_.contains(tag); }

Vec3 GeoFactory::pointCoordinates(int tag) const {
  auto it = points_.find(tag);
  if (it == points_.end()) fail("Point ", tag, " is not defined");
  return it->second.xyz;
}

int GeoFactory::maxTag(int kind) const {
  auto last = [](const auto& m) { return m.empty() ? 0 : m.rbegin()->first; };
  switch (kind) {
    case 0: return last(points_);
    case 1: return last(curves_);
    case 2: return last(surfaces_);
    case 3: return last(volumes_);
    case kCurveLoop: return last(curveLoops_);
    case kSurfaceLoop: return last(surfaceLoops_);
    default: return 0;
  }
}

void GeoFactory::clear() {
  const double tolerance = tolerance_;
  *this = GeoFactory();
  tolerance_ = tolerance;
}

double GeoFactory::absoluteTolerance() const {
  const double size = bounds_.empty() ? 0.0 : distance(bounds_.min, bounds_.max);
  return tolerance_ * (size > 0 ? size : 1.0);
}

std::array<int, 2> GeoFactory::curveEnds(int signedCurve) const {
  const Curve& c = curves_.at(std::abs(signedCurve));
  return signedCurve > 0 ? std::array{c.start(), c.end()} : std::array{c.end(), c.start()};
}

std::vector<Vec3> GeoFactory::loopSamples(int signedLoop) const {
  constexpr int kArcSamples = 16;
  std::vector<Vec3> samples;
  for (int c : loopCurves(signedLoop)) {
    const Curve& curve = curves_.at(std::abs(c));
    samples.push_back(points_.at(curveEnds(c)[0]).xyz);
    if (curve.kind == CurveKind::Line) continue;
    const auto geometry = curveGeometry(curve);
    for (int i = 1; i < kArcSamples; ++i) {
      const double t = static_cast<double>(i) / kArcSamples;
      samples.push_back(geometry->point(c > 0 ? t : 1 - t));
    }
  }
  return samples;
}

std::vector<int> GeoFactory::loopCurves(int signedLoop) const {
  const std::vector<int>& loop = curveLoops_.at(std::abs(signedLoop));
  return signedLoop > 0 ? loop : reversedLoop(loop);
}

// The plane is fitted to the outer loop (its normal follows the loop's orientation, so the
// loop runs counter-clockwise in the plane's parameters); every loop must lie on it. Arcs are
// sampled, so that both the fit and the check see their shape.
std::shared_ptr<const SurfaceGeometry> GeoFactory::fitPlaneSurface(
    int tag, const std::vector<int>& loops) const {
  const PlaneFit fit = fitPlane(loopSamples(loops.front()));
  if (norm(fit.normal) == 0)
    fail("Plane surface ", tag, ": curve loop ", std::abs(loops.front()), " encloses no area");
  auto plane = std::make_shared<PlaneGeometry>(fit.origin, fit.normal);
  const double tolerance = absoluteTolerance();
  for (int loop : loops)
    for (Vec3 xyz : loopSamples(loop)) {
      const double offset = std::abs(dot(xyz - fit.origin, fit.normal));
      if (offset > tolerance)
        fail("Plane surface ", tag, " is not plane: curve loop ", std::abs(loop),
             " passes ", offset, " away from the plane of curve loop ", std::abs(loops.front()));
      plane->include(xyz);
    }
  return plane;
}

// A closed shell uses each curve of its surfaces' boundaries exactly twice.
void GeoFactory::checkShellClosed(int tag, const std::vector<int>& surfaces) const {
  std::map<int, std::vector<int>> surfacesOfCurve;
  for (int s : surfaces)
    for (int loop : surfaces_.at(std::abs(s)).loops)
      for (int c : curveLoops_.at(std::abs(loop))) surfacesOfCurve[std::abs(c)].push_back(s);
  for (const auto& [curve, users] : surfacesOfCurve)
    if (users.size() != 2)
      fail("Surface loop ", tag, " is not closed: curve ", curve, " bounds ", users.size(),
           users.size() == 1 ? " of its surfaces (surface " : " of its surfaces (surfaces ",
           std::abs(users.front()), users.size() == 1 ? ")" : ", ...)");
}

void GeoFactory::synchronize(Model& model) const {
  model.clear();
  for (const auto& [tag, p] : points_) model.addPoint(p);
  for (const auto& [tag, c] : curves_)
    model.addCurve(ModelCurve{tag, c.start(), c.end(), curveGeometry(c)});
  for (const auto& [tag, s] : surfaces_) {
    // Holes run against the direction they were given in, as the built-in kernel of Gmsh
    // lists them (whatever that direction was).
    ModelSurface surface{tag, {}, s.geometry, {}, {}};
    for (std::size_t i = 0; i < s.loops.size(); ++i)
      surface.loops.push_back(loopCurves(i == 0 ? s.loops[i] : -s.loops[i]));
    model.addSurface(std::move(surface));
  }
  for (const auto& [tag, v] : volumes_) {
    ModelVolume volume{tag, {}};
    for (int loop : v.shells) {
      std::vector<int> shell = surfaceLoops_.at(std::abs(loop));
      if (loop < 0)
        for (int& s : shell) s = -s;
      volume.shells.push_back(std::move(shell));
    }
    model.addVolume(std::move(volume));
  }
  for (const auto& [id, group] : physicals_) {
    PhysicalGroup kept = group;
    const int dim = id.dim;
    std::erase_if(kept.entities, [&](int e) { return !model.contains({dim, std::abs(e)}); });
    model.addPhysicalGroup(std::move(kept));
  }
}

}  // namespace geomesh
