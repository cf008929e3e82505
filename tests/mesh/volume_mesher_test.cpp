// Tests of the volume mesher: cubes, holes, and rejected intersecting or folded boundaries.
#include "mesh/volumes/volume_mesher.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>

#include "mesh/pipeline/generate.h"

namespace geomesh {
namespace {

using Face = std::array<NodeIndex, 3>;

Face sorted(Face f) {
  std::sort(f.begin(), f.end());
  return f;
}

// Triangulates the surface of the box [lo, hi] with an n x n grid of split squares per face,
// one surface per face (tags firstTag..firstTag+5); odd faces are given reversed, to check
// that the mesher does not depend on the surfaces' orientation.
class BoxSurface {
 public:
  BoxSurface(Mesh& mesh, Vec3 lo, Vec3 hi, int n, int firstTag) : mesh_(mesh) {
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) addFace(lo, hi, n, axis, side, firstTag++);
  }
  std::vector<Face> faces;

 private:
  NodeIndex node(Vec3 p) {
    auto key = std::array{p.x, p.y, p.z};
    auto [it, inserted] = index_.try_emplace(key, 0);
    if (inserted) it->second = mesh_.addNode(p);
    return it->second;
  }

  void addFace(Vec3 lo, Vec3 hi, int n, int axis, int side, int tag) {
    auto at = [&](int i, int j) {
      double c[3];
      const double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
      c[axis] = side ? h[axis] : l[axis];
      const int a = (axis + 1) % 3, b = (axis + 2) % 3;
      c[a] = l[a] + (h[a] - l[a]) * i / n;
      c[b] = l[b] + (h[b] - l[b]) * j / n;
      return node({c[0], c[1], c[2]});
    };
    ElementBlock& tris = mesh_.entity({2, tag}).block(ElementType::Triangle3);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        Face t1{at(i, j), at(i + 1, j), at(i + 1, j + 1)};
        Face t2{at(i, j), at(i + 1, j + 1), at(i, j + 1)};
        for (Face t : {t1, t2}) {
          if (tag % 2) std::swap(t[0], t[1]);
          tris.nodes.insert(tris.nodes.end(), t.begin(), t.end());
          faces.push_back(t);
        }
      }
  }

  Mesh& mesh_;
  std::map<std::array<double, 3>, NodeIndex> index_;
};

Model boxModel(int shells) {
  Model model;
  std::vector<std::vector<int>> loops;
  for (int s = 0; s < shells; ++s) {
    loops.emplace_back();
    for (int t = 1; t <= 6; ++t) {
      model.addSurface({6 * s + t, {}, nullptr, {}, {}});
      loops.back().push_back(6 * s + t);
    }
  }
  model.addVolume({1, loops});
  return model;
}

double tetVolume(const Mesh& mesh, std::span<const NodeIndex> t) {
  const Vec3 a = mesh.node(t[0]);
  return dot(cross(mesh.node(t[1]) - a, mesh.node(t[2]) - a), mesh.node(t[3]) - a) / 6;
}

// Checks orientation, total volume and that each boundary triangle is the face of exactly one
// tetrahedron.
void expectValidTetMesh(const Mesh& mesh, const std::vector<Face>& boundary, double volume) {
  const ElementBlock* tets = mesh.find({3, 1})->findBlock(ElementType::Tet4);
  ASSERT_NE(tets, nullptr);
  double total = 0;
  std::map<Face, int> faceUses;
  for (std::size_t i = 0; i < tets->size(); ++i) {
    const auto t = tets->element(i);
    const double v = tetVolume(mesh, t);
    EXPECT_GT(v, 0) << "tetrahedron " << i;
    total += v;
    for (int k = 0; k < 4; ++k)
      ++faceUses[sorted({t[k], t[(k + 1) % 4], t[(k + 2) % 4]})];
  }
  EXPECT_NEAR(total, volume, 1e-12);
  for (const Face& f : boundary) EXPECT_EQ(faceUses[sorted(f)], 1);
  // Every other face is shared by two tetrahedra: the mesh is conforming.
  std::size_t boundaryFaces = 0;
  for (const auto& [face, uses] : faceUses) {
    EXPECT_LE(uses, 2);
    boundaryFaces += uses == 1;
  }
  EXPECT_EQ(boundaryFaces, boundary.size());
}

TEST(VolumeMesher, UnitCubeFromTwelveTriangles) {
  Mesh mesh;
  BoxSurface box(mesh, {0, 0, 0}, {1, 1, 1}, 1, 1);
  ASSERT_EQ(box.faces.size(), 12u);
  meshVolume(boxModel(1), MeshOptions{}, 1, nullptr, mesh);
  expectValidTetMesh(mesh, box.faces, 1);
}

