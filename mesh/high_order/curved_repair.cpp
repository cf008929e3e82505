// Repair of curved elements: a Laplacian of the high-order nodes' displacements spreads the
// boundary's curvature into the free nodes around bad elements; elements still invalid are
// straightened, and so are the neighbours that this makes invalid, until none is left.
#include "mesh/high_order/curved_repair.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "mesh/high_order/jacobian.h"
#include "mesh/high_order/reference_element.h"

namespace geomesh {
namespace {

struct ElementRef {
  EntityId entity;
  std::uint32_t block = 0;
  std::uint32_t index = 0;
};

class CurvedElements {
 public:
  CurvedElements(const Model& model, Mesh& mesh) : model_(model), mesh_(mesh) {
    for (auto& [id, em] : mesh_.entities()) {
      for (std::size_t b = 0; b < em.blocks.size(); ++b) {
        const ElementBlock& block = em.blocks[b];
        if (order(block.type) < 2 || dimension(block.type) < 1) continue;
        for (std::size_t e = 0; e < block.size(); ++e)
          elements_.push_back({id, static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(e)});
      }
    }
    home_.assign(mesh_.nodeCount(), EntityId{-1, 0});
    for (const auto& [id, em] : mesh_.entities())
      for (NodeIndex n : em.nodes) home_[n] = id;
    buildAdjacency();
  }

  std::size_t size() const { return elements_.size(); }

  std::span<const NodeIndex> nodes(std::size_t e) const {
    const ElementRef& r = elements_[e];
    return mesh_.find(r.entity)->blocks[r.block].element(r.index);
  }
  ElementType type(std::size_t e) const {
    const ElementRef& r = elements_[e];
    return mesh_.find(r.entity)->blocks[r.block].type;
  }
  int dim(std::size_t e) const { return dimension(type(e)); }

  std::vector<Vec3> points(std::size_t e) const {
    std::vector<Vec3> x;
    for (NodeIndex n : nodes(e)) x.push_back(mesh_.node(n));
    return x;
  }
  double scaledJacobian(std::size_t e) const { return geomesh::scaledJacobian(type(e), points(e)); }
  bool isCurved(std::size_t e) const { return !isStraight(type(e), points(e)); }

  // Where high-order node k of element e sits on its straight (first-order) element.
  Vec3 straightPosition(std::size_t e, std::size_t k) const {
    const ReferenceElement& ref = referenceElement(type(e));
    return linearImage(ref.family, ref.xi[k], points(e));
  }

  // Puts every high-order node of e on the straight element; returns the nodes moved.
  std::vector<NodeIndex> straighten(std::size_t e) {
    std::vector<NodeIndex> moved;
    const std::span<const NodeIndex> c = nodes(e);
    const ReferenceElement& ref = referenceElement(type(e));
    const std::vector<Vec3> now = points(e);
    for (std::size_t k = vertexCount(type(e)); k < c.size(); ++k) {
      const Vec3 x = linearImage(ref.family, ref.xi[k], now);
      if (mesh_.node(c[k]) == x) continue;
      mesh_.setNode(c[k], x);
      moved.push_back(c[k]);
    }
    return moved;
  }

  std::span<const std::uint32_t> elementsAt(NodeIndex n) const {
    return {around_.data() + start_[n], around_.data() + start_[n + 1]};
  }
  EntityId home(NodeIndex n) const { return home_[n]; }
  const Model& model() const { return model_; }
  Mesh& mesh() { return mesh_; }

 private:
  void buildAdjacency() {
    start_.assign(mesh_.nodeCount() + 1, 0);
    for (std::size_t e = 0; e < elements_.size(); ++e)
      for (NodeIndex n : nodes(e)) ++start_[n + 1];
    for (std::size_t n = 0; n < mesh_.nodeCount(); ++n) start_[n + 1] += start_[n];
    around_.resize(start_.back());
    std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
    for (std::size_t e = 0; e < elements_.size(); ++e)
      for (NodeIndex n : nodes(e)) around_[next[n]++] = static_cast<std::uint32_t>(e);
  }

