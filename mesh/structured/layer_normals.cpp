// LayerNormals: angle-weighted mean normals of the boundary layers' source meshes, per index.
#include "mesh/structured/layer_normals.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <sstream>
#include <string>

#include "mesh/core/mesh_error.h"
#include "mesh/sizes/view_size.h"
#include "mesh/structured/layer_shrinking.h"
#include "mesh/structured/swept_volume.h"
#include "mesh/views/view_probe.h"

namespace geomesh {

struct LayerNormals::Field {
  explicit Field(const Mesh& mesh, double tolerance) : locator(mesh, tolerance) {}
  extrusion::NodeLocator locator;
  std::unordered_map<NodeIndex, Vec3> sums, units;
  LayerFaces faces;
  LayerShrinking shrinking;
};

namespace {

bool isLayer(const std::optional<ExtrusionRecord>& record) {
  return record && record->motion && record->motion->kind == ExtrusionMotion::Kind::Normals;
}

double angleBetween(Vec3 a, Vec3 b) {
  const double na = norm(a), nb = norm(b);
  if (na == 0 || nb == 0) return 0;
  return std::acos(std::clamp(dot(a, b) / (na * nb), -1.0, 1.0));
}

// Each corner of a face adds the face's unit normal, weighed by the face's angle there.
void addFace(const Mesh& mesh, std::span<const NodeIndex> f,
             std::unordered_map<NodeIndex, Vec3>& sums) {
  const std::size_t n = f.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 p = mesh.node(f[i]);
    const Vec3 next = mesh.node(f[(i + 1) % n]) - p, previous = mesh.node(f[(i + n - 1) % n]) - p;
    const Vec3 normal = cross(next, previous);
    const double length = norm(normal);
    if (length == 0) continue;
    sums[f[i]] = sums[f[i]] + angleBetween(next, previous) / length * normal;
  }
}

}  // namespace

LayerNormals::LayerNormals(const Model& model, const post::ViewStore* views)
    : views_(views) {
  const BoundingBox box = model.boundingBox();
  const double diagonal = box.empty() ? 0 : distance(box.min, box.max);
  tolerance_ = 1e-9 * (diagonal > 0 ? diagonal : 1);
  auto noteHeight = [&](const ExtrusionRecord& r, std::map<int, double>& heights) {
    double& h = heights[r.source];
    if (!r.layers.heights.empty() && std::abs(r.layers.heights.back()) > std::abs(h))
      h = r.layers.heights.back();
  };
  for (const auto& [tag, volume] : model.volumes())
    if (isLayer(volume.extrusion)) {
      surfaces_[volume.extrusion->motion->layerIndex].insert(volume.extrusion->source);
      noteHeight(*volume.extrusion, surfaceHeights_);
    }
  for (const auto& [tag, surface] : model.surfaces())
    if (isLayer(surface.extrusion)) {
      curves_[surface.extrusion->motion->layerIndex].insert(surface.extrusion->source);
      noteHeight(*surface.extrusion, curveHeights_);
    }
}

std::vector<std::string> LayerNormals::warnings() const {
  std::vector<std::string> lines;
  for (const auto& [index, f] : fields_) {
    const LayerShrinking& s = f->shrinking;
    if (s.shrunk == 0) continue;
    std::ostringstream line;
    line << "boundary layer of index " << index << ": " << s.shrunk
         << " columns made thinner than asked, where the layer would cross itself or the "
            "layer facing it (down to "
         << std::lround(100 * s.smallest) << "% at (" << s.at.x << ", " << s.at.y << ", "
         << s.at.z << "))";
    lines.push_back(line.str());
  }
  return lines;
}

LayerNormals::~LayerNormals() = default;

bool LayerNormals::sourcesMeshed(const Mesh& mesh, int index) const {
  const auto surfaces = surfaces_.find(index);
  if (surfaces == surfaces_.end()) return true;
  return std::all_of(surfaces->second.begin(), surfaces->second.end(), [&](int tag) {
    const EntityMesh* em = mesh.find({2, tag});
    return em && em->elementCount() > 0;
  });
}

