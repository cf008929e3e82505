// Homology and cohomology bases of small complexes whose spaces are known: ranks, cycles that
// are closed, cocycles that vanish on boundaries, and bases that pair unimodularly (so that no
// basis element is homologous to zero).
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>

#include "mesh/homology/cell_complex.h"
#include "mesh/homology/homology.h"
#include "mesh/homology/homology_bases.h"
#include "mesh/homology/integer_homology.h"

namespace geomesh {
namespace {

ComplexElement element(ElementFamily family, std::initializer_list<NodeIndex> corners) {
  ComplexElement e;
  e.family = family;
  std::copy(corners.begin(), corners.end(), e.corners.begin());
  return e;
}

// A closed polygon of n line elements.
std::vector<ComplexElement> circle(NodeIndex n) {
  std::vector<ComplexElement> out;
  for (NodeIndex i = 0; i < n; ++i) out.push_back(element(ElementFamily::Line, {i, (i + 1) % n}));
  return out;
}

// An n x m grid of squares split into triangles; `wrapI` / `wrapJ` glue opposite sides.
std::vector<ComplexElement> triangleGrid(int n, int m, bool wrapI, bool wrapJ,
                                         const std::vector<std::pair<int, int>>& holes = {}) {
  const int rowsI = wrapI ? n : n + 1, rowsJ = wrapJ ? m : m + 1;
  auto id = [&](int i, int j) { return static_cast<NodeIndex>((i % rowsI) * rowsJ + j % rowsJ); };
  std::vector<ComplexElement> out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      if (std::find(holes.begin(), holes.end(), std::pair{i, j}) != holes.end()) continue;
      const NodeIndex a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      out.push_back(element(ElementFamily::Triangle, {a, b, c}));
      out.push_back(element(ElementFamily::Triangle, {a, c, d}));
    }
  return out;
}

// An n x n x 1 block of unit cubes without its middle column of cubes (a thick ring): as
// hexahedra, or as six tetrahedra each (all cubes split the same way, so they match).
std::vector<ComplexElement> ringOfCubes(int n, bool tetrahedra) {
  auto id = [&](int x, int y, int z) {
    return static_cast<NodeIndex>((z * (n + 1) + y) * (n + 1) + x);
  };
  std::vector<ComplexElement> out;
  for (int x = 0; x < n; ++x)
    for (int y = 0; y < n; ++y) {
      if (x == n / 2 && y == n / 2) continue;
      const NodeIndex v[8] = {id(x, y, 0), id(x + 1, y, 0), id(x + 1, y + 1, 0), id(x, y + 1, 0),
                              id(x, y, 1), id(x + 1, y, 1), id(x + 1, y + 1, 1), id(x, y + 1, 1)};
      if (!tetrahedra) {
        out.push_back(
            element(ElementFamily::Hex, {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]}));
        continue;
      }
      // Paths from corner 0 to corner 6 along the axes, one tetrahedron per path.
      const int paths[6][2] = {{1, 2}, {1, 5}, {3, 2}, {3, 7}, {4, 5}, {4, 7}};
      for (const auto& p : paths)
        out.push_back(element(ElementFamily::Tet, {v[0], v[p[0]], v[p[1]], v[6]}));
    }
  return out;
}

// The boundary of a chain (homology) or coboundary of a cochain (cohomology) in the complex.
std::map<CellId, std::int64_t> boundaryOf(const CellComplex& complex, const Chain& chain,
                                          HomologyKind kind) {
  std::map<CellId, std::int64_t> out;
  for (const auto& [cell, coef] : chain) {
    const auto incidences =
        kind == HomologyKind::Homology ? complex.faces(cell) : complex.cofaces(cell);
    for (const Incidence& f : incidences) out[f.cell] += coef * f.sign;
  }
  std::erase_if(out, [](const auto& entry) { return entry.second == 0; });
  return out;
}

std::int64_t determinant(std::vector<std::vector<std::int64_t>> a) {
  // Bareiss elimination: exact on integers.
  const std::size_t n = a.size();
  std::int64_t sign = 1, previous = 1;
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;
    while (p < n && a[p][k] == 0) ++p;
    if (p == n) return 0;
    if (p != k) {
      std::swap(a[p], a[k]);
      sign = -sign;
    }
    for (std::size_t i = k + 1; i < n; ++i)
      for (std::size_t j = k + 1; j < n; ++j)
        a[i][j] = (a[i][j] * a[k][k] - a[i][k] * a[k][j]) / previous;
    previous = a[k][k];
  }
  return sign * a[n - 1][n - 1];
}

