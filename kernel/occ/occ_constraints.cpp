// The OpenCASCADE factory's mesh constraints on its entities: periodicity, embedding,
// compounds. They are recorded by tag and exported with the entities.
#include <cmath>
#include <cstdio>
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
      updated.embeddedPoints = c.embedded[0];
      updated.embeddedCurves = c.embedded[1];
      updated.compound = c.compound;
      model.addSurface(std::move(updated));
    } else if (e.dim == 3) {
      const ModelVolume* volume = model.volume(e.tag);
      if (!volume) continue;
      ModelVolume updated = *volume;
      updated.embeddedPoints = c.embedded[0];
      updated.embeddedCurves = c.embedded[1];
      updated.embeddedSurfaces = c.embedded[2];
      model.addVolume(std::move(updated));
    }
  }
}

}  // namespace geomesh
