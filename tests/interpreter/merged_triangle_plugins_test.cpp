// Plugins on merged triangulations from scripts: Simplify and Fair change the merged triangles
// (before ClassifySurfaces), Curvature and VertexNormals make views of them, and Merge tells
// of a file's holes and non-manifold edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "api/meshing.h"
#include "api/output.h"
#include "mesh/discrete/mesh_triangles.h"
#include "mesh/discrete/surface_topology.h"
#include "script_runner.h"
#include "scratch_dir_test.h"

namespace geomesh::testing {
namespace {

using Facet = std::array<Vec3, 3>;

// A sphere of radius r: the octahedron's faces cut n x n (8 n^2 triangles, outwards), pushed
// onto the sphere, each vertex off it by up to `noise` times r (a fixed pattern).
std::vector<Facet> sphereFacets(double r, int n, double noise) {
  std::map<std::array<long, 3>, Vec3> points;
  auto point = [&](Vec3 p) {
    const std::array<long, 3> key{std::lround(p.x * n), std::lround(p.y * n), std::lround(p.z * n)};
    const auto [it, added] = points.try_emplace(key);
    if (added) {
      const double wobble = std::sin(12.9898 * key[0] + 78.233 * key[1] + 37.719 * key[2]);
      it->second = r * (1 + noise * wobble) * normalized(p);
    }
    return it->second;
  };
  std::vector<Facet> facets;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1}) {
        const Vec3 a{double(sx), 0, 0}, b{0, double(sy), 0}, c{0, 0, double(sz)};
        auto at = [&](int i, int j) {
          return a + (double(i) / n) * (b - a) + (double(j) / n) * (c - a);
        };
        for (int i = 0; i < n; ++i)
          for (int j = 0; i + j < n; ++j) {
            std::vector<Facet> quad = {{point(at(i, j)), point(at(i + 1, j)), point(at(i, j + 1))}};
            if (i + j + 1 < n)
              quad.push_back({point(at(i + 1, j)), point(at(i + 1, j + 1)), point(at(i, j + 1))});
            for (Facet& f : quad) {
              if (sx * sy * sz < 0) std::swap(f[1], f[2]);
              facets.push_back(f);
            }
          }
      }
  return facets;
}

// One solid of the facets; with `split`, two: those above z = 0 and those below.
void writeStl(const std::filesystem::path& path, const std::vector<Facet>& facets,
              bool split = false) {
  std::ofstream out(path);
  out.precision(17);
  for (int part = 0; part < (split ? 2 : 1); ++part) {
    out << "solid scan\n";
    for (const Facet& f : facets) {
      if (split && (f[0].z + f[1].z + f[2].z > 0) != (part == 0)) continue;
      out << "facet normal 0 0 0\nouter loop\n";
      for (const Vec3& p : f) out << "vertex " << p.x << ' ' << p.y << ' ' << p.z << '\n';
      out << "endloop\nendfacet\n";
    }
    out << "endsolid scan\n";
  }
}

bool hasMessage(const std::vector<std::string>& messages, const std::string& part) {
  return std::any_of(messages.begin(), messages.end(),
                     [&](const std::string& m) { return m.find(part) != std::string::npos; });
}

class MergedTrianglePlugins : public ScratchDirTest {
 protected:
  MergedTrianglePlugins() : ScratchDirTest("merged-plugins-") {}
  // A noisy sphere of radius 2 in 800 triangles, as scan.stl.
  void writeScan(double noise = 0.01) { writeStl(dir_ / "scan.stl", sphereFacets(2, 10, noise)); }
};

TEST_F(MergedTrianglePlugins, SimplifyLeavesFewerTrianglesThatCanBeClassifiedAndMeshed) {
  writeScan();
  ScriptRun run;
  runMain(run, R"(
    Merge "scan.stl";
    Plugin(Simplify).TargetTriangles = 300;
    Plugin(Simplify).Run;
  )");
  EXPECT_TRUE(hasMessage(run.log.infos, "Plugin(Simplify): 800 -> 300 triangles"));
  // The session's mesh, still the file's, is the simplified one (Save writes it).
  EXPECT_EQ(run.session.mesh().elementCount(2), 300u);
  ScriptRun remesh;
  runMain(remesh, R"(
    Merge "scan.stl";
    Plugin(Simplify).TargetTriangles = 300;
    Plugin(Simplify).Run;
    ClassifySurfaces{40 * Pi / 180, 1, 1, Pi};
    CreateGeometry;
    Mesh.MeshSizeMax = 0.5;
  )");
  api::generate(remesh.session, 2);
  EXPECT_GT(remesh.session.mesh().elementCount(2), 100u);
}