TEST(VolumeMesher, FinerCubeGetsInteriorNodes) {
  Mesh mesh;
  BoxSurface box(mesh, {0, 0, 0}, {1, 1, 1}, 6, 1);
  const std::size_t boundaryNodes = mesh.nodeCount();
  meshVolume(boxModel(1), MeshOptions{}, 1, nullptr, mesh);
  expectValidTetMesh(mesh, box.faces, 1);
  const EntityMesh* em = mesh.find({3, 1});
  EXPECT_GT(em->nodes.size(), 0u);
  EXPECT_EQ(mesh.nodeCount(), boundaryNodes + em->nodes.size());
  for (NodeIndex n : em->nodes) {
    const Vec3 p = mesh.node(n);
    EXPECT_TRUE(p.x > 0 && p.x < 1 && p.y > 0 && p.y < 1 && p.z > 0 && p.z < 1);
  }
}

TEST(VolumeMesher, InnerShellIsAHole) {
  Mesh mesh;
  BoxSurface outer(mesh, {0, 0, 0}, {1, 1, 1}, 3, 1);
  BoxSurface inner(mesh, {0.25, 0.25, 0.25}, {0.75, 0.75, 0.75}, 2, 7);
  std::vector<Face> all = outer.faces;
  all.insert(all.end(), inner.faces.begin(), inner.faces.end());
  meshVolume(boxModel(2), MeshOptions{}, 1, nullptr, mesh);
  expectValidTetMesh(mesh, all, 1 - 0.125);
}

TEST(VolumeMesher, MissingSurfaceMeshNamesVolumeAndSurface) {
  Mesh mesh;
  BoxSurface box(mesh, {0, 0, 0}, {1, 1, 1}, 1, 1);
  Model model = boxModel(1);
  model.addSurface({7, {}, nullptr, {}, {}});
  model.addVolume({1, {{1, 2, 3, 4, 5, 6, 7}}});
  try {
    meshVolume(model, MeshOptions{}, 1, nullptr, mesh);
    FAIL() << "no error";
  } catch (const MeshError& e) {
    EXPECT_EQ(e.entity, (EntityId{3, 1}));
    EXPECT_NE(std::string(e.what()).find("surface 7 has no triangle mesh"), std::string::npos);
  }
  EXPECT_THROW(meshVolume(model, MeshOptions{}, 2, nullptr, mesh), MeshError);
}

TEST(VolumeMesher, IntersectingBoundaryIsAnError) {
  Mesh mesh;
  BoxSurface a(mesh, {0, 0, 0}, {1, 1, 1}, 1, 1);
  BoxSurface b(mesh, {0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}, 1, 7);
  Model model = boxModel(2);
  model.addVolume({1, {{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}}});
  try {
    meshVolume(model, MeshOptions{}, 1, nullptr, mesh);
    FAIL() << "no error";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("boundary intersects itself"), std::string::npos)
        << e.what();
  }
}

// Two boxes touching along a face, each with its own nodes there: overlapping coplanar
// triangles, not a valid boundary.
TEST(VolumeMesher, OverlappingCoplanarTrianglesAreAnError) {
  Mesh mesh;
  BoxSurface a(mesh, {0, 0, 0}, {1, 1, 1}, 2, 1);
  Mesh other;
  BoxSurface b(other, {1, 0, 0}, {2, 1, 1}, 3, 7);
  // Copy the second box into the first mesh with fresh node indices.
  const NodeIndex offset = static_cast<NodeIndex>(mesh.nodeCount());
  for (std::size_t i = 0; i < other.nodeCount(); ++i) mesh.addNode(other.node(i));
  for (int s = 7; s <= 12; ++s) {
    ElementBlock& tris = mesh.entity({2, s}).block(ElementType::Triangle3);
    for (NodeIndex n : other.find({2, s})->findBlock(ElementType::Triangle3)->nodes)
      tris.nodes.push_back(n + offset);
  }
  Model model = boxModel(2);
  model.addVolume({1, {{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}}});
  EXPECT_THROW(meshVolume(model, MeshOptions{}, 1, nullptr, mesh), MeshError);
}

// A face folded onto its neighbour: two triangles sharing an edge, on the same side of it.
TEST(VolumeMesher, FoldedBoundaryIsAnError) {
  Mesh mesh;
  BoxSurface box(mesh, {0, 0, 0}, {1, 1, 1}, 1, 1);
  // Move the node at (1, 1, 1) into the plane z = 0, inside the bottom face.
  for (NodeIndex i = 0; i < mesh.nodeCount(); ++i)
    if (mesh.node(i) == Vec3{1, 1, 1}) mesh.setNode(i, {0.25, 0.5, 0});
  EXPECT_THROW(meshVolume(boxModel(1), MeshOptions{}, 1, nullptr, mesh), MeshError);
}

}  // namespace
}  // namespace geomesh
