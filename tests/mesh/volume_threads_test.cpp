// Tests of meshing several volumes on several threads: the same mesh, byte for byte.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "io/msh_writer.h"
#include "kernel/geo/geo_factory.h"
#include "mesh/pipeline/generate.h"
#include "mesh_measures.h"

namespace geomesh {
namespace {

// Three unit cubes side by side with gaps, three volumes, meshed at size h.
Model threeCubes(double h) {
  GeoFactory geo;
  for (int c = 0; c < 3; ++c) {
    const int p = 100 * c, x0 = 2 * c;
    int tag = p + 1;
    for (int z = 0; z < 2; ++z)
      for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
          geo.addPoint(tag++, {double(x0 + x), double(y), double(z)}, h);
    const int edges[12][2] = {{1, 2}, {2, 4}, {4, 3}, {3, 1}, {5, 6}, {6, 8},
                              {8, 7}, {7, 5}, {1, 5}, {2, 6}, {4, 8}, {3, 7}};
    for (int e = 0; e < 12; ++e) geo.addLine(p + e + 1, p + edges[e][0], p + edges[e][1]);
    const std::vector<std::vector<int>> loops = {{1, 2, 3, 4},    {5, 6, 7, 8},
                                                 {1, 10, -5, -9}, {2, 11, -6, -10},
                                                 {3, 12, -7, -11}, {4, 9, -8, -12}};
    for (int s = 0; s < 6; ++s) {
      std::vector<int> loop;
      for (int e : loops[s]) loop.push_back(e > 0 ? p + e : e - p);
      geo.addCurveLoop(p + s + 1, loop);
      geo.addPlaneSurface(p + s + 1, {p + s + 1});
    }
    geo.addSurfaceLoop(p + 1, {p + 1, p + 2, p + 3, p + 4, p + 5, p + 6});
    geo.addVolume(c + 1, {p + 1});
  }
  Model model;
  geo.synchronize(model);
  return model;
}

std::string meshed(const Model& model, int threads) {
  MeshOptions options;
  options.numThreads = threads;
  Mesh mesh;
  testing::QuietSink log;
  generateMesh(model, options, 3, mesh, log);
  std::ostringstream out;
  writeMsh(out, model, mesh, {});
  return out.str();
}

TEST(VolumeThreads, SameMeshForAnyNumberOfThreads) {
  const Model model = threeCubes(0.2);
  const std::string one = meshed(model, 1);
  EXPECT_NE(one.find("$Elements"), std::string::npos);
  EXPECT_EQ(meshed(model, 2), one);
  EXPECT_EQ(meshed(model, 3), one);
  EXPECT_EQ(meshed(model, 8), one);  // more threads than volumes
}

}  // namespace
}  // namespace geomesh