TEST_F(MergedTrianglePlugins, EachMergedSurfaceIsSimplifiedApartAndTheirSeamKept) {
  writeStl(dir_ / "halves.stl", sphereFacets(2, 10, 0.01), true);
  ScriptRun run;
  runMain(run, R"(
    Merge "halves.stl";
    Plugin(Simplify).TargetTriangles = 200;
    Plugin(Simplify).Run;
  )");
  const Mesh& mesh = run.session.mesh();
  ASSERT_NE(mesh.find({2, 1}), nullptr);
  ASSERT_NE(mesh.find({2, 2}), nullptr);
  // Each its share of the target, less a flap both made across the seam, dropped twice.
  for (int tag : {1, 2}) {
    EXPECT_LE(mesh.find({2, tag})->elementCount(), 100u);
    EXPECT_GE(mesh.find({2, tag})->elementCount(), 90u);
  }
  // Still one closed surface: the halves share the nodes of their seam.
  const MeshTriangles all = meshTriangles(mesh);
  const Triangulation* merged = run.session.mergedTriangulation();
  ASSERT_NE(merged, nullptr);
  EXPECT_EQ(surfaceTopology(*merged).vertices, merged->points.size());  // each has a triangle
  const SurfaceTopologyReport topology = surfaceTopology(all.triangulation);
  EXPECT_EQ(topology.components, 1);
  EXPECT_EQ(topology.boundaryLoops, 0);
  EXPECT_EQ(topology.euler, 2);
  EXPECT_EQ(topology.inconsistentEdges, 0u);
  EXPECT_EQ(topology.nonManifoldEdges, 0u);
}

TEST_F(MergedTrianglePlugins, MaxErrorBoundsHowFarTheSurfaceMoves) {
  writeScan();
  auto simplified = [&](const std::string& bound) {
    ScriptRun run;
    runMain(run, "Merge \"scan.stl\";\nPlugin(Simplify).MaxError = " + bound +
                     ";\nPlugin(Simplify).Run;\n");
    return run.session.mesh().elementCount(2);
  };
  EXPECT_EQ(simplified("1e-9"), 800u);  // every collapse moves a noisy vertex farther
  const std::size_t some = simplified("0.02"), more = simplified("0.2");
  EXPECT_LT(some, 800u);
  EXPECT_LT(more, some);
}

TEST_F(MergedTrianglePlugins, SimplifyWithoutTargetNorBoundIsALocatedError) {
  writeScan();
  ScriptRun run;
  try {
    runMain(run, "Merge \"scan.stl\";\nPlugin(Simplify).Run;\n");
    FAIL() << "no error";
  } catch (const ScriptError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("main.geo:2:1: error: Plugin(Simplify) needs TargetTriangles (a triangle "
                        "count) or MaxError (a distance)"),
              std::string::npos)
        << what;
  }
}

TEST_F(MergedTrianglePlugins, WithoutMergedTrianglesThePluginsWarnAndDoNothing) {
  ScriptRun run;
  run.run(R"(
    Plugin(Simplify).TargetTriangles = 10;
    Plugin(Simplify).Run;
    Plugin(Fair).Run;
    Plugin(Curvature).Run;
    Plugin(VertexNormals).Run;
  )");
  EXPECT_TRUE(hasMessage(run.log.warnings,
                         "test.geo:3:5: warning: Plugin(Simplify): there are no merged "
                         "triangles (merge an STL, PLY or OFF file first); nothing done"));
  EXPECT_TRUE(hasMessage(run.log.warnings, "Plugin(Fair): there are no merged triangles"));
  EXPECT_TRUE(hasMessage(run.log.warnings,
                         "Plugin(Curvature): there is no surface mesh and no merged "
                         "triangulation; nothing done"));
  EXPECT_TRUE(hasMessage(run.log.warnings, "Plugin(VertexNormals): there is no surface mesh"));
  EXPECT_EQ(run.session.views().size(), 0u);
}

