// Model: entities, adjacencies both ways, physical groups and bounding boxes.
#include "kernel/model.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace geomesh {

namespace {

template <class Entity>
const Entity* findIn(const std::map<int, Entity>& m, int tag) {
  auto it = m.find(tag);
  return it == m.end() ? nullptr : &it->second;
}

void appendUnique(std::vector<int>& v, int tag) {
  auto it = std::lower_bound(v.begin(), v.end(), tag);
  if (it == v.end() || *it != tag) v.insert(it, tag);
}

}  // namespace

void Model::clear() {
  MeshConstraints constraints = std::move(meshConstraints_);
  *this = Model();
  meshConstraints_ = std::move(constraints);
}

ModelPoint& Model::addPoint(ModelPoint p) { return points_[p.tag] = std::move(p); }

ModelCurve& Model::addCurve(ModelCurve c) {
  appendUnique(upward_[{0, c.startPoint}], c.tag);
  appendUnique(upward_[{0, c.endPoint}], c.tag);
  return curves_[c.tag] = std::move(c);
}

ModelSurface& Model::addSurface(ModelSurface s) {
  for (const auto& loop : s.loops)
    for (int c : loop) appendUnique(upward_[{1, std::abs(c)}], s.tag);
  return surfaces_[s.tag] = std::move(s);
}

ModelVolume& Model::addVolume(ModelVolume v) {
  for (const auto& shell : v.shells)
    for (int s : shell) appendUnique(upward_[{2, std::abs(s)}], v.tag);
  return volumes_[v.tag] = std::move(v);
}

void Model::addPhysicalGroup(PhysicalGroup g) { physicals_[{g.dim, g.tag}] = std::move(g); }

const ModelPoint* Model::point(int tag) const { return findIn(points_, tag); }
const ModelCurve* Model::curve(int tag) const { return findIn(curves_, tag); }
const ModelSurface* Model::surface(int tag) const { return findIn(surfaces_, tag); }
const ModelVolume* Model::volume(int tag) const { return findIn(volumes_, tag); }

bool Model::contains(EntityId e) const {
  switch (e.dim) {
    case 0: return point(e.tag) != nullptr;
    case 1: return curve(e.tag) != nullptr;
    case 2: return surface(e.tag) != nullptr;
    case 3: return volume(e.tag) != nullptr;
    default: return false;
  }
}

std::vector<EntityId> Model::entities(int dim) const {
  std::vector<EntityId> out;
  auto collect = [&](int d, const auto& m) {
    if (dim != -1 && dim != d) return;
    for (const auto& [tag, entity] : m) out.push_back({d, tag});
  };
  collect(0, points_);
  collect(1, curves_);
  collect(2, surfaces_);
  collect(3, volumes_);
  return out;
}

int Model::maxTag(int dim) const {
  auto last = [](const auto& m) { return m.empty() ? 0 : m.rbegin()->first; };
  switch (dim) {
    case 0: return last(points_);
    case 1: return last(curves_);
    case 2: return last(surfaces_);
    case 3: return last(volumes_);
    default: return 0;
  }
}

std::vector<int> Model::boundary(EntityId e) const {
  std::vector<int> out;
  if (e.dim == 1) {
    if (const ModelCurve* c = curve(e.tag)) {
      out.push_back(c->startPoint);
      if (c->endPoint != c->startPoint) out.push_back(c->endPoint);
    }
  } else if (e.dim == 2) {
    if (const ModelSurface* s = surface(e.tag))
      for (const auto& loop : s->loops) out.insert(out.end(), loop.begin(), loop.end());
  } else if (e.dim == 3) {
    if (const ModelVolume* v = volume(e.tag))
      for (const auto& shell : v->shells) out.insert(out.end(), shell.begin(), shell.end());
  }
  return out;
}

std::vector<int> Model::upward(EntityId e) const {
  auto it = upward_.find(e);
  if (it == upward_.end()) return {};
  std::vector<int> out;
  // Entities may have been replaced or removed since: keep those whose current boundary still
  // holds e.
  for (int tag : it->second) {
    const std::vector<int> b = boundary({e.dim + 1, tag});
    if (std::any_of(b.begin(), b.end(), [&](int t) { return std::abs(t) == e.tag; }))
      out.push_back(tag);
  }
  return out;
}

std::vector<int> Model::physicalTagsOf(EntityId e) const {
  std::vector<int> out;
  for (const auto& [id, group] : physicals_)
    if (id.dim == e.dim && std::any_of(group.entities.begin(), group.entities.end(),
                                       [&](int member) { return std::abs(member) == e.tag; }))
      out.push_back(id.tag);  // a member given as -tag (reversed) is in the group all the same
  return out;
}

BoundingBox Model::boundingBox(EntityId e) const {
  BoundingBox box;
  switch (e.dim) {
    case 0:
      if (const ModelPoint* p = point(e.tag)) box.include(p->xyz);
      break;
    case 1:
      if (const ModelCurve* c = curve(e.tag)) {
        if (c->geometry) {
          box = c->geometry->boundingBox();
        } else {
          box.include(boundingBox({0, c->startPoint}));
          box.include(boundingBox({0, c->endPoint}));
        }
      }
      break;
    default:
      for (int b : boundary(e)) box.include(boundingBox({e.dim - 1, std::abs(b)}));
      break;
  }
  return box;
}

BoundingBox Model::boundingBox() const {
  BoundingBox box = sizeBoxExtra_;
  for (const auto& [tag, p] : points_) box.include(p.xyz);
  for (const auto& [tag, c] : curves_) box.include(boundingBox({1, tag}));
  return box;
}

BoundingBox Model::sizeBox() const {
  BoundingBox box = sizeBoxExtra_;
  for (const auto& [tag, p] : points_) box.include(p.xyz);
  for (const auto& [tag, c] : curves_)
    if (!c.boxedByPoints) box.include(boundingBox({1, tag}));
  return box;
}

}  // namespace geomesh
