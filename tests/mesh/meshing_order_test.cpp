// Tests of meshingOrder: images after their sources, closed extrusion chains cut, cycles refused.
#include "mesh/structured/meshing_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "mesh/core/mesh_error.h"
#include "mesh_test_models.h"

namespace geomesh {
namespace {

using testing::SegmentGeometry;

// Curves 1..n between points on the x axis, each from point k to point k + 1.
Model chainOfLines(int n) {
  Model model;
  for (int k = 1; k <= n + 1; ++k) model.addPoint({k, {double(k), 0, 0}, 0.1});
  for (int k = 1; k <= n; ++k)
    model.addCurve({k, k, k + 1,
                    std::make_shared<SegmentGeometry>(model.point(k)->xyz,
                                                      model.point(k + 1)->xyz)});
  return model;
}

std::size_t positionOf(const std::vector<PlannedEntity>& order, int tag) {
  const auto it = std::find_if(order.begin(), order.end(),
                               [&](const PlannedEntity& p) { return p.tag == tag; });
  return static_cast<std::size_t>(it - order.begin());
}

TEST(MeshingOrder, PeriodicSlavesComeAfterTheirMastersWhateverTheTags) {
  const Model model = chainOfLines(3);
  const std::map<int, Periodicity> links{{1, {2, {}}}, {2, {3, {}}}};
  const std::vector<PlannedEntity> order = meshingOrder(model, 1, links);
  ASSERT_EQ(order.size(), 3u);
  EXPECT_EQ(order[positionOf(order, 3)].method, MeshingMethod::Own);
  EXPECT_EQ(order[positionOf(order, 1)].method, MeshingMethod::PeriodicImage);
  EXPECT_EQ(order[positionOf(order, 1)].source, 2);
  EXPECT_LT(positionOf(order, 3), positionOf(order, 2));
  EXPECT_LT(positionOf(order, 2), positionOf(order, 1));
}

TEST(MeshingOrder, CircularPeriodicityIsALocatedError) {
  const Model model = chainOfLines(2);
  const std::map<int, Periodicity> links{{1, {2, {}}}, {2, {1, {}}}};
  try {
    meshingOrder(model, 1, links);
    FAIL() << "no error";
  } catch (const MeshError& e) {
    EXPECT_EQ(e.entity.dim, 1);
    EXPECT_NE(std::string(e.what()).find("circular"), std::string::npos) << e.what();
  }
}

TEST(MeshingOrder, EntitiesWithoutCopiesKeepTheirTagOrder) {
  const Model model = chainOfLines(4);
  const std::vector<PlannedEntity> order = meshingOrder(model, 1, {});
  ASSERT_EQ(order.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(order[k].tag, k + 1);
    EXPECT_EQ(order[k].method, MeshingMethod::Own);
  }
}

}  // namespace
}  // namespace geomesh