TEST_F(MergedTrianglePlugins, FairingSmoothsTheNoiseTheCurvatureViewShows) {
  writeScan(0.02);
  ScriptRun run;
  const std::string printed = runMain(run, R"(
    Merge "scan.stl";
    Plugin(Curvature).Run;
    Plugin(Fair).Iterations = 3;
    Plugin(Fair).Run;
    Plugin(Curvature).Run;
    Printf("%.6f %.6f %.6f %.6f", View[0].Min, View[0].Max, View[1].Min, View[1].Max);
  )");
  double min0, max0, min1, max1;
  ASSERT_EQ(std::sscanf(printed.c_str(), "%lf %lf %lf %lf", &min0, &max0, &min1, &max1), 4);
  EXPECT_GT(max0 - min0, 1.0);  // noise of 2% on 0.1-long edges: curvatures far from 1/R
  EXPECT_LT(max1 - min1, 0.25 * (max0 - min0));
  EXPECT_NEAR((min1 + max1) / 2, 0.5, 0.1);  // 1/R
  EXPECT_TRUE(hasMessage(run.log.infos, "Plugin(Fair): 3 iteration(s); vertices moved by at most"));
  // The enclosed volume is kept: the sphere's radius stays near 2.
  const Mesh& mesh = run.session.mesh();
  for (std::size_t k = 0; k < mesh.nodeCount(); ++k) EXPECT_NEAR(norm(mesh.node(k)), 2, 0.05);
}

TEST_F(MergedTrianglePlugins, FairTakesOneIterationUnlessToldAndChecksItsOptions) {
  writeScan();
  ScriptRun run;
  runMain(run, "Merge \"scan.stl\";\nPlugin(Fair).Run;\n");
  EXPECT_TRUE(hasMessage(run.log.infos, "Plugin(Fair): 1 iteration(s)"));
  ScriptRun bad;
  EXPECT_THROW(runMain(bad, "Merge \"scan.stl\";\nPlugin(Fair).TimeStep = 0;\nPlugin(Fair).Run;\n"),
               ScriptError);
  ScriptRun badIterations;
  EXPECT_THROW(runMain(badIterations,
                       "Merge \"scan.stl\";\nPlugin(Fair).Iterations = 1.5;\nPlugin(Fair).Run;\n"),
               ScriptError);
}

