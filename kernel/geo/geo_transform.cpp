// Transformations, copies, deletion and topological queries of the built-in kernel.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>

#include "kernel/geo/geo_detail.h"
#include "kernel/geo/geo_factory.h"

namespace geomesh {

using geo_detail::fail;

namespace {

const char* dimensionName(int dim) {
  static constexpr const char* kNames[] = {"Point", "Curve", "Surface", "Volume"};
  return dim >= 0 && dim <= 3 ? kNames[dim] : "Entity";
}

void appendOnce(std::vector<int>& out, int tag) {
  if (std::find(out.begin(), out.end(), tag) == out.end()) out.push_back(tag);
}

bool isIdentityLinearPart(const AffineMap& map) {
  return map.m[0] == 1 && map.m[1] == 0 && map.m[2] == 0 && map.m[4] == 0 && map.m[5] == 1 &&
         map.m[6] == 0 && map.m[8] == 0 && map.m[9] == 0 && map.m[10] == 1;
}

}  // namespace

void GeoFactory::requireShape(EntityId shape, const char* operation) const {
  if (!contains({shape.dim, std::abs(shape.tag)}))
    fail(operation, ": ", dimensionName(shape.dim), " ", std::abs(shape.tag),
         " is not defined");
}

void GeoFactory::requireGeometric(EntityId shape, const char* operation) const {
  requireShape(shape, operation);
  static constexpr const char* kLowerNames[] = {"point", "curve", "surface"};
  const int tag = std::abs(shape.tag);
  if (shape.dim < 3 && isDiscrete({shape.dim, tag}))
    fail(operation, ": ", kLowerNames[shape.dim], " ", tag,
         " comes from a merged mesh file; its triangles cannot be moved, copied or extruded");
  if (shape.dim != 3) return;
  for (const auto& shell : volumes_.at(tag).shells)
    for (int s : shell)
      if (isDiscrete({2, std::abs(s)}))
        fail(operation, ": surface ", std::abs(s),
             " comes from a merged mesh file; its triangles cannot be moved, copied or extruded");
}

// Every point the shape's geometry depends on: the control points of its curves included
// (appended with repeats; see pointsUnder).
void GeoFactory::collectPoints(EntityId shape, std::vector<int>& out) const {
  const int tag = std::abs(shape.tag);
  switch (shape.dim) {
    case 0: out.push_back(tag); break;
    case 1: {
      const auto& points = curves_.at(tag).points;
      out.insert(out.end(), points.begin(), points.end());
      break;
    }
    case 2:
      for (const auto& loop : surfaces_.at(tag).loops)
        for (int c : loop) collectPoints({1, c}, out);
      break;
    case 3:
      for (const auto& shell : volumes_.at(tag).shells)
        for (int s : shell) collectPoints({2, s}, out);
      break;
    default: break;
  }
}

std::vector<int> GeoFactory::pointsUnder(const std::vector<EntityId>& shapes) const {
  std::vector<int> points;
  for (EntityId shape : shapes) collectPoints(shape, points);
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

void GeoFactory::transform(const std::vector<EntityId>& shapes, const AffineMap& map) {
  for (EntityId shape : shapes) requireGeometric(shape, "Transformation");
  for (double x : map.m)
    if (!std::isfinite(x)) fail("Transformation: its parameters are not finite numbers");
  if (!std::isfinite(map.pivot.x) || !std::isfinite(map.pivot.y) || !std::isfinite(map.pivot.z))
    fail("Transformation: its center is not a finite point");
  const std::vector<int> moved = pointsUnder(shapes);
  std::map<int, Vec3> image;
  for (int p : moved) image[p] = map.apply(points_.at(p).xyz);
  if (!isIdentityLinearPart(map)) checkArcsStayCircular(image);
  for (const auto& [p, xyz] : image) {
    points_.at(p).xyz = xyz;
    bounds_.include(xyz);
  }
  if (!isIdentityLinearPart(map)) {
    // A swept surface keeps its exact shape only under translations; otherwise it falls back
    // to interpolating its (moved) boundary.
    const std::set<int> movedSet(moved.begin(), moved.end());
    for (auto& [tag, surface] : surfaces_) {
      std::vector<int> own;
      collectPoints({2, tag}, own);
      if (surface.sweep &&
          std::any_of(own.begin(), own.end(), [&](int p) { return movedSet.contains(p); }))
        surface.sweep.reset();
    }
  }
  if (autoCoherence_) coherence();
}

// A transformation that does not keep distances (a dilation by different factors, a shear)
// can break circle arcs: their ends must stay at about the same distance from the center.
void GeoFactory::checkArcsStayCircular(const std::map<int, Vec3>& image) const {
  auto where = [&](int p) {
    auto it = image.find(p);
    return it != image.end() ? it->second : points_.at(p).xyz;
  };
  for (const auto& [tag, curve] : curves_) {
    if (curve.kind != CurveKind::CircleArc) continue;
    const auto& p = curve.points;
    if (!image.contains(p[0]) && !image.contains(p[1]) && !image.contains(p[2])) continue;
    const double r1 = distance(where(p[0]), where(p[1])), r2 = distance(where(p[2]), where(p[1]));
    if (std::abs(r1 - r2) > 0.1 * std::max(r1, r2))
      fail("Transformation: circle ", tag, " would no longer be circular (radii ", r1, " and ",
           r2, " around point ", p[1], ")");
  }
}

int GeoFactory::copyPoint(int tag) {
  const int copy = newPointTag();
  ModelPoint point = points_.at(tag);
  point.tag = copy;
  points_[copy] = point;
  if (layerCopyIndex_ >= 0) layerPoints_[copy] = {tag, layerCopyIndex_};
  return copy;
}

// As the built-in kernel of Gmsh does, the copy gets its own copies of every control point,
// and two more tags are spent on its end points (merged with the former by Coherence). A
// negative tag copies the reversed curve (as a curve of positive tag).
int GeoFactory::copyCurve(int signedTag) {
  const int copy = newRegionTag(1);
  Curve curve = curves_.at(std::abs(signedTag));
  curve.tag = copy;
  if (signedTag < 0) curve.points = reversedPoints(curve);
  for (int& p : curve.points) p = copyPoint(p);
  newPointTag();
  newPointTag();
  curve.extrusion.reset();
  curve.periodic.reset();
  curve.compound.clear();
  curve.embeddedPoints.clear();
  curves_[copy] = std::move(curve);
  return copy;
}

int GeoFactory::copySurface(int tag) {
  const int copy = newRegionTag(2);
  Surface surface = surfaces_.at(tag);
  surface.tag = copy;
  surface.loopTags.clear();
  for (auto& loop : surface.loops)
    for (int& c : loop) c = copyCurve(c);
  surface.extrusion.reset();
  surface.sweep.reset();
  surface.periodic.reset();
  surface.compound.clear();
  surface.embeddedPoints.clear();
  surface.embeddedCurves.clear();
  surfaces_[copy] = std::move(surface);
  return copy;
}

// Unlike extruded volumes, copies take the next tag of the shared numbering.
int GeoFactory::copyVolume(int tag) {
  const int copy = newRegionTag(3);
  Volume volume = volumes_.at(tag);
  volume.tag = copy;
  volume.shellTags.clear();
  for (auto& shell : volume.shells)
    for (int& s : shell) s = (s < 0 ? -1 : 1) * copySurface(std::abs(s));
  volume.extrusion.reset();
  volume.embeddedPoints.clear();
  volume.embeddedCurves.clear();
  volume.embeddedSurfaces.clear();
  volumes_[copy] = std::move(volume);
  return copy;
}

std::vector<EntityId> GeoFactory::duplicate(const std::vector<EntityId>& shapes) {
  for (EntityId shape : shapes) requireGeometric(shape, "Duplicata");
  std::vector<EntityId> copies;
  for (EntityId shape : shapes) {
    const int tag = std::abs(shape.tag);
    switch (shape.dim) {
      case 0: copies.push_back({0, copyPoint(tag)}); break;
      case 1: copies.push_back({1, copyCurve(shape.tag)}); break;
      case 2: copies.push_back({2, copySurface(tag)}); break;
      default: copies.push_back({3, copyVolume(tag)}); break;
    }
  }
  return copies;
}

std::vector<int> GeoFactory::reversedPoints(const Curve& c) {
  std::vector<int> points(c.points.rbegin(), c.points.rend());
  // An ellipse arc's {start, center, major, end} becomes {end, center, major, start}.
  if (c.kind == CurveKind::EllipseArc) std::swap(points[1], points[2]);
  return points;
}

bool GeoFactory::isUsed(EntityId e) const {
  auto inChains = [&](const std::vector<std::vector<int>>& chains) {
    for (const auto& chain : chains)
      for (int t : chain)
        if (std::abs(t) == e.tag) return true;
    return false;
  };
  switch (e.dim) {
    case 0:
      return std::any_of(curves_.begin(), curves_.end(), [&](const auto& c) {
        const auto& p = c.second.points;
        return std::find(p.begin(), p.end(), e.tag) != p.end();
      });
    case 1:
      return std::any_of(surfaces_.begin(), surfaces_.end(),
                         [&](const auto& s) { return inChains(s.second.loops); });
    case 2:
      return std::any_of(volumes_.begin(), volumes_.end(),
                         [&](const auto& v) { return inChains(v.second.shells); });
    default: return false;
  }
}

void GeoFactory::eraseEntity(EntityId e) {
  switch (e.dim) {
    case 0:
      points_.erase(e.tag);
      discretePoints_.erase(e.tag);
      break;
    case 1: curves_.erase(e.tag); break;
    case 2:
      surfaces_.erase(e.tag);
      discreteBoxes_.erase(e.tag);
      discreteFiles_.erase(e.tag);
      break;
    default: volumes_.erase(e.tag); break;
  }
  int& mark = highWater_[static_cast<std::size_t>(e.dim)];
  if (mark == e.tag) --mark;
}

void GeoFactory::remove(const std::vector<EntityId>& shapes, bool recursive) {
  for (EntityId shape : shapes) {
    const EntityId e{shape.dim, std::abs(shape.tag)};
    if (!contains(e) || isUsed(e)) continue;
    std::vector<EntityId> below;
    if (recursive && e.dim == 1)
      for (int p : curves_.at(e.tag).points) below.push_back({0, p});
    else if (recursive)
      for (EntityId b : boundary({e}, false)) below.push_back(b);
    eraseEntity(e);
    if (recursive) remove(below, true);
  }
}

// As the built-in kernel of Gmsh gives them: a curve's ends in its direction (a negative tag
// reverses them); a surface's curves and a volume's surfaces in loop order, as positive tags.
std::vector<EntityId> GeoFactory::boundary(const std::vector<EntityId>& shapes,
                                           bool combined) const {
  for (EntityId shape : shapes) requireShape(shape, "Boundary");
  std::vector<EntityId> out;
  for (EntityId shape : shapes) {
    const int tag = std::abs(shape.tag);
    if (shape.dim == 1) {
      const auto ends = curveEnds(shape.tag);
      out.push_back({0, ends[0]});
      out.push_back({0, ends[1]});
    } else if (shape.dim == 2) {
      for (const auto& loop : surfaces_.at(tag).loops)
        for (int c : loop) out.push_back({1, std::abs(c)});
    } else if (shape.dim == 3) {
      for (const auto& shell : volumes_.at(tag).shells)
        for (int s : shell) out.push_back({2, std::abs(s)});
    }
  }
  return combined ? cancelShared(out) : out;
}

std::vector<int> GeoFactory::pointsOf(const std::vector<EntityId>& shapes) const {
  for (EntityId shape : shapes) requireShape(shape, "PointsOf");
  std::vector<int> out;
  for (EntityId shape : shapes) {
    if (shape.dim == 0) {
      appendOnce(out, std::abs(shape.tag));
      continue;
    }
    std::vector<EntityId> level{{shape.dim, std::abs(shape.tag)}};
    while (!level.empty() && level.front().dim > 0) level = boundary(level, false);
    for (EntityId p : level) appendOnce(out, std::abs(p.tag));
  }
  return out;
}

BoundingBox GeoFactory::boundingBox(EntityId shape) const {
  requireShape(shape, "BoundingBox");
  BoundingBox box;
  const int tag = std::abs(shape.tag);
  if (shape.dim == 0) {
    box.include(points_.at(tag).xyz);
  } else if (shape.dim == 1) {
    box = curveGeometry(curves_.at(tag))->boundingBox();
  } else if (const auto it = discreteBoxes_.find(tag);
             shape.dim == 2 && it != discreteBoxes_.end()) {
    box = it->second;
  } else {
    for (EntityId b : boundary({shape}, false)) box.include(boundingBox(b));
  }
  return box;
}

std::vector<int> GeoFactory::entitiesInBox(int dim, const BoundingBox& box) const {
  const double tol = absoluteTolerance();
  auto inside = [&](const BoundingBox& b) {
    return !b.empty() && b.min.x >= box.min.x - tol && b.min.y >= box.min.y - tol &&
           b.min.z >= box.min.z - tol && b.max.x <= box.max.x + tol &&
           b.max.y <= box.max.y + tol && b.max.z <= box.max.z + tol;
  };
  std::vector<int> out;
  auto scan = [&](const auto& entities) {
    for (const auto& [tag, entity] : entities)
      if (inside(boundingBox({dim, tag}))) out.push_back(tag);
  };
  switch (dim) {
    case 0: scan(points_); break;
    case 1: scan(curves_); break;
    case 2: scan(surfaces_); break;
    case 3: scan(volumes_); break;
    default: break;
  }
  return out;
}

}  // namespace geomesh
