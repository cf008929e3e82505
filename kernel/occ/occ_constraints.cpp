// The OpenCASCADE factory's mesh constraints on its entities: periodicity, embedding,
// compounds. They are recorded by tag, exported with the entities and written to the unrolled
// script.
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Vertex.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <utility>
#include <ostream>
#include <string>

#include "kernel/geometry_error.h"
#include "kernel/occ/occ_factory.h"
#include "kernel/occ/occ_shapes.h"

namespace geomesh {

namespace {

void append(std::vector<int>& to, const std::vector<int>& tags) {
  for (int t : tags) to.push_back(std::abs(t));
}

// `recorded` after what the entity already embeds (its internal points), without repeats.
std::vector<int> merged(std::vector<int> present, const std::vector<int>& recorded) {
  for (int t : recorded)
    if (std::find(present.begin(), present.end(), t) == present.end()) present.push_back(t);
  return present;
}

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.16g", x);
  return text;
}

std::string braced(const std::vector<int>& tags) {
  std::string text = "{";
  for (std::size_t i = 0; i < tags.size(); ++i) text += (i ? ", " : "") + std::to_string(tags[i]);
  return text + "}";
}

// "Point{5, 6} In Surface{1};", "Compound Curve{2, 3};", "Periodic Surface{2} = {1} Affine{..};"
void writeConstraints(EntityId e, const OccShapes::Constraints& c, std::ostream& out) {
  for (int dim = 0; dim < e.dim; ++dim)
    if (!c.embedded[dim].empty())
      out << entityKind(dim) << braced(c.embedded[dim]) << " In " << entityKind(e.dim) << "{"
          << e.tag << "};\n";
  if (!c.compound.empty() && c.compound.front() == e.tag)
    out << "Compound " << entityKind(e.dim) << braced(c.compound) << ";\n";
  if (c.periodic) {
    out << "Periodic " << entityKind(e.dim) << "{" << e.tag << "} = {" << c.periodic->master
        << "} Affine{";
    for (std::size_t i = 0; i < c.periodic->affine.size(); ++i)
      out << (i ? ", " : "") << number(c.periodic->affine[i]);
    out << "};\n";
  }
}

}  // namespace

void OccFactory::setPeriodic(int dim, const std::vector<int>& slaves,
                             const std::vector<int>& masters, const AffineMap& map) {
  if (dim != 1 && dim != 2)
    throw GeometryError("Periodic: only curves and surfaces can be periodic");
  if (slaves.size() != masters.size())
    throw GeometryError("Periodic: " + std::to_string(slaves.size()) +
                        " entities cannot match " + std::to_string(masters.size()));
  const auto h = map.homogeneous();
  for (std::size_t i = 0; i < slaves.size(); ++i) {
    shapes_->find(dim, std::abs(slaves[i]));
    shapes_->find(dim, std::abs(masters[i]));
    shapes_->constraints[{dim, std::abs(slaves[i])}].periodic =
        Periodicity{std::abs(masters[i]), std::vector<double>(h.begin(), h.end())};
  }
}

namespace {

// The first and last vertex of a curve taken forward.
std::array<int, 2> curveEnds(const OccShapes& shapes, int tag) {
  const TopoDS_Edge edge = TopoDS::Edge(shapes.find(1, std::abs(tag)).Oriented(TopAbs_FORWARD));
  return {shapes.tagOf(0, TopExp::FirstVertex(edge)), shapes.tagOf(0, TopExp::LastVertex(edge))};
}

// Master point -> slave point along the listed curves, the first pair of curves taken in
// `firstOrientation`, each next pair the way that agrees with a point already matched (the
// curves of a loop share their ends; OpenCASCADE's curves run either way). Empty when the
// curves cannot match.
std::map<int, int> matchedPoints(const OccShapes& shapes, const std::vector<int>& slaveCurves,
                                 const std::vector<int>& masterCurves, bool firstOrientation) {
  std::map<int, int> imageOf;
  for (std::size_t k = 0; k < slaveCurves.size(); ++k) {
    std::array<int, 2> s = curveEnds(shapes, slaveCurves[k]);
    const std::array<int, 2> m = curveEnds(shapes, masterCurves[k]);
    const bool known0 = imageOf.contains(m[0]), known1 = imageOf.contains(m[1]);
    const bool swap = k == 0 ? !firstOrientation
                             : (known0 && imageOf[m[0]] == s[1]) ||
                                   (!known0 && known1 && imageOf[m[1]] == s[0]);
    if (swap) std::swap(s[0], s[1]);
    for (int end = 0; end < 2; ++end) {
      const auto [it, inserted] = imageOf.emplace(m[end], s[end]);
      if (!inserted && it->second != s[end]) return {};
    }
  }
  return imageOf;
}

}  // namespace

