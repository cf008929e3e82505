// Tests of Model: upward adjacencies forget the boundaries of replaced entities.
#include "kernel/model.h"

#include <gtest/gtest.h>

namespace geomesh {
namespace {

// Replacing an entity must not leave the adjacency of its old boundary behind.
TEST(Model, UpwardForgetsReplacedBoundaries) {
  Model model;
  model.addPoint({1, {0, 0, 0}, 0});
  model.addPoint({2, {1, 0, 0}, 0});
  model.addPoint({3, {0, 1, 0}, 0});
  model.addCurve({1, 1, 2, nullptr});
  EXPECT_EQ(model.upward({0, 2}), (std::vector<int>{1}));
  model.addCurve({1, 1, 3, nullptr});
  EXPECT_TRUE(model.upward({0, 2}).empty());
  EXPECT_EQ(model.upward({0, 3}), (std::vector<int>{1}));
  EXPECT_EQ(model.upward({0, 1}), (std::vector<int>{1}));
}

}  // namespace
}  // namespace geomesh
