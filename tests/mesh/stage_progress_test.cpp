// The progress each meshing stage reports: rising from 0 to 1 per stage, ending at 1.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/messages.h"
#include "mesh/pipeline/generate.h"
#include "tests/mesh/mesh_test_models.h"

namespace geomesh {
namespace {

class ProgressSink final : public MessageSink {
 public:
  std::map<std::string, std::vector<double>> fractions;
  void info(std::string_view) override {}
  void warning(std::string_view) override {}
  void progress(std::string_view stage, double fraction) override {
    fractions[std::string(stage)].push_back(fraction);
  }
};

TEST(StageProgress, EachStageRisesToOne) {
  const Model model = testing::cubeModel(0.1);
  Mesh mesh;
  ProgressSink log;
  generateMesh(model, MeshOptions{}, 3, mesh, log);
  for (const char* stage : {"Meshing 2D", "Meshing 3D"}) {
    ASSERT_TRUE(log.fractions.contains(stage)) << stage;
    const std::vector<double>& f = log.fractions.at(stage);
    EXPECT_EQ(f.back(), 1.0) << stage;
    for (std::size_t i = 1; i < f.size(); ++i) EXPECT_GE(f[i], f[i - 1]) << stage << " " << i;
    for (double x : f) EXPECT_TRUE(x >= 0 && x <= 1) << stage << " " << x;
  }
  // The 2D stage reports each of the cube's six faces; the volume its phases in between.
  EXPECT_GE(log.fractions.at("Meshing 2D").size(), 6u);
  const std::vector<double>& volume = log.fractions.at("Meshing 3D");
  EXPECT_GE(volume.size(), 4u);
  EXPECT_GT(volume.front(), 0.0);
  EXPECT_LT(volume.front(), 0.5);
}

}  // namespace
}  // namespace geomesh
