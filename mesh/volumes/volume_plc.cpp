// collectVolumePlc: a volume's shells and embedded entities as one complex, with node sizes.
#include "mesh/volumes/volume_plc.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "mesh/core/mesh_error.h"

namespace geomesh {

namespace {

std::uint64_t edgeKey(int a, int b) {
  return std::uint64_t(std::min(a, b)) << 32 | std::uint32_t(std::max(a, b));
}

std::vector<int> sortedUnique(std::vector<int> tags) {
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  return tags;
}

// Nearest-node queries over a fixed set of nodes: a k-d tree in one array (the nodes reordered
// so that each subtree is a contiguous range split at its middle element).
class NearestNode {
 public:
  NearestNode(std::vector<int> nodes, const std::vector<Vec3>& xyz)
      : nodes_(std::move(nodes)), axis_(nodes_.size(), 0), xyz_(xyz) {
    build(0, nodes_.size());
  }
  int nearest(Vec3 p) const {
    Best best{-1, 1e300};
    search(p, 0, nodes_.size(), best);
    return best.node;
  }

 private:
  struct Best {
    int node;
    double distance2;
  };
  static double coordinate(Vec3 p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

  void build(std::size_t begin, std::size_t end) {
    if (end - begin <= 1) return;
    BoundingBox box;
    for (std::size_t k = begin; k < end; ++k) box.include(xyz_[nodes_[k]]);
    const Vec3 extent = box.max - box.min;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(
        nodes_.begin() + begin, nodes_.begin() + mid, nodes_.begin() + end,
        [&](int a, int b) { return coordinate(xyz_[a], axis) < coordinate(xyz_[b], axis); });
    axis_[mid] = static_cast<std::uint8_t>(axis);
    build(begin, mid);
    build(mid + 1, end);
  }

  void search(Vec3 p, std::size_t begin, std::size_t end, Best& best) const {
    if (begin >= end) return;
    const std::size_t mid = begin + (end - begin) / 2;
    const Vec3 d = p - xyz_[nodes_[mid]];
    if (dot(d, d) < best.distance2) best = {nodes_[mid], dot(d, d)};
    const double delta = coordinate(d, axis_[mid]);
    const bool lowFirst = delta < 0;
    search(p, lowFirst ? begin : mid + 1, lowFirst ? mid : end, best);
    if (delta * delta < best.distance2)
      search(p, lowFirst ? mid + 1 : begin, lowFirst ? end : mid, best);
  }

  std::vector<int> nodes_;
  std::vector<std::uint8_t> axis_;
  const std::vector<Vec3>& xyz_;
};

class PlcBuilder {
 public:
  PlcBuilder(const ModelVolume& volume, const Mesh& mesh) : id_{3, volume.tag}, mesh_(mesh) {}

  // `what` names the surface in errors: "surface" or "embedded surface". Quadrangles are
  // taken on the shells only (`shell` >= 0), recorded for pyramids.
  void addSurface(int s, const std::string& what, int shell = -1) {
    const EntityMesh* em = mesh_.find({2, s});
    const ElementBlock* tris = em ? em->findBlock(ElementType::Triangle3) : nullptr;
    const ElementBlock* quads = em && shell >= 0 ? em->findBlock(ElementType::Quad4) : nullptr;
    const std::size_t triangleCount = tris ? tris->size() : 0;
    const std::size_t quadCount = quads ? quads->size() : 0;
    if (triangleCount + quadCount == 0)
      throw MeshError(id_, what + " " + std::to_string(s) + " has no triangle mesh");
    if (em->elementCount() != triangleCount + quadCount)
      throw MeshError(id_, what + " " + std::to_string(s) + " has elements other than " +
                               (shell >= 0 ? "3-node triangles and 4-node quadrangles"
                                           : "3-node triangles"));
    for (std::size_t i = 0; i < quadCount; ++i) {
      const auto q = quads->element(i);
      plc_.quads.push_back({localIndex(q[0]), localIndex(q[1]), localIndex(q[2]), localIndex(q[3])});
      plc_.quadSurfaceOf.push_back(s);
      plc_.quadShellOf.push_back(static_cast<std::size_t>(shell));
    }
    for (std::size_t i = 0; i < triangleCount; ++i) {
      const auto t = tris->element(i);
      plc_.triangles.push_back({localIndex(t[0]), localIndex(t[1]), localIndex(t[2])});
      plc_.surfaceOf.push_back(s);
    }
  }

  // Segments already given as triangle edges, or by a curve embedded twice, are left out.
  void addCurves(const std::vector<int>& curves) {
    std::unordered_set<std::uint64_t> present;
    for (const PlcTriangle& t : plc_.triangles)
      for (int k = 0; k < 3; ++k) present.insert(edgeKey(t[k], t[(k + 1) % 3]));
    for (int c : curves) {
      const EntityMesh* em = mesh_.find({1, c});
      const ElementBlock* lines = em ? em->findBlock(ElementType::Line2) : nullptr;
      if (!lines || lines->size() == 0)
        throw MeshError(id_, "embedded curve " + std::to_string(c) + " has no line mesh");
      if (em->elementCount() != lines->size())
        throw MeshError(
            id_, "embedded curve " + std::to_string(c) + " has elements other than 2-node lines");
      for (std::size_t i = 0; i < lines->size(); ++i) {
        const int a = localIndex(lines->element(i)[0]), b = localIndex(lines->element(i)[1]);
        if (!present.insert(edgeKey(a, b)).second) continue;
        plc_.segments.push_back({a, b});
        plc_.curveOf.push_back(c);
      }
    }
  }

