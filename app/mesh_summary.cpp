// Element counts, measures, quality and physical groups of a mesh, and their printed form.
#include "app/mesh_summary.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mesh/core/quality.h"

namespace geomesh {

namespace {

void addMeasures(const Mesh& mesh, MeshSummary& s) {
  for (const auto& [id, em] : mesh.entities()) {
    for (const ElementBlock& block : em.blocks) {
      s.elements[block.type] += block.size();
      double total = 0;
      for (std::size_t i = 0; i < block.size(); ++i)
        total += elementMeasure(mesh, block.type, block.element(i));
      switch (dimension(block.type)) {
        case 1: s.length += total; break;
        case 2: s.area += total; break;
        case 3: s.volume += total; break;
        default: break;
      }
    }
  }
}

void addGroups(const Model& model, const Mesh& mesh, MeshSummary& s) {
  for (const auto& [id, group] : model.physicalGroups()) {
    MeshSummary::Group g{group.dim, group.tag, group.name, 0};
    for (int tag : group.entities)
      if (const EntityMesh* em = mesh.find({group.dim, tag})) g.elements += em->elementCount();
    s.physicalGroups.push_back(g);
  }
}

std::string plural(std::size_t n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

}  // namespace

MeshSummary summarizeMesh(const Model& model, const Mesh& mesh) {
  MeshSummary s;
  s.nodes = mesh.nodeCount();
  addMeasures(mesh, s);
  addGroups(model, mesh, s);
  // Quality of the highest-dimensional elements present.
  for (int dim = 3; dim >= 2; --dim) {
    QualityStats q = meshQuality(mesh, dim, QualityMeasure::Gamma);
    if (q.count == 0) continue;
    s.minQuality = q.min;
    s.meanQuality = q.mean;
    break;
  }
  return s;
}

std::string formatSummary(const MeshSummary& s) {
  std::ostringstream os;
  std::size_t total = 0;
  for (const auto& [type, n] : s.elements) total += n;
  os << plural(s.nodes, "node") << ", " << plural(total, "element");
  if (!s.elements.empty()) {
    os << " (";
    bool first = true;
    for (const auto& [type, n] : s.elements) {
      os << (first ? "" : ", ") << n << ' ' << elementName(type);
      first = false;
    }
    os << ")";
  }
  os.precision(6);
  if (s.volume > 0) os << "; volume " << s.volume;
  if (s.area > 0) os << "; area " << s.area;
  if (s.length > 0) os << "; length " << s.length;
  if (s.meanQuality > 0) {
    os.precision(4);
    os << "; quality (gamma) min " << s.minQuality << ", mean " << s.meanQuality;
  }
  return os.str();
}

std::string describeModel(const Model& model) {
  return plural(model.points().size(), "point") + ", " + plural(model.curves().size(), "curve") +
         ", " + plural(model.surfaces().size(), "surface") + ", " +
         plural(model.volumes().size(), "volume") + ", " +
         plural(model.physicalGroups().size(), "physical group");
}

}  // namespace geomesh
