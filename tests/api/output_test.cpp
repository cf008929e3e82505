// The library layer's output: which format a file is written in, atomic writes of the mesh,
// the unrolled geometry and the options, the options writers are given, and option setters.
#include "api/output.h"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "api/meshing.h"
#include "api/options.h"
#include "tests/scratch.h"

namespace fs = std::filesystem;

namespace geomesh {
namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string refusal(const OptionRegistry& options, const std::string& path,
                    const std::string& name = "") {
  try {
    api::outputFormat(options, path, name);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST(OutputFormat, ANameWinsOverTheExtension) {
  OptionRegistry options;
  EXPECT_EQ(api::outputFormat(options, "a.whatever", "msh22").name(), "msh22");
  EXPECT_EQ(api::outputFormat(options, "a.msh", "msh").name(), "msh41");
  EXPECT_EQ(refusal(options, "a.msh", "nope")
                .rfind("unsupported output format 'nope' (supported: " + formatNameList() + ")", 0),
            0u);
}

TEST(OutputFormat, MeshFormatTenChoosesByExtensionAndVersion) {
  OptionRegistry options;
  EXPECT_EQ(api::outputFormat(options, "a.msh").name(), "msh41");
  options.setNumber("Mesh.MshFileVersion", 2.2);
  EXPECT_EQ(api::outputFormat(options, "a.msh").name(), "msh22");
  EXPECT_EQ(refusal(options, "dir/a.xyz"),
            "cannot write 'dir/a.xyz': the '.xyz' format is not supported yet (only " +
                writtenExtensionList() + ")");
}

TEST(OutputFormat, OtherMeshFormatCodesFindTheirRow) {
  OptionRegistry options;
  options.setNumber("Mesh.Format", 1);
  EXPECT_EQ(api::outputFormat(options, "a.anything").name(), "msh41");
  options.setNumber("Mesh.Format", 16);
  EXPECT_EQ(api::outputFormat(options, "a.msh").name(), "vtk");
  options.setNumber("Mesh.Format", 47);
  const std::string message = refusal(options, "a.msh");
  EXPECT_EQ(message.rfind("Mesh.Format 47 is not supported yet (supported: 1 (msh)", 0), 0u)
      << message;
}

TEST(WriteMesh, WritesInTheChosenFormatAndFollowsSaveAll) {
  SilentSink log;
  Session session(log);
  GeometryFactory& geo = session.factory();
  geo.addPoint(1, {0, 0, 0}, 0.5);
  geo.addPoint(2, {1, 0, 0}, 0.5);
  geo.addLine(1, 1, 2);
  geo.addPhysicalGroup(0, 1, "", {1});
  api::generate(session, 1);
  const fs::path path = scratch::path("api-write.msh");
  api::writeMesh(session, path.string(), *findFormatByName("msh22"));
  const std::string onlyPhysical = slurp(path);
  EXPECT_EQ(onlyPhysical.rfind("$MeshFormat\n2.2 0 8\n", 0), 0u) << onlyPhysical;
  session.options().setNumber("Mesh.SaveAll", 1);
  api::writeMesh(session, path.string(), *findFormatByName("msh22"));
  EXPECT_GT(slurp(path).size(), onlyPhysical.size());
  EXPECT_FALSE(fs::exists(path.string() + ".partial"));
  fs::remove(path);
}

class WarningSink final : public MessageSink {
 public:
  void info(std::string_view) override {}
  void warning(std::string_view m) override { warnings.emplace_back(m); }
  std::vector<std::string> warnings;
};

TEST(WriteMesh, WarnsAboutMeshedEntitiesLeftOutOfPhysicalGroups) {
  WarningSink log;
  Session session(log);
  GeometryFactory& geo = session.factory();
  geo.addPoint(1, {0, 0, 0}, 0.5);
  geo.addPoint(2, {1, 0, 0}, 0.5);
  geo.addPoint(3, {2, 0, 0}, 0.5);
  geo.addLine(1, 1, 2);
  geo.addLine(2, 2, 3);
  geo.addPhysicalGroup(1, 1, "", {1});  // curve 2 is in no group
  api::generate(session, 1);
  const fs::path path = scratch::path("api-left-out.msh");
  api::writeMesh(session, path.string(), *findFormatByName("msh41"));
  ASSERT_EQ(log.warnings.size(), 1u);
  EXPECT_NE(log.warnings[0].find("curve 2 (2 elements)"), std::string::npos) << log.warnings[0];
  EXPECT_NE(log.warnings[0].find("-save_all"), std::string::npos);
  EXPECT_EQ(log.warnings[0].find("point"), std::string::npos) << "points have no group at all";
  session.options().setNumber("Mesh.SaveAll", 1);
  api::writeMesh(session, path.string(), *findFormatByName("msh41"));
  EXPECT_EQ(log.warnings.size(), 1u) << "nothing is left out with SaveAll";
  fs::remove(path);
}

TEST(WriteMesh, AFailureLeavesNoFile) {
  SilentSink log;
  Session session(log);
  const fs::path path = scratch::path("api-no-dir") / "m.msh";
  EXPECT_THROW(api::writeMesh(session, path.string(), *findFormatByName("msh41")),
               std::runtime_error);
  EXPECT_FALSE(fs::exists(path.parent_path()));
}

TEST(WriteUnrolledGeometry, WritesTheFlatScript) {
  SilentSink log;
  Session session(log);
  session.factory().addPoint(1, {0, 0, 0}, 0.5);
  session.factory().addPoint(2, {1, 0, 0}, 0.5);
  session.factory().addLine(1, 1, 2);
  const fs::path path = scratch::path("api.geo_unrolled");
  api::writeUnrolledGeometry(session, path.string());
  EXPECT_NE(slurp(path).find("Line(1) = {1, 2};"), std::string::npos) << slurp(path);
  fs::remove(path);
}

TEST(WriteChangedOptions, ListsOnlyWhatDiffersFromTheDefaults) {
  SilentSink log;
  Session session(log);
  session.options().setNumber("Mesh.MeshSizeMax", 0.5);
  const fs::path path = scratch::path("api.opt");
  api::writeChangedOptions(session, path.string());
  EXPECT_EQ(slurp(path).find("Mesh.MeshSizeMax = 0.5;"), 0u) << slurp(path);
  EXPECT_EQ(slurp(path).find("Mesh.Algorithm"), std::string::npos);
  fs::remove(path);
}

TEST(SetNumber, SetsTheOptionElseAParameter) {
  SilentSink log;
  Session session(log);
  api::setNumber(session, "Mesh.Algorithm", 5);
  api::setNumber(session, "n", 7);
  api::setString(session, "General.DefaultFileName", "plate.geo");
  api::setString(session, "label", "top");
  EXPECT_EQ(session.options().number("Mesh.Algorithm"), 5);
  EXPECT_EQ(session.numberOverrides().at("n"), 7);
  EXPECT_EQ(session.numberOverrides().count("Mesh.Algorithm"), 0u);
  EXPECT_EQ(session.options().string("General.DefaultFileName"), "plate.geo");
  EXPECT_EQ(session.stringOverrides().at("label"), "top");
}

TEST(WriteOptions, PicturesTakeTheirSizeAndViewFromPrintAndGeneralOptions) {
  OptionRegistry options;
  MeshWriteOptions w = api::writeOptions(options);
  EXPECT_EQ(w.pictureWidth, 800);  // General.GraphicsWidth and Height, as Print.* are -1
  EXPECT_EQ(w.pictureHeight, 600);
  EXPECT_FALSE(w.viewRotation);
  options.setNumber("General.GraphicsWidth", 320);
  options.setNumber("Print.Height", 100);
  options.setNumber("General.RotationZ", 90);
  w = api::writeOptions(options);
  EXPECT_EQ(w.pictureWidth, 320);
  EXPECT_EQ(w.pictureHeight, 100);
  ASSERT_TRUE(w.viewRotation);
  EXPECT_EQ(*w.viewRotation, (std::array<double, 3>{0, 0, 90}));
}

}  // namespace
}  // namespace geomesh