// The older form Periodic Surface s {curves} = m {curves}: the transformation follows from
// the curves' ends, as in the built-in kernel, which handles its own surfaces.
void OccFactory::setPeriodicByCurves(int slave, const std::vector<int>& slaveCurves, int master,
                                     const std::vector<int>& masterCurves) {
  // Entities of the built-in kernel are that kernel's to match (through the handover).
  bool mine = shapes_->contains(2, std::abs(slave)) && shapes_->contains(2, std::abs(master));
  for (const auto* curves : {&slaveCurves, &masterCurves})
    for (int c : *curves) mine = mine && shapes_->contains(1, std::abs(c));
  if (!mine) unsupported("Periodic");
  if (slaveCurves.size() != masterCurves.size() || slaveCurves.empty())
    throw GeometryError("Periodic Surface " + std::to_string(slave) + ": " +
                        std::to_string(slaveCurves.size()) + " curves cannot match " +
                        std::to_string(masterCurves.size()));
  for (bool orientation : {true, false}) {
    std::vector<std::pair<Vec3, Vec3>> pairs;
    BoundingBox box;
    for (const auto& [from, to] : matchedPoints(*shapes_, slaveCurves, masterCurves, orientation)) {
      pairs.emplace_back(pointCoordinates(from), pointCoordinates(to));
      box.include(pairs.back().first);
      box.include(pairs.back().second);
    }
    const double tolerance = 1e-7 + 1e-9 * (box.empty() ? 0 : distance(box.min, box.max));
    if (const std::optional<AffineMap> map = rigidMotion(pairs, tolerance))
      return setPeriodic(2, {slave}, {master}, *map);
  }
  throw GeometryError("Periodic Surface " + std::to_string(slave) +
                      ": its curves are not the image of those of surface " +
                      std::to_string(master) + " by a translation or a rotation");
}

void OccFactory::embed(int dim, const std::vector<int>& tags, int hostDim, int hostTag) {
  if (dim < 0 || hostDim > 3 || dim >= hostDim || hostDim < 1)
    throw GeometryError("In: cannot embed entities of dimension " + std::to_string(dim) +
                        " in dimension " + std::to_string(hostDim));
  shapes_->find(hostDim, std::abs(hostTag));
  for (int t : tags) shapes_->find(dim, std::abs(t));
  append(shapes_->constraints[{hostDim, std::abs(hostTag)}].embedded[dim], tags);
}

void OccFactory::addCompound(int dim, const std::vector<int>& tags) {
  if (dim < 1 || dim > 2) throw GeometryError("Compound: only curves and surfaces are compounds");
  for (int t : tags) shapes_->find(dim, std::abs(t));
  for (int t : tags) {
    std::vector<int>& compound = shapes_->constraints[{dim, std::abs(t)}].compound;
    compound.clear();
    append(compound, tags);
  }
}

// After the line merging the shapes' XAO file: the sizes at points, then for each curve,
// surface and volume its embedded entities, compound and periodicity, and the hooks' lines.
void OccFactory::writeUnrolled(std::ostream& out, const UnrolledGeoHooks& hooks) const {
  for (const auto& [tag, size] : meshSizes_)
    if (size > 0 && shapes_->contains(0, tag))
      out << "MeshSize{" << tag << "} = " << number(size) << ";\n";
  for (int dim = 1; dim <= 3; ++dim)
    for (const auto& entry : shapes_->byTag[dim]) {
      const EntityId e{dim, entry.first};
      if (auto c = shapes_->constraints.find(e); c != shapes_->constraints.end())
        writeConstraints(e, c->second, out);
      if (hooks.afterEntity) hooks.afterEntity(e, out);
    }
}

// Copies the constraints recorded on the model's entities of this factory.
void applyConstraints(const OccShapes& shapes, Model& model) {
  for (const auto& [e, c] : shapes.constraints) {
    if (e.dim == 1) {
      const ModelCurve* curve = model.curve(e.tag);
      if (!curve) continue;
      ModelCurve updated = *curve;
      updated.periodic = c.periodic;
      updated.embeddedPoints = c.embedded[0];
      updated.compound = c.compound;
      model.addCurve(std::move(updated));
    } else if (e.dim == 2) {
      const ModelSurface* surface = model.surface(e.tag);
      if (!surface) continue;
      ModelSurface updated = *surface;
      updated.periodic = c.periodic;
      updated.embeddedPoints = merged(updated.embeddedPoints, c.embedded[0]);
      updated.embeddedCurves = c.embedded[1];
      updated.compound = c.compound;
      model.addSurface(std::move(updated));
    } else if (e.dim == 3) {
      const ModelVolume* volume = model.volume(e.tag);
      if (!volume) continue;
      ModelVolume updated = *volume;
      updated.embeddedPoints = merged(updated.embeddedPoints, c.embedded[0]);
      updated.embeddedCurves = c.embedded[1];
      updated.embeddedSurfaces = c.embedded[2];
      model.addVolume(std::move(updated));
    }
  }
}

}  // namespace geomesh