TEST_F(MergedTrianglePlugins, AfterClassifySurfacesTheTrianglesAreNotChanged) {
  writeScan();
  ScriptRun run;
  try {
    runMain(run, R"(
      Merge "scan.stl";
      ClassifySurfaces{40 * Pi / 180, 1, 1, Pi};
      Plugin(Fair).Run;
    )");
    FAIL() << "no error";
  } catch (const ScriptError& e) {
    EXPECT_NE(std::string(e.what()).find("Plugin(Fair) changes the merged triangles before "
                                         "ClassifySurfaces, CreateTopology or CreateGeometry, "
                                         "not after"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(MergedTrianglePlugins, CurvatureOfARemeshedSphereUsesTheMesh) {
  ScriptRun run;
  run.run(R"(
    SetFactory("OpenCASCADE");
    Sphere(1) = {0, 0, 0, 2};
    Mesh.MeshSizeMax = 0.2;
    Mesh 2;
    Plugin(Curvature).Run;
    Plugin(VertexNormals).Run;
  )");
  ASSERT_EQ(run.session.views().size(), 2u);
  const post::View& h = run.session.views().at(0);
  EXPECT_EQ(h.name, "Mean curvature");
  EXPECT_EQ(h.elementCount(), run.session.mesh().elementCount(2));
  double sum = 0;
  std::size_t count = 0;
  for (const post::ElementList& list : h.lists)
    for (double v : list.values) sum += v, ++count;
  EXPECT_NEAR(sum / double(count), 0.5, 0.01);  // 1/R
  EXPECT_GT(h.minimum(), 0.4);
  EXPECT_LT(h.maximum(), 0.65);
  EXPECT_EQ(run.session.views().at(1).name, "Vertex normals");
  EXPECT_NEAR(run.session.views().at(1).minimum(), 1, 1e-9);
}

TEST_F(MergedTrianglePlugins, TheUnrolledScriptRepeatsTheChange) {
  writeScan();
  ScriptRun run;
  runMain(run, R"(
    Merge "scan.stl";
    Plugin(Fair).Iterations = 2;
    Plugin(Fair).Run;
    Plugin(Simplify).TargetTriangles = 400;
    Plugin(Simplify).Run;
  )");
  const std::string path = (dir_ / "main.geo_unrolled").string();
  api::writeUnrolledGeometry(run.session, path);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("Plugin(Fair).Iterations = 2; Plugin(Fair).TimeStep = 0.5; "
                            "Plugin(Fair).Run;\nPlugin(Simplify).TargetTriangles = 400; "
                            "Plugin(Simplify).MaxError = 0; Plugin(Simplify).Run;"),
            std::string::npos)
      << text.str();
}

TEST_F(MergedTrianglePlugins, MergeTellsOfHolesAndNonManifoldEdges) {
  std::vector<Facet> facets = sphereFacets(2, 4, 0);
  facets.erase(facets.begin() + 9);  // a hole: 3 edges on one facet only
  const Facet last = facets.back();   // in another octant
  facets.push_back({last[0], last[1], Vec3{0, 0, 0}});  // a fin: 1 edge on 3 facets
  writeStl(dir_ / "holey.stl", facets);
  ScriptRun run;
  runMain(run, "Merge \"holey.stl\";\n");
  const std::string file = "Merged '" + (dir_ / "holey.stl").string() + "': ";
  // The hole's three edges, and the fin's two free ones.
  EXPECT_TRUE(hasMessage(run.log.infos,
                         file + "5 boundary edges (on one facet only: holes or open borders), "
                                "the first on facet "))
      << ::testing::PrintToString(run.log.infos);
  EXPECT_TRUE(hasMessage(run.log.warnings, file + "1 non-manifold edges (on more than two "
                                                  "facets), the first on facet "))
      << ::testing::PrintToString(run.log.warnings);
  ScriptRun clean;
  writeScan();
  runMain(clean, "Merge \"scan.stl\";\n");
  EXPECT_FALSE(hasMessage(clean.log.infos, "boundary edges"));
  EXPECT_FALSE(hasMessage(clean.log.warnings, "non-manifold"));
  EXPECT_FALSE(hasMessage(clean.log.warnings, "intersect"));
}

TEST_F(MergedTrianglePlugins, MergeTellsOfFacetsThatCrossEachOther) {
  // Two balls of radius 2 whose centres are 1 apart: their skins cross along a circle.
  std::vector<Facet> facets = sphereFacets(2, 6, 0);
  const std::size_t first = facets.size();
  for (std::size_t k = 0; k < first; ++k) {
    Facet moved = facets[k];
    for (Vec3& p : moved) p.x += 1;
    facets.push_back(moved);
  }
  writeStl(dir_ / "two.stl", facets);
  ScriptRun run;
  runMain(run, "Merge \"two.stl\";\n");
  const std::string file = "Merged '" + (dir_ / "two.stl").string() + "': ";
  const auto said =
      std::find_if(run.log.warnings.begin(), run.log.warnings.end(),
                   [](const std::string& w) { return w.find("intersect") != std::string::npos; });
  ASSERT_NE(said, run.log.warnings.end()) << ::testing::PrintToString(run.log.warnings);
  EXPECT_EQ(said->rfind(file, 0), 0u) << *said;
  EXPECT_NE(
      said->find(" pairs of facets intersect (the surface crosses itself), the first facets "),
      std::string::npos)
      << *said;
  // The crossing lies where the two spheres meet: x = 0.5 (on the facets, so near it).
  const std::size_t at = said->rfind(" at (");
  ASSERT_NE(at, std::string::npos);
  EXPECT_NEAR(std::stod(said->substr(at + 5)), 0.5, 0.3) << *said;
}

}  // namespace
}  // namespace geomesh::testing