// Computes both bases and checks everything that must hold of them; returns the ranks.
std::array<int, 4> checkedRanks(std::span<const ComplexElement> domain,
                                std::span<const ComplexElement> subdomain = {}) {
  const CellComplex complex = buildCellComplex(domain, subdomain);
  const HomologyBases h = computeHomologyBases(complex, HomologyKind::Homology);
  const HomologyBases c = computeHomologyBases(complex, HomologyKind::Cohomology);
  EXPECT_EQ(h.ranks, c.ranks) << "homology and cohomology ranks differ";
  for (int dim = 0; dim <= 3; ++dim) {
    EXPECT_EQ(h.generators[dim].size(), static_cast<std::size_t>(h.ranks[dim]));
    EXPECT_EQ(c.generators[dim].size(), static_cast<std::size_t>(c.ranks[dim]));
    for (const Chain& z : h.generators[dim]) {
      EXPECT_FALSE(z.empty());
      for (const auto& [cell, coef] : z) EXPECT_EQ(complex.dimension(cell), dim);
      EXPECT_TRUE(boundaryOf(complex, z, HomologyKind::Homology).empty())
          << "open cycle, dim " << dim;
    }
    for (const Chain& phi : c.generators[dim])
      EXPECT_TRUE(boundaryOf(complex, phi, HomologyKind::Cohomology).empty())
          << "cochain with a coboundary, dim " << dim;
    // A cocycle vanishes on boundaries: a unimodular pairing shows every cycle is none.
    if (h.ranks[dim] == 0 || h.ranks[dim] != c.ranks[dim]) continue;
    std::vector<std::vector<std::int64_t>> pairing(h.ranks[dim],
                                                   std::vector<std::int64_t>(h.ranks[dim], 0));
    for (int i = 0; i < h.ranks[dim]; ++i)
      for (int j = 0; j < h.ranks[dim]; ++j) {
        std::map<CellId, std::int64_t> values(c.generators[dim][j].begin(),
                                              c.generators[dim][j].end());
        for (const auto& [cell, coef] : h.generators[dim][i])
          if (auto it = values.find(cell); it != values.end()) pairing[i][j] += coef * it->second;
      }
    EXPECT_EQ(std::llabs(determinant(pairing)), 1) << "dimension " << dim;
  }
  return h.ranks;
}

TEST(CellComplex, CountsAndBoundaryOfBoundary) {
  const auto torus = triangleGrid(4, 5, true, true);
  const CellComplex complex = buildCellComplex(torus, {});
  EXPECT_EQ(complex.count(0), 20u);
  EXPECT_EQ(complex.count(1), 60u);
  EXPECT_EQ(complex.count(2), 40u);
  for (CellId c = complex.first(2); c < complex.first(3); ++c) {
    std::map<CellId, std::int64_t> bb;
    for (const Incidence& e : complex.faces(c))
      for (const Incidence& v : complex.faces(e.cell)) bb[v.cell] += e.sign * v.sign;
    for (const auto& [v, coef] : bb) EXPECT_EQ(coef, 0);
  }
}

TEST(CellComplex, HexahedraAndTetrahedraHaveConsistentFaces) {
  for (bool tets : {false, true}) {
    const CellComplex complex = buildCellComplex(ringOfCubes(3, tets), {});
    for (CellId c = complex.first(3); c < complex.first(3) + complex.count(3); ++c) {
      std::map<CellId, std::int64_t> bb;
      for (const Incidence& f : complex.faces(c))
        for (const Incidence& e : complex.faces(f.cell)) bb[e.cell] += f.sign * e.sign;
      for (const auto& [e, coef] : bb) EXPECT_EQ(coef, 0) << (tets ? "tet" : "hex");
    }
  }
}

TEST(Homology, CircleHasOneLoop) {
  EXPECT_EQ(checkedRanks(circle(7)), (std::array<int, 4>{1, 1, 0, 0}));
}

TEST(Homology, TorusSurfaceHasTwoLoopsAndOneShell) {
  EXPECT_EQ(checkedRanks(triangleGrid(4, 5, true, true)), (std::array<int, 4>{1, 2, 1, 0}));
}

TEST(Homology, SquareWithThreeHolesHasThreeLoops) {
  const auto plate = triangleGrid(7, 3, false, false, {{1, 1}, {3, 1}, {5, 1}});
  EXPECT_EQ(checkedRanks(plate), (std::array<int, 4>{1, 3, 0, 0}));
}

TEST(Homology, CylinderRelativeToItsEnds) {
  // Around (i, wrapped) times along (j): the two end circles are j = 0 and j = 4.
  const int around = 6, along = 4;
  const auto cylinder = triangleGrid(around, along, true, false);
  std::vector<ComplexElement> ends;
  for (int i = 0; i < around; ++i)
    for (int j : {0, along}) {
      auto id = [&](int a) { return static_cast<NodeIndex>((a % around) * (along + 1) + j); };
      ends.push_back(element(ElementFamily::Line, {id(i), id(i + 1)}));
    }
  EXPECT_EQ(checkedRanks(cylinder), (std::array<int, 4>{1, 1, 0, 0}));
  EXPECT_EQ(checkedRanks(cylinder, ends), (std::array<int, 4>{0, 1, 1, 0}));
}

