// The library layer without the interpreter: meshing a session's model, failures located at
// the statement of their entity, and models left empty by ignored statements.
#include "api/meshing.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "grammar/diagnostic.h"
#include "mesh/core/mesh_error.h"
#include "tests/kernel/kernel_test_helpers.h"
#include "tests/scratch.h"

namespace fs = std::filesystem;

namespace geomesh {
namespace {

// A self-crossing quadrilateral: its curves mesh, its surface cannot.
void addBowTie(GeometryFactory& geo) {
  geo.addPoint(1, {0, 0, 0}, 0.1);
  geo.addPoint(2, {3, 0, 0}, 0.1);
  geo.addPoint(3, {0, 1, 0}, 0.1);
  geo.addPoint(4, {1, 2, 0}, 0.1);
  for (int i = 1; i <= 4; ++i) geo.addLine(i, i, i % 4 + 1);
  geo.addCurveLoop(1, {1, 2, 3, 4});
  geo.addPlaneSurface(1, {1});
}

TEST(ApiGenerate, MeshesUpToTheDimension) {
  SilentSink log;
  Session session(log);
  addUnitSquareSurface(session.factory(), 0.5);
  api::generate(session, 2);
  EXPECT_GT(session.mesh().elementCount(2), 0u);
}

TEST(ApiGenerate, AFailurePointsAtTheStatementOfItsEntity) {
  const fs::path script = scratch::path("api-bow.geo");
  std::ofstream(script) << "// line 1\n// line 2\nPlane Surface(1) = {1};\n";
  SilentSink log;
  Session session(log);
  addBowTie(session.factory());
  session.recordOrigin({2, 1}, {script.string(), 3, 1});
  try {
    api::generate(session, 2);
    FAIL() << "no error";
  } catch (const ScriptError& error) {
    EXPECT_EQ(error.location(), (SourceLocation{script.string(), 3, 1}));
    EXPECT_NE(error.message().find("surface 1"), std::string::npos) << error.message();
    // The diagnostic quotes the statement from its file.
    EXPECT_NE(std::string(error.what()).find("\nPlane Surface(1) = {1};\n^"), std::string::npos)
        << error.what();
  }
  fs::remove(script);
}

TEST(ApiGenerate, AFailureOnAnEntityOfUnknownOriginStaysAMeshError) {
  SilentSink log;
  Session session(log);
  addBowTie(session.factory());
  EXPECT_THROW(api::generate(session, 2), MeshError);
}

TEST(NothingToMesh, IgnoredStatementsAndAnEmptyModelAreAnError) {
  SilentSink log;
  Session session(log);
  session.noteIgnoredStatement({"occ.geo", 1, 1});
  session.noteIgnoredStatement({"occ.geo", 2, 1});
  session.noteIgnoredStatement({"occ.geo", 1, 1});  // the same statement again (a loop)
  try {
    api::requireSomethingToMesh(session, 3);
    FAIL() << "no error";
  } catch (const ScriptError& error) {
    EXPECT_EQ(error.location(), (SourceLocation{"occ.geo", 1, 1}));
    EXPECT_EQ(error.message(),
              "nothing to mesh: 2 statements were ignored as not supported yet (the first "
              "here) and the model has no point, curve, surface or volume");
  }
}

TEST(NothingToMesh, OneIgnoredStatementIsNamedAlone) {
  SilentSink log;
  Session session(log);
  session.noteIgnoredStatement({"occ.geo", 4, 3});
  try {
    api::requireSomethingToMesh(session, 2);
    FAIL() << "no error";
  } catch (const ScriptError& error) {
    EXPECT_EQ(error.message(),
              "nothing to mesh: 1 statement was ignored as not supported yet (this one) and "
              "the model has no point, curve or surface");
    EXPECT_EQ(std::string(error.what()).rfind("occ.geo:4:3: error: nothing to mesh", 0), 0u);
  }
}

TEST(NothingToMesh, AModelWithEntitiesOrNoIgnoredStatementIsFine) {
  SilentSink log;
  Session empty(log);
  EXPECT_NO_THROW(api::requireSomethingToMesh(empty, 3));  // nothing ignored: not our case
  Session withGeometry(log);
  addUnitSquareSurface(withGeometry.factory(), 0.5);
  withGeometry.noteIgnoredStatement({"occ.geo", 1, 1});
  EXPECT_NO_THROW(api::requireSomethingToMesh(withGeometry, 2));
}

}  // namespace
}  // namespace geomesh
