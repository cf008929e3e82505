// The format table: lookups by name, extension and code, the lists messages show, and writing
// and reading through a row.
#include "io/formats.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/atomic_file.h"
#include "kernel/geo/geo_factory.h"
#include "tests/scratch.h"

namespace fs = std::filesystem;

namespace geomesh {
namespace {

// The triangle (0,0)-(1,0)-(0,1) as one element on surface 1, its three nodes on points 1..3.
void buildTriangle(Model& model, Mesh& mesh) {
  GeoFactory geo;
  geo.addPoint(1, {0, 0, 0}, 1);
  geo.addPoint(2, {1, 0, 0}, 1);
  geo.addPoint(3, {0, 1, 0}, 1);
  for (int i = 1; i <= 3; ++i) geo.addLine(i, i, i % 3 + 1);
  geo.addCurveLoop(1, {1, 2, 3});
  geo.addPlaneSurface(1, {1});
  geo.synchronize(model);
  for (int p = 1; p <= 3; ++p) {
    const NodeIndex n = mesh.addNode(model.point(p)->xyz);
    mesh.entity({0, p}).nodes.push_back(n);
    mesh.entity({0, p}).block(ElementType::Point1).nodes.push_back(n);
  }
  mesh.entity({2, 1}).block(ElementType::Triangle3).nodes = {0, 1, 2};
}

TEST(Formats, EveryMshNameFindsItsVersion) {
  for (const char* name : {"msh41", "msh4", "msh"}) {
    ASSERT_NE(findFormatByName(name), nullptr) << name;
    EXPECT_EQ(findFormatByName(name)->name(), "msh41") << name;
  }
  for (const char* name : {"msh22", "msh2"}) {
    ASSERT_NE(findFormatByName(name), nullptr) << name;
    EXPECT_EQ(findFormatByName(name)->name(), "msh22") << name;
  }
  EXPECT_EQ(findFormatByName("wrl"), nullptr);
  EXPECT_EQ(findFormatByName(""), nullptr);
}

TEST(Formats, TheMshVersionChoosesAmongRowsSharingAnExtensionOrACode) {
  EXPECT_EQ(findFormatByExtension(".msh", 4.1)->name(), "msh41");
  EXPECT_EQ(findFormatByExtension(".msh", 4.0)->name(), "msh41");
  EXPECT_EQ(findFormatByExtension(".msh", 2.2)->name(), "msh22");
  EXPECT_EQ(findFormatByExtension(".msh", 3)->name(), "msh22");
  EXPECT_EQ(findFormatByCode(1, 4.1)->name(), "msh41");
  EXPECT_EQ(findFormatByCode(1, 2.2)->name(), "msh22");
  EXPECT_EQ(findFormatByExtension(".wrl", 4.1), nullptr);
  EXPECT_EQ(findFormatByExtension("", 4.1), nullptr);
  EXPECT_EQ(findFormatByCode(19, 4.1), nullptr);
  EXPECT_EQ(findFormatByCode(0, 4.1), nullptr);  // rows without a code
  EXPECT_EQ(findReaderByExtension(".msh")->name(), "msh41");
  EXPECT_EQ(findReaderByExtension(".wrl"), nullptr);
}

TEST(Formats, ListsComeFromTheTable) {
  EXPECT_EQ(formatNameList().rfind("msh41, msh4, msh, msh22, msh2", 0), 0u) << formatNameList();
  EXPECT_EQ(formatNameGroups().rfind("msh41 (msh4, msh), msh22 (msh2)", 0), 0u)
      << formatNameGroups();
  EXPECT_EQ(writtenExtensionList().rfind(".msh", 0), 0u);
  EXPECT_EQ(writtenExtensionList().find(".msh", 1), std::string::npos) << "listed once";
  EXPECT_EQ(readExtensionList().rfind(".msh", 0), 0u);
  EXPECT_EQ(formatCodeList().rfind("1 (msh)", 0), 0u) << formatCodeList();
  // Every row that is written has a name, an extension and a code (0 when the Gmsh manual
  // gives the format none; such rows are not in formatCodeList()).
  for (const MeshFormat& format : meshFormats()) {
    EXPECT_FALSE(format.name().empty());
    EXPECT_EQ(format.extensions.substr(0, 1), ".");
    EXPECT_GE(format.code, 0);
    if (format.code == 0) {
      EXPECT_EQ(formatCodeList().find("(" + std::string(format.name()) + ")"), std::string::npos);
    }
    EXPECT_TRUE(format.writes() || format.read);
  }
}

TEST(Formats, AWrittenMshFileReadsBackThroughTheTable) {
  Model model;
  Mesh mesh;
  buildTriangle(model, mesh);
  const fs::path path = scratch::path("formats-roundtrip.msh");
  for (const char* name : {"msh41", "msh22"}) {
    writeMeshFile(path.string(), *findFormatByName(name), model, mesh, {true, false});
    Model readModel;
    Mesh readMesh;
    readMeshFile(path.string(), *findReaderByExtension(".msh"), readModel, readMesh);
    EXPECT_EQ(readMesh.nodeCount(), 3u) << name;
    EXPECT_EQ(readMesh.elementCount(2), 1u) << name;
  }
  fs::remove(path);
}

TEST(Formats, ReadingAMissingFileNamesIt) {
  Model model;
  Mesh mesh;
  try {
    readMeshFile("/no/such/file.msh", *findReaderByExtension(".msh"), model, mesh);
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("/no/such/file.msh"), std::string::npos);
  }
}

TEST(AtomicFile, WritesTheWholeFileAndNoPartialOne) {
  const fs::path path = scratch::path("atomic-ok.txt");
  writeFileAtomically(path.string(), [](std::ostream& out) { out << "complete\n"; });
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "complete");
  EXPECT_FALSE(fs::exists(path.string() + ".partial"));
  fs::remove(path);
}

TEST(AtomicFile, AFailingWriterLeavesTheOldFileAndNoPartialOne) {
  const fs::path path = scratch::path("atomic-fail.txt");
  std::ofstream(path) << "old\n";
  try {
    writeFileAtomically(path.string(), [](std::ostream& out) {
      out << "half";
      throw std::invalid_argument("inconsistent mesh");
    });
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()),
              "cannot write '" + path.string() + "': inconsistent mesh");
  }
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "old");
  EXPECT_FALSE(fs::exists(path.string() + ".partial"));
  fs::remove(path);
}

TEST(AtomicFile, AMissingDirectoryIsAnErrorNamingTheFile) {
  const fs::path path = scratch::path("atomic-no-dir") / "sub" / "f.txt";
  try {
    writeFileAtomically(path.string(), [](std::ostream& out) { out << "x"; });
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()).rfind("cannot write '" + path.string() + "': ", 0), 0u)
        << error.what();
  }
  EXPECT_FALSE(fs::exists(path.parent_path()));
}

}  // namespace
}  // namespace geomesh