TEST(Homology, RingOfCubesAsHexahedraAndTetrahedra) {
  for (bool tets : {false, true}) {
    const auto ring = ringOfCubes(3, tets);
    EXPECT_EQ(checkedRanks(ring), (std::array<int, 4>{1, 1, 0, 0})) << (tets ? "tet" : "hex");
  }
}

TEST(Homology, EmptyComplexHasNothing) {
  EXPECT_EQ(checkedRanks({}), (std::array<int, 4>{0, 0, 0, 0}));
}

TEST(IntegerHomology, TorsionOfTheProjectivePlaneBoundaryMap) {
  // One cell per level, the 2-cell wrapping twice round the loop: H_1 = Z/2, H_2 = 0.
  const IntegerMatrix d2 = {{2}};
  const IntegerHomology h1 = integerHomology({{0}}, d2, 1);
  EXPECT_TRUE(h1.freeBasis.empty());
  EXPECT_EQ(h1.torsion, (std::vector<std::int64_t>{2}));
  const IntegerHomology h2 = integerHomology(d2, {}, 1);
  EXPECT_TRUE(h2.freeBasis.empty());
}

TEST(IntegerHomology, KernelBasisModuloImage) {
  // Three edges of a triangle without its face, then with it.
  const IntegerMatrix d1 = {{-1, 0, 1}, {1, -1, 0}, {0, 1, -1}};
  const IntegerHomology open = integerHomology(d1, {}, 3);
  ASSERT_EQ(open.freeBasis.size(), 1u);
  const auto& z = open.freeBasis[0];
  EXPECT_TRUE(std::llabs(z[0]) == 1 && z[0] == z[1] && z[1] == z[2]);
  const IntegerHomology filled = integerHomology(d1, {{1}, {1}, {1}}, 3);
  EXPECT_TRUE(filled.freeBasis.empty());
  EXPECT_TRUE(filled.torsion.empty());
}

TEST(ComputeHomology, SavesEachBasisChainAsANamedPhysicalGroup) {
  // A plate with three holes as surface 1, its left and right sides as curves 1 and 2.
  Model model;
  Mesh mesh;
  const int n = 7, m = 3;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) mesh.addNode({double(i), double(j), 0});
  EntityMesh& plate = mesh.entity({2, 1});
  for (const ComplexElement& e : triangleGrid(n, m, false, false, {{1, 1}, {3, 1}, {5, 1}}))
    plate.block(ElementType::Triangle3)
        .nodes.insert(plate.block(ElementType::Triangle3).nodes.end(), e.corners.begin(),
                      e.corners.begin() + 3);
  for (int side : {0, 1}) {
    EntityMesh& em = mesh.entity({1, side + 1});
    const int i = side == 0 ? 0 : n;
    for (int j = 0; j < m; ++j)
      em.block(ElementType::Line2)
          .nodes.insert(em.block(ElementType::Line2).nodes.end(),
                        {NodeIndex(i * (m + 1) + j), NodeIndex(i * (m + 1) + j + 1)});
  }
  model.addSurface({1, {}, nullptr, {}, {}});
  model.addCurve({1, 0, 0, nullptr});
  model.addCurve({2, 0, 0, nullptr});
  model.addPhysicalGroup({2, 5, "", {1}});
  model.addPhysicalGroup({1, 6, "", {1, 2}});
  std::vector<HomologyRequest> requests(2);
  requests[0].domain = {5};
  requests[0].subdomain = {6};
  requests[1] = requests[0];
  requests[1].kind = HomologyKind::Cohomology;
  requests[1].dims = {1};
  SilentSink log;
  computeHomology(requests, model, mesh, log);

  std::vector<std::string> names;
  for (const auto& [id, group] : model.physicalGroups())
    if (id.tag > 6) {
      EXPECT_EQ(id.dim, 1);
      ASSERT_EQ(group.entities.size(), 1u);
      EXPECT_GT(mesh.find({1, group.entities[0]})->elementCount(), 0u);
      names.push_back(group.name);
    }
  // Relative to both sides: a path across the plate besides the three loops.
  EXPECT_EQ(names,
            (std::vector<std::string>{"H_1{5},{6}1", "H_1{5},{6}2", "H_1{5},{6}3", "H_1{5},{6}4",
                                      "H^1{5},{6}1", "H^1{5},{6}2", "H^1{5},{6}3", "H^1{5},{6}4"}));
  EXPECT_TRUE(model.physicalGroups().contains({1, 14}));  // numbered after the largest, 6
  EXPECT_EQ(model.maxTag(1), 10);  // entities 3 to 10, numbered after the largest tag
}

}  // namespace
}  // namespace geomesh
