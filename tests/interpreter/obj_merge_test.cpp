// Merge of a Wavefront OBJ file: its objects become discrete surfaces, which close a volume as
// they are, or are classified and given a geometry (ClassifySurfaces, CreateGeometry).
#include <gtest/gtest.h>

#include <string>

#include "api/meshing.h"
#include "mesh_measures.h"
#include "script_runner.h"
#include "scratch_dir_test.h"

namespace geomesh::testing {
namespace {

class ObjMerge : public ScratchDirTest {
 protected:
  ObjMerge() : ScratchDirTest("obj-merge-") {}

  // The surface mesh of an OpenCASCADE box, 1 by 2 by 3, saved as box.obj.
  void writeBox() {
    ScriptRun make;
    runMain(make,
            "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 2, 3};\n"
            "Mesh.MeshSizeMax = 0.25;\nMesh 2;\nSave \"box.obj\";\n");
  }
};

TEST_F(ObjMerge, TheObjectsOfAFileCloseAVolume) {
  writeBox();
  ScriptRun session;
  runMain(session, "Merge \"box.obj\";\nSurface Loop(1) = Surface{:};\nVolume(1) = {1};\n");
  EXPECT_EQ(session.session.model().surfaces().size(), 6u);
  api::generate(session.session, 3);
  const Mesh& mesh = session.session.mesh();
  EXPECT_NEAR(measure(mesh, 3), 6, 1e-9);
  EXPECT_NEAR(measure(mesh, 2), 22, 1e-9);
}

TEST_F(ObjMerge, AClassifiedBoxIsRemeshedAndFilled) {
  writeBox();
  ScriptRun session;
  runMain(session,
          "Merge \"box.obj\";\nClassifySurfaces{40 * Pi / 180, 1, 0, Pi};\nCreateGeometry;\n"
          "Surface Loop(1) = Surface{:};\nVolume(1) = {1};\nMesh.MeshSizeMax = 0.3;\n");
  api::generate(session.session, 3);
  const Mesh& mesh = session.session.mesh();
  EXPECT_EQ(session.session.model().surfaces().size(), 6u);
  EXPECT_EQ(session.session.model().curves().size(), 12u);
  EXPECT_NEAR(measure(mesh, 3), 6, 1e-9);
  EXPECT_NEAR(measure(mesh, 2), 22, 1e-9);
  EXPECT_NEAR(measure(mesh, 1), 24, 1e-9);
}

}  // namespace
}  // namespace geomesh::testing
