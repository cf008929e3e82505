// Extrusions of the built-in kernel: points sweep curves, curves sweep surfaces, surfaces sweep
// volumes. The entities are created in the order the built-in kernel of Gmsh creates them
// (the top as a copy of the source, then the sweeps of its boundary, then the swept entity),
// and coincident ones are merged after each shape, so that tags match Gmsh's.
#include <cmath>
#include <cstdlib>

#include "kernel/geo/geo_detail.h"
#include "kernel/geo/geo_factory.h"

namespace geomesh {

using geo_detail::fail;

namespace {

// The curve a point sweeps; 0 when the point does not move (it lies on the rotation axis).
int sweptCurve(const std::vector<EntityId>& made) { return made.empty() ? 0 : made[1].tag; }

bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void checkMotion(const ExtrusionMotion& motion) {
  using Kind = ExtrusionMotion::Kind;
  if (!finite(motion.translation) || !finite(motion.axis) || !finite(motion.axisPoint) ||
      !std::isfinite(motion.angle))
    fail("Extrude: its parameters are not finite numbers");
  const bool turns = motion.kind != Kind::Translation && motion.angle != 0;
  const bool moves = motion.kind != Kind::Rotation && norm(motion.translation) > 0;
  if (motion.kind != Kind::Translation && norm(motion.axis) == 0)
    fail("Extrude: the rotation axis is the zero vector");
  if (!turns && !moves) fail("Extrude: the extrusion does not move anything");
}

int remapped(int signedTag, const std::map<int, int>& merges) {
  auto it = merges.find(std::abs(signedTag));
  if (it == merges.end()) return signedTag;
  return signedTag < 0 ? -it->second : it->second;
}

}  // namespace

std::vector<EntityId> GeoFactory::extrude(const std::vector<EntityId>& shapes,
                                          const ExtrusionMotion& motion,
                                          const ExtrusionLayers& layers) {
  for (EntityId shape : shapes) requireGeometric(shape, "Extrude");
  const bool layer = motion.kind == ExtrusionMotion::Kind::Normals;
  if (!layer) checkMotion(motion);
  if (layer && layers.elements.empty())
    fail("Extrude along normals (a boundary layer) needs Layers{..}");
  // The copies a boundary layer makes are its own points (see layerPoints_).
  struct LayerScope {
    int& index;
    ~LayerScope() { index = -1; }
  } scope{layerCopyIndex_};
  layerCopyIndex_ = layer ? motion.layerIndex : -1;
  std::vector<EntityId> out;
  for (EntityId shape : shapes) {
    const int tag = std::abs(shape.tag);
    std::vector<EntityId> made;
    if (shape.dim == 0) made = extrudePoint(tag, motion, layers);
    else if (shape.dim == 1) made = extrudeCurve(shape.tag, motion, layers);
    else if (shape.dim == 2) made = extrudeSurface(tag, motion, layers);
    else fail("Extrude: volume ", tag, " cannot be extruded");
    for (auto& merges : lastMerges_) merges.clear();
    if (autoCoherence_) coherence();
    if (!returnLaterals_ && made.size() > 2) made.resize(2);
    for (EntityId e : made)
      out.push_back({e.dim, remapped(e.tag, lastMerges_[static_cast<std::size_t>(e.dim)])});
  }
  return out;
}

std::vector<EntityId> GeoFactory::extrudePoint(int tag, const ExtrusionMotion& motion,
                                               const ExtrusionLayers& layers) {
  const ModelPoint source = points_.at(tag);
  auto addMoved = [&](double s) {
    const int moved = newPointTag();
    points_[moved] = ModelPoint{moved, motion.apply(source.xyz, s), source.meshSize};
    bounds_.include(points_[moved].xyz);
    if (layerCopyIndex_ >= 0) layerPoints_[moved] = {tag, layerCopyIndex_};
    return moved;
  };
  Curve curve{0};
  if (motion.kind == ExtrusionMotion::Kind::Translation ||
      motion.kind == ExtrusionMotion::Kind::Normals) {
    curve = Curve{0, CurveKind::Line, {tag, addMoved(1)}};
  } else if (motion.kind == ExtrusionMotion::Kind::Rotation) {
    if (std::abs(motion.angle) >= std::acos(-1.0))
      fail("Extrude: point ", tag, " cannot be rotated by half a turn or more in one step");
    const Vec3 axis = normalized(motion.axis);
    const Vec3 center = motion.axisPoint + dot(source.xyz - motion.axisPoint, axis) * axis;
    if (distance(center, source.xyz) <= absoluteTolerance()) return {};  // stays in place
    const int end = addMoved(1);
    const int centerTag = newPointTag();
    points_[centerTag] = ModelPoint{centerTag, center, source.meshSize};
    curve = Curve{0, CurveKind::CircleArc, {tag, centerTag, end}};
  } else {
    // Each step moves the previous point by a fraction of the motion (as Gmsh does, which
    // keeps its rounding).
    curve = Curve{0, CurveKind::Spline, {tag}};
    Vec3 xyz = source.xyz;
    for (int i = 1; i <= twistSteps_; ++i) {
      xyz = motion.apply(xyz, 1.0 / twistSteps_);
      const int step = newPointTag();
      points_[step] = ModelPoint{step, xyz, source.meshSize};
      bounds_.include(xyz);
      curve.points.push_back(step);
    }
  }
  curve.tag = newRegionTag(1);
  curve.extrusion = ExtrusionRecord{tag, layers, curve.end(), std::make_shared<const ExtrusionMotion>(motion)};
  curves_[curve.tag] = curve;
  return {{0, curve.end()}, {1, curve.tag}};
}

void GeoFactory::moveCopy(EntityId copy, const ExtrusionMotion& motion) {
  for (int p : pointsUnder({copy})) {
    Vec3& xyz = points_.at(p).xyz;
    xyz = motion.apply(xyz, 1);
    bounds_.include(xyz);
  }
}

// A negative tag sweeps the reversed curve: its loop then starts with it, as given.
std::vector<EntityId> GeoFactory::extrudeCurve(int tag, const ExtrusionMotion& motion,
                                               const ExtrusionLayers& layers) {
  const int top = copyCurve(tag);
  moveCopy({1, top}, motion);
  const auto ends = curveEnds(tag);
  const int startSweep = sweptCurve(extrudePoint(ends[0], motion, layers));
  const int endSweep = sweptCurve(extrudePoint(ends[1], motion, layers));
  if (startSweep == 0 && endSweep == 0) return {{1, top}};  // the curve lies on the axis
  // An end on the rotation axis stays in place: the surface has three sides.
  std::vector<int> loop{tag, endSweep, -top, -startSweep};
  if (endSweep == 0) loop = {-top, -startSweep, tag};
  if (startSweep == 0) loop = {tag, endSweep, -top};
  Surface surface{newRegionTag(2), SurfaceKind::Swept, {loop}};
  surface.extrusion = ExtrusionRecord{std::abs(tag), layers, top, std::make_shared<const ExtrusionMotion>(motion)};
  surface.sweep = motion;
  surfaces_[surface.tag] = surface;
  std::vector<EntityId> out{{1, top}, {2, surface.tag}};
  if (endSweep != 0) out.push_back({1, endSweep});
  if (startSweep != 0) out.push_back({1, -startSweep});
  return out;
}

std::vector<EntityId> GeoFactory::extrudeSurface(int tag, const ExtrusionMotion& motion,
                                                 const ExtrusionLayers& layers) {
  const int firstTop = copySurface(tag);
  moveCopy({2, firstTop}, motion);
  std::vector<EntityId> laterals;
  const std::vector<std::vector<int>> loops = surfaces_.at(tag).loops;
  for (const auto& loop : loops)
    for (int c : loop) {
      const auto made = extrudeCurve(c, motion, layers);
      if (made.size() > 1) laterals.push_back(made[1]);
    }
  // The top gets a tag after those of the lateral surfaces.
  Surface top = surfaces_.at(firstTop);
  surfaces_.erase(firstTop);
  top.tag = newRegionTag(2);
  if (motion.kind == ExtrusionMotion::Kind::Normals) top.sweep = motion;  // see surfaceGeometry
  surfaces_[top.tag] = top;
  Volume volume{newVolumeTag(), {{tag, top.tag}}};
  for (EntityId s : laterals) volume.shells.front().push_back(s.tag);
  volume.extrusion = ExtrusionRecord{tag, layers, top.tag, std::make_shared<const ExtrusionMotion>(motion)};
  volumes_[volume.tag] = volume;
  std::vector<EntityId> out{{2, top.tag}, {3, volume.tag}};
  out.insert(out.end(), laterals.begin(), laterals.end());
  return out;
}

}  // namespace geomesh