  const Model& model_;
  Mesh& mesh_;
  std::vector<ElementRef> elements_;
  std::vector<EntityId> home_;  // the entity each node is classified on
  std::vector<std::uint32_t> start_, around_;
};

// Whether a node may move freely: it lies inside a volume, or inside a plane surface.
bool isFree(const CurvedElements& all, NodeIndex n, int dim) {
  const EntityId home = all.home(n);
  if (home.dim != dim) return false;
  if (dim == 3) return true;
  if (dim != 2) return false;
  const ModelSurface* surface = all.model().surface(home.tag);
  return surface && surface->geometry && surface->geometry->isPlane();
}

std::vector<std::size_t> layersAround(const CurvedElements& all, const std::vector<std::size_t>& bad,
                                      int layers) {
  std::set<std::size_t> patch(bad.begin(), bad.end());
  std::vector<std::size_t> front = bad;
  for (int layer = 0; layer < layers && !front.empty(); ++layer) {
    std::vector<std::size_t> next;
    for (std::size_t e : front)
      for (NodeIndex n : all.nodes(e))
        for (std::uint32_t f : all.elementsAt(n))
          if (all.dim(f) == all.dim(e) && patch.insert(f).second) next.push_back(f);
    front = std::move(next);
  }
  return {patch.begin(), patch.end()};
}

double worstOf(const CurvedElements& all, const std::vector<std::size_t>& elements) {
  double worst = 1;
  for (std::size_t e : elements) worst = std::min(worst, all.scaledJacobian(e));
  return worst;
}

// Spreads the displacement of fixed high-order nodes (curved boundary) into the free ones of
// the patch by Jacobi sweeps of a graph Laplacian; kept only if the patch's worst element got
// better. Returns whether it did.
bool relaxPatch(CurvedElements& all, const std::vector<std::size_t>& patch) {
  std::unordered_map<NodeIndex, std::uint32_t> local;
  std::vector<NodeIndex> node;
  std::vector<Vec3> straight, shift;
  std::vector<char> free;
  for (std::size_t e : patch) {
    const std::span<const NodeIndex> c = all.nodes(e);
    for (std::size_t k = vertexCount(all.type(e)); k < c.size(); ++k) {
      if (!local.emplace(c[k], static_cast<std::uint32_t>(node.size())).second) continue;
      node.push_back(c[k]);
      straight.push_back(all.straightPosition(e, k));
      shift.push_back(all.mesh().node(c[k]) - straight.back());
      free.push_back(isFree(all, c[k], all.dim(e)));
    }
  }
  // Neighbours of each free node: the high-order nodes of the patch sharing an element with it.
  std::vector<std::uint32_t> start{0}, around;
  for (std::size_t i = 0; i < node.size(); ++i) {
    if (free[i])
      for (std::uint32_t e : all.elementsAt(node[i])) {
        const std::span<const NodeIndex> c = all.nodes(e);
        for (std::size_t k = vertexCount(all.type(e)); k < c.size(); ++k)
          if (auto it = local.find(c[k]); it != local.end() && it->second != i)
            around.push_back(it->second);
      }
    start.push_back(static_cast<std::uint32_t>(around.size()));
  }
  if (std::none_of(free.begin(), free.end(), [](char f) { return f != 0; })) return false;
  const double before = worstOf(all, patch);
  std::vector<Vec3> next = shift;
  for (int sweep = 0; sweep < 40; ++sweep) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      if (!free[i] || start[i] == start[i + 1]) continue;
      Vec3 sum{0, 0, 0};
      for (std::uint32_t j = start[i]; j < start[i + 1]; ++j) sum += shift[around[j]];
      next[i] = sum / double(start[i + 1] - start[i]);
    }
    shift.swap(next);
    next = shift;
  }
  std::vector<Vec3> original(node.size());
  for (std::size_t i = 0; i < node.size(); ++i) {
    original[i] = all.mesh().node(node[i]);
    if (free[i]) all.mesh().setNode(node[i], straight[i] + shift[i]);
  }
  if (worstOf(all, patch) > before) return true;
  for (std::size_t i = 0; i < node.size(); ++i) all.mesh().setNode(node[i], original[i]);
  return false;
}

void forgetParameters(Mesh& mesh, const std::vector<NodeIndex>& moved, const CurvedElements& all) {
  std::set<int> dims;
  for (NodeIndex n : moved) dims.insert(all.home(n).dim);
  if (!dims.contains(1) && !dims.contains(2)) return;
  std::unordered_set<NodeIndex> set(moved.begin(), moved.end());
  for (const auto& entry : mesh.entities()) {
    if (entry.first.dim != 1 && entry.first.dim != 2) continue;
    EntityMesh& em = mesh.entity(entry.first);
    if (std::any_of(em.nodes.begin(), em.nodes.end(), [&](NodeIndex n) { return set.contains(n); }))
      em.parametric.clear();
  }
}

}  // namespace

void repairCurvedElements(const Model& model, const MeshOptions& options, Mesh& mesh,
                          MessageSink& log, HighOrderSummary& summary) {
  CurvedElements all(model, mesh);
  std::vector<std::size_t> invalid, poor;
  for (std::size_t e = 0; e < all.size(); ++e) {
    if (!all.isCurved(e)) continue;
    const double s = all.scaledJacobian(e);
    if (s <= 0) invalid.push_back(e);
    if (s < options.highOrderThresholdMin) poor.push_back(e);
  }
  summary.invalidFound = invalid.size();
  if (options.highOrderOptimize > 0 && !poor.empty()) {
    relaxPatch(all, layersAround(all, poor, std::max(options.highOrderNumLayers, 1)));
    std::vector<std::size_t> still;
    for (std::size_t e : invalid)
      if (all.scaledJacobian(e) <= 0) still.push_back(e);
    summary.repaired = invalid.size() - still.size();
    invalid = std::move(still);
  }
  std::vector<NodeIndex> movedAll;
  std::set<std::size_t> straightened;
  while (!invalid.empty()) {
    std::set<std::size_t> recheck;
    for (std::size_t e : invalid) {
      straightened.insert(e);
      for (NodeIndex n : all.straighten(e)) {
        movedAll.push_back(n);
        for (std::uint32_t f : all.elementsAt(n)) recheck.insert(f);
      }
    }
    invalid.clear();
    for (std::size_t f : recheck)
      if (!straightened.contains(f) && all.scaledJacobian(f) <= 0) invalid.push_back(f);
  }
  summary.straightened = straightened.size();
  forgetParameters(mesh, movedAll, all);
  if (summary.repaired > 0)
    log.info(std::to_string(summary.repaired) +
             " invalid curved elements made valid by moving their free high-order nodes");
  if (summary.straightened > 0)
    log.warning(std::to_string(summary.straightened) +
                " curved elements were invalid (Jacobian changing sign) and were straightened");
}

}  // namespace geomesh