const LayerNormals::Field& LayerNormals::field(const Mesh& mesh, int index,
                                               EntityId asking) const {
  if (const auto it = fields_.find(index); it != fields_.end()) return *it->second;
  auto made = std::make_unique<Field>(mesh, tolerance_);
  std::unordered_map<NodeIndex, Vec3>& sums = made->sums;
  if (const auto surfaces = surfaces_.find(index); surfaces != surfaces_.end()) {
    for (int tag : surfaces->second) {
      const EntityMesh* em = mesh.find({2, tag});
      if (!em || em->elementCount() == 0)
        throw MeshError(asking, "surface " + std::to_string(tag) +
                                    ", which its boundary layer grows from, has no mesh");
      for (const ElementBlock& block : em->blocks) {
        const std::size_t size = block.type == ElementType::Triangle3 ? 3
                                 : block.type == ElementType::Quad4   ? 4
                                                                      : 0;
        if (size == 0) continue;
        for (std::size_t e = 0; e + size <= block.nodes.size(); e += size) {
          const std::span<const NodeIndex> face(block.nodes.data() + e, size);
          addFace(mesh, face, sums);
          made->faces.nodes.insert(made->faces.nodes.end(), face.begin(), face.end());
          made->faces.sizes.push_back(static_cast<unsigned char>(size));
          made->faces.heights.push_back(surfaceHeights_.at(tag));
        }
      }
    }
  } else if (const auto curves = curves_.find(index); curves != curves_.end()) {
    for (int tag : curves->second) {
      const EntityMesh* em = mesh.find({1, tag});
      if (!em || em->elementCount() == 0)
        throw MeshError(asking, "curve " + std::to_string(tag) +
                                    ", which its boundary layer grows from, has no mesh");
      for (const ElementBlock& block : em->blocks) {
        if (block.type != ElementType::Line2) continue;
        for (std::size_t e = 0; e + 2 <= block.nodes.size(); e += 2) {
          const Vec3 d = mesh.node(block.nodes[e + 1]) - mesh.node(block.nodes[e]);
          const Vec3 normal = cross(d, Vec3{0, 0, 1});
          const double length = norm(normal);
          if (length == 0) continue;
          for (std::size_t k = 0; k < 2; ++k)
            sums[block.nodes[e + k]] = sums[block.nodes[e + k]] + normal / length;
          made->faces.nodes.insert(made->faces.nodes.end(), {block.nodes[e], block.nodes[e + 1]});
          made->faces.sizes.push_back(2);
          made->faces.heights.push_back(curveHeights_.at(tag));
        }
      }
    }
  } else {
    throw MeshError(asking, "no surface or curve is extruded along normals with index " +
                                std::to_string(index) + " to give its normals");
  }
  std::vector<NodeIndex> nodes;
  for (const auto& [node, sum] : sums) nodes.push_back(node);
  std::sort(nodes.begin(), nodes.end());
  for (NodeIndex node : nodes) {
    made->locator.add(node);
    const double length = norm(sums.at(node));
    made->units[node] = length > 1e-12 ? sums.at(node) / length : Vec3{};
  }
  made->shrinking = shrinkLayer(mesh, made->faces, made->units);
  return *fields_.emplace(index, std::move(made)).first->second;
}

// The direction a node moves along per unit height under Using View[v]: a scalar view's
// value times the normal, or a vector view's vector.
Vec3 LayerNormals::viewDirection(int view, Vec3 p, Vec3 normal, EntityId asking) const {
  auto probe = probes_.find(view);
  if (probe == probes_.end()) {
    const post::View* v = viewNamed(views_, view, -1);
    if (!v)
      throw MeshError(asking, "its boundary layer is extruded Using View[" + std::to_string(view) +
                                  "], and there is no view at index " + std::to_string(view));
    probe = probes_.emplace(view, std::make_unique<post::ViewProbe>(*v)).first;
  }
  int count = 0;
  std::optional<std::array<double, 9>> c = probe->second->components(p, &count);
  if (!c) c = probe->second->nearestComponents(p, &count);
  if (!c)
    throw MeshError(asking, "View[" + std::to_string(view) + "], which sets its boundary layer, "
                                "holds no value");
  return count == 3 ? Vec3{(*c)[0], (*c)[1], (*c)[2]} : (*c)[0] * normal;
}

Vec3 LayerNormals::moved(const Mesh& mesh, int index, int view, Vec3 p, double height,
                         EntityId asking) const {
  const Field& f = field(mesh, index, asking);
  const std::optional<NodeIndex> node = f.locator.find(p);
  if (!node)
    throw MeshError(asking, "its boundary layer starts at a point that is on none of the "
                            "surfaces or curves it grows from");
  const Vec3 unit = f.units.at(*node);
  if (norm(unit) == 0)
    throw MeshError(asking, "the normals of the faces its boundary layer grows from cancel at "
                            "node " + std::to_string(*node + 1));
  const Vec3 direction = view >= 0 ? viewDirection(view, p, unit, asking) : unit;
  return p + height * f.shrinking.factor.at(*node) * direction;
}

}  // namespace geomesh
