// readMshViews: the data sections of an MSH file grouped into views (one per name, steps in
// time-step order), each with its MeshData and element lists built over the mesh.
#include <algorithm>
#include <map>
#include <span>
#include <tuple>

#include "io/msh_view_data.h"
#include "io/view_file_parts.h"
#include "io/view_files.h"

namespace geomesh {

using post::FieldKind;
using post::MeshData;

namespace {

struct MeshElement {
  ElementType type;
  std::span<const NodeIndex> nodes;
};

// The mesh's elements in the order of their tags (see FileMeshTags).
std::vector<MeshElement> meshElements(const Mesh& mesh) {
  std::vector<MeshElement> elements;
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& b : em.blocks)
      for (std::size_t i = 0; i < b.size(); ++i) elements.push_back({b.type, b.element(i)});
  return elements;
}

FieldKind kindOfComponents(int components) {
  if (components <= 1) return FieldKind::Scalar;
  return components <= 3 ? FieldKind::Vector : FieldKind::Tensor;
}

// The values of one node as the view holds them: 2 components padded to a vector, 6 (xx, xy,
// xz, yy, yz, zz) made a full symmetric tensor.
void appendConverted(std::vector<double>& out, const double* v, int components) {
  if (components == 2) {
    out.insert(out.end(), {v[0], v[1], 0.0});
  } else if (components == 6) {
    out.insert(out.end(), {v[0], v[1], v[2], v[1], v[3], v[4], v[2], v[4], v[5]});
  } else {
    out.insert(out.end(), v, v + components);
  }
}

// Per step, where the values of each node (node data) or element (other kinds) start.
std::vector<std::vector<const double*>> valueStarts(const MeshData& data, std::size_t nodes,
                                                    std::size_t elements) {
  std::vector<std::vector<const double*>> starts;
  const bool byNode = data.kind == MeshData::Kind::Node;
  for (const MeshData::Step& step : data.steps) {
    std::vector<const double*>& at = starts.emplace_back(byNode ? nodes : elements, nullptr);
    std::size_t offset = 0;
    for (std::size_t k = 0; k < step.tags.size(); ++k) {
      at[step.tags[k] - 1] = step.values.data() + offset;
      const int perEntry = data.kind == MeshData::Kind::ElementNode ? step.counts[k] : 1;
      offset += std::size_t(perEntry) * std::size_t(data.components);
    }
  }
  return starts;
}

}  // namespace

void buildMeshDataLists(post::View& view, const Mesh& mesh) {
  view.lists.clear();
  const MeshData& data = *view.meshData;
  const std::vector<MeshElement> elements = meshElements(mesh);
  const auto starts = valueStarts(data, mesh.nodeCount(), elements.size());
  const FieldKind kind = kindOfComponents(data.components);
  const int c = data.components;
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const MeshElement& el = elements[e];
    const int order = listOrderOfType(el.type);
    const std::size_t n = std::size_t(order == 2 ? nodeCount(el.type) : vertexCount(el.type));
    auto start = [&](std::size_t step, std::size_t i) -> const double* {
      switch (data.kind) {
        case MeshData::Kind::Node:
          return starts[step][el.nodes[i]];
        case MeshData::Kind::Element:
          return starts[step][e];
        case MeshData::Kind::ElementNode:
          break;
      }
      const double* first = starts[step][e];
      return first ? first + i * std::size_t(c) : nullptr;
    };
    bool complete = true;
    for (std::size_t s = 0; s < starts.size() && complete; ++s)
      for (std::size_t i = 0; i < n && complete; ++i) complete = start(s, i) != nullptr;
    if (!complete) continue;
    post::ElementList& list = view.list(shapeOfType(el.type), kind, order);
    list.nodesPerElement = static_cast<int>(n);
    list.steps = static_cast<int>(starts.size());
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 p = mesh.node(el.nodes[i]);
      list.coordinates.insert(list.coordinates.end(), {p.x, p.y, p.z});
    }
    for (std::size_t s = 0; s < starts.size(); ++s)
      for (std::size_t i = 0; i < n; ++i) appendConverted(list.values, start(s, i), c);
  }
}

int readMshViews(const std::string& path, const Mesh& mesh, post::ViewStore& views) {
  const std::string data = readViewFile(path);
  std::vector<DataSection> sections = readMshDataSections(data, path, mesh);
  // One view per name (and kind and component count, which a view cannot mix), in the order
  // of first appearance; its steps in the order of their time-step numbers.
  using Key = std::tuple<std::string, MeshData::Kind, int>;
  std::vector<Key> order;
  std::map<Key, std::vector<DataSection*>> groups;
  for (DataSection& s : sections) {
    const Key key{s.name, s.kind, s.components};
    if (!groups.contains(key)) order.push_back(key);
    groups[key].push_back(&s);
  }
  for (const Key& key : order) {
    std::vector<DataSection*>& steps = groups[key];
    std::stable_sort(steps.begin(), steps.end(), [](const DataSection* a, const DataSection* b) {
      return a->step.index < b->step.index;
    });
    post::View& view = views.add(std::get<0>(key));
    MeshData meshData;
    meshData.kind = std::get<1>(key);
    meshData.components = std::get<2>(key);
    for (DataSection* s : steps) {
      view.times.push_back(s->step.time);
      meshData.steps.push_back(std::move(s->step));
    }
    view.meshData = std::move(meshData);
    buildMeshDataLists(view, mesh);
  }
  return static_cast<int>(order.size());
}

}  // namespace geomesh