  // A point at a node the complex has already (an end of an embedded curve, a node of a
  // surface it is embedded in too) is kept by that node.
  void addPoints(const std::vector<int>& points) {
    for (int p : points) {
      const EntityMesh* em = mesh_.find({0, p});
      if (!em || em->nodes.empty())
        throw MeshError(id_, "embedded point " + std::to_string(p) + " has no mesh node");
      if (local_.contains(em->nodes.front())) continue;
      plc_.points.push_back(localIndex(em->nodes.front()));
      plc_.pointOf.push_back(p);
    }
  }

  VolumePlc& plc() { return plc_; }

 private:
  int localIndex(NodeIndex n) {
    auto [it, inserted] = local_.try_emplace(n, static_cast<int>(plc_.nodes.size()));
    if (inserted) plc_.nodes.push_back(n);
    return it->second;
  }

  EntityId id_;
  const Mesh& mesh_;
  VolumePlc plc_;
  std::unordered_map<NodeIndex, int> local_;
};

}  // namespace

VolumePlc collectVolumePlc(const Model& model, const ModelVolume& volume, const Mesh& mesh) {
  PlcBuilder builder(volume, mesh);
  VolumePlc& plc = builder.plc();
  for (const std::vector<int>& shell : volume.shells) {
    const int index = static_cast<int>(plc.shellStart.size());
    plc.shellStart.push_back(plc.triangles.size());
    for (int signedSurface : shell) builder.addSurface(std::abs(signedSurface), "surface", index);
  }
  plc.shellEnd = plc.triangles.size();
  if (plc.shellEnd + 2 * plc.quads.size() < 4)
    throw MeshError({3, volume.tag}, "its boundary has fewer than 4 triangles");
  for (int s : sortedUnique(volume.embeddedSurfaces)) {
    if (!model.surface(s))
      throw MeshError({3, volume.tag}, "embedded surface " + std::to_string(s) + " does not exist");
    builder.addSurface(s, "embedded surface");
  }
  builder.addCurves(sortedUnique(volume.embeddedCurves));
  builder.addPoints(sortedUnique(volume.embeddedPoints));
  return std::move(plc);
}

std::vector<double> plcNodeSizes(const VolumePlc& plc, const std::vector<Vec3>& xyz,
                                 const MeshOptions& options) {
  std::vector<double> sum(plc.nodes.size(), 0);
  std::vector<int> count(plc.nodes.size(), 0);
  for (const PlcTriangle& t : plc.triangles)
    for (int k = 0; k < 3; ++k) {
      const int p = t[k], q = t[(k + 1) % 3];
      const double length = distance(xyz[p], xyz[q]);
      sum[p] += length;
      sum[q] += length;
      ++count[p];
      ++count[q];
    }
  std::vector<double> size(plc.nodes.size(), 0);
  std::vector<int> onTriangles;
  for (std::size_t i = 0; i < size.size(); ++i)
    if (count[i] > 0) {
      size[i] = std::clamp(sum[i] / count[i], options.sizeMin, options.sizeMax);
      onTriangles.push_back(static_cast<int>(i));
    }
  // The reference does not refine the tetrahedra around embedded curves and points, whatever
  // their sizes: their nodes take the size of the nearest node of a surface.
  const NearestNode nearest(std::move(onTriangles), xyz);
  for (std::size_t i = 0; i < size.size(); ++i)
    if (count[i] == 0) size[i] = size[nearest.nearest(xyz[i])];
  return size;
}

std::vector<std::array<std::uint32_t, 3>> plcTriangles(const VolumePlc& plc, std::size_t first) {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (std::size_t t = first; t < plc.triangles.size(); ++t) {
    const PlcTriangle& c = plc.triangles[t];
    triangles.push_back({std::uint32_t(c[0]), std::uint32_t(c[1]), std::uint32_t(c[2])});
  }
  return triangles;
}

std::vector<std::array<std::uint32_t, 2>> plcSegments(const VolumePlc& plc) {
  std::vector<std::array<std::uint32_t, 2>> segments;
  for (const PlcSegment& s : plc.segments)
    segments.push_back({std::uint32_t(s[0]), std::uint32_t(s[1])});
  return segments;
}

void renumberPlc(VolumePlc& plc, std::vector<Vec3>& xyz, std::vector<double>& sizes,
                 std::size_t start) {
  const std::size_t n = plc.nodes.size();
  std::size_t stride = std::max<std::size_t>(start, 1);
  while (std::gcd(stride, n) != 1) ++stride;
  std::vector<int> to(n);
  for (std::size_t i = 0; i < n; ++i) to[i] = static_cast<int>(i * stride % n);
  std::vector<NodeIndex> nodes(n);
  std::vector<Vec3> places(n);
  std::vector<double> targets(n);
  for (std::size_t i = 0; i < n; ++i) {
    nodes[to[i]] = plc.nodes[i];
    places[to[i]] = xyz[i];
    targets[to[i]] = sizes[i];
  }
  plc.nodes = std::move(nodes);
  xyz = std::move(places);
  sizes = std::move(targets);
  for (PlcTriangle& t : plc.triangles)
    for (int& k : t) k = to[k];
  for (PlcSegment& s : plc.segments)
    for (int& k : s) k = to[k];
  for (int& k : plc.points) k = to[k];
  for (auto& q : plc.quads)
    for (int& k : q) k = to[k];
}

}  // namespace geomesh
