// What the size field tests share: a sink that keeps warnings, and the node count of a 2D mesh.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

#include "kernel/messages.h"
#include "mesh/checks/mesh_check.h"
#include "mesh/pipeline/generate.h"

namespace geomesh::testing {

class RecordingSink final : public MessageSink {
 public:
  std::vector<std::string> warnings;
  void info(std::string_view) override {}
  void warning(std::string_view m) override { warnings.emplace_back(m); }
};

// Meshes the model in 2D, expects a valid mesh and returns its node count.
inline std::size_t nodeCount(Model model, MeshOptions options = {}) {
  Mesh mesh;
  RecordingSink log;
  generateMesh(model, options, 2, mesh, log);
  const MeshCheckReport report = checkMesh(model, mesh);
  EXPECT_TRUE(report.ok()) << report.summary();
  return mesh.nodeCount();
}

}  // namespace geomesh::testing
