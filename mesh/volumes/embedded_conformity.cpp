// embeddedConformityDefects: embedded triangles, segments and points looked up among the tets.
#include "mesh/volumes/embedded_conformity.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <string>

#include "mesh/core/predicates.h"

namespace geomesh {

namespace {

using Face = std::array<NodeIndex, 3>;  // sorted

struct TetFace {
  Face face;
  NodeIndex apex;  // the tetrahedron's fourth node
  friend bool operator<(const TetFace& a, const TetFace& b) { return a.face < b.face; }
};

std::uint64_t edgeKey(NodeIndex a, NodeIndex b) {
  return a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
}

std::string near(Vec3 p) {
  return " near (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) +
         ")";
}

std::string nodeList(std::initializer_list<NodeIndex> nodes) {
  std::string text;
  for (NodeIndex n : nodes) text += (text.empty() ? "(" : ", ") + std::to_string(n + 1);
  return text + ")";
}

class ConformityCheck {
 public:
  ConformityCheck(const Mesh& mesh, const ElementBlock& tets, std::size_t limit)
      : mesh_(mesh), tets_(tets), limit_(limit) {}

  void checkSurface(int tag) {
    const EntityMesh* em = mesh_.find({2, tag});
    const ElementBlock* tris = em ? em->findBlock(ElementType::Triangle3) : nullptr;
    if (!tris) return;
    if (faces_.empty()) collectFaces();
    const std::string name = "embedded surface " + std::to_string(tag) + ": triangle ";
    for (std::size_t e = 0; e < tris->size(); ++e) {
      const auto t = tris->element(e);
      Face key{t[0], t[1], t[2]};
      std::sort(key.begin(), key.end());
      const auto [first, last] = std::equal_range(faces_.begin(), faces_.end(), TetFace{key, 0});
      const Vec3 a = mesh_.node(t[0]), b = mesh_.node(t[1]), c = mesh_.node(t[2]);
      const std::string where = nodeList({t[0], t[1], t[2]}) + near((a + b + c) / 3);
      if (last - first != 2)
        report(name + where + " is a face of " + std::to_string(last - first) +
               " tetrahedra instead of 2");
      else if (orient3d(a, b, c, mesh_.node(first->apex)) *
                   orient3d(a, b, c, mesh_.node((first + 1)->apex)) >=
               0)
        report(name + where + " has its two tetrahedra on the same side");
    }
  }

  void checkCurve(int tag) {
    const EntityMesh* em = mesh_.find({1, tag});
    const ElementBlock* lines = em ? em->findBlock(ElementType::Line2) : nullptr;
    if (!lines) return;
    if (edges_.empty()) collectEdges();
    for (std::size_t e = 0; e < lines->size(); ++e) {
      const NodeIndex a = lines->element(e)[0], b = lines->element(e)[1];
      if (!std::binary_search(edges_.begin(), edges_.end(), edgeKey(a, b)))
        report("embedded curve " + std::to_string(tag) + ": segment " + nodeList({a, b}) +
               near((mesh_.node(a) + mesh_.node(b)) / 2) + " is not an edge of the tetrahedra");
    }
  }

  void checkPoint(int tag) {
    const EntityMesh* em = mesh_.find({0, tag});
    if (!em || em->nodes.empty()) return;
    if (used_.empty()) {
      used_.assign(mesh_.nodeCount(), 0);
      for (NodeIndex n : tets_.nodes) used_[n] = 1;
    }
    const NodeIndex n = em->nodes.front();
    if (!used_[n])
      report("embedded point " + std::to_string(tag) + ": node " + std::to_string(n + 1) +
             near(mesh_.node(n)) + " is not a node of the tetrahedra");
  }

  std::vector<std::string> defects() { return std::move(defects_); }

 private:
  void report(std::string defect) {
    if (defects_.size() < limit_) defects_.push_back(std::move(defect));
  }

  void collectFaces() {
    for (std::size_t e = 0; e < tets_.size(); ++e) {
      const auto t = tets_.element(e);
      for (int k = 0; k < 4; ++k) {
        Face f{t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]};
        std::sort(f.begin(), f.end());
        faces_.push_back({f, t[k]});
      }
    }
    std::sort(faces_.begin(), faces_.end());
  }

  void collectEdges() {
    for (std::size_t e = 0; e < tets_.size(); ++e) {
      const auto t = tets_.element(e);
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) edges_.push_back(edgeKey(t[i], t[j]));
    }
    std::sort(edges_.begin(), edges_.end());
    edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
  }

  const Mesh& mesh_;
  const ElementBlock& tets_;
  std::size_t limit_;
  std::vector<TetFace> faces_;
  std::vector<std::uint64_t> edges_;
  std::vector<char> used_;
  std::vector<std::string> defects_;
};

}  // namespace

std::vector<std::string> embeddedConformityDefects(const ModelVolume& volume, const Mesh& mesh,
                                                   const ElementBlock& tets, std::size_t limit) {
  ConformityCheck check(mesh, tets, limit);
  for (int s : volume.embeddedSurfaces) check.checkSurface(s);
  for (int c : volume.embeddedCurves) check.checkCurve(c);
  for (int p : volume.embeddedPoints) check.checkPoint(p);
  return check.defects();
}

}  // namespace geomesh
