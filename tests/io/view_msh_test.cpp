// Tests of the MSH view files: $NodeData, $ElementData and $ElementNodeData read (4.1 and 2.2,
// ASCII and binary) into views over the mesh, located errors, and views written back as MSH.
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/msh_reader.h"
#include "io/msh_writer.h"
#include "io/view_files.h"
#include "tests/io/scratch_files.h"

namespace geomesh {
namespace {

using post::ElementShape;
using post::FieldKind;
using post::MeshData;

const char* kMesh41 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Nodes
1 4 10 40
2 1 0 4
10
20
30
40
0 0 0
1 0 0
1 1 0
0 1 0
$EndNodes
$Elements
1 2 5 6
2 1 2 2
5 10 20 30
6 10 30 40
$EndElements
)";

const char* kMesh22 = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
4
10 0 0 0
20 1 0 0
30 1 1 0
40 0 1 0
$EndNodes
$Elements
2
5 2 2 0 1 10 20 30
6 2 2 0 1 10 30 40
$EndElements
)";

// Two steps of "u" given in reverse order, vector data on one element, element-node data.
const char* kData = R"($NodeData
1
"u"
1
2.0
3
1
1
4
10 1
20 2
30 3
40 4
$EndNodeData
$NodeData
1
"u"
1
1.0
3
0
1
4
10 10
20 20
30 30
40 40
$EndNodeData
$ElementData
1
"e"
0
3
0
3
1
6 7 8 9
$EndElementData
$ElementNodeData
1
"en"
0
3
0
1
2
5 3 1 2 3
6 3 4 5 6
$EndElementNodeData
)";

class ViewMsh : public ScratchFiles {
 protected:
  ViewMsh() : ScratchFiles("view-msh") {}

  // The mesh and views of an MSH file, as a merge reads them.
  void read(const std::string& path) {
    Model model;
    readMshFile(path, model, mesh_);
    views_.clear();
    readMshViews(path, mesh_, views_);
  }
  std::string readError(const std::string& path) {
    try {
      read(path);
    } catch (const ViewReadError& e) {
      return e.what();
    }
    return "no error";
  }

  Mesh mesh_;
  post::ViewStore views_;
};

void expectTheThreeViews(const post::ViewStore& views) {
  ASSERT_EQ(views.size(), 3u);
  const post::View& u = views.at(0);
  EXPECT_EQ(u.name, "u");
  EXPECT_EQ(u.times, (std::vector<double>{1, 2}));  // in time-step order
  ASSERT_EQ(u.lists.size(), 1u);
  const post::ElementList& st = u.lists[0];
  EXPECT_EQ(st.shape, ElementShape::Triangle);
  EXPECT_EQ(st.steps, 2);
  EXPECT_EQ(st.coordinates,
            (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0}));
  EXPECT_EQ(st.values, (std::vector<double>{10, 20, 30, 1, 2, 3, 10, 30, 40, 1, 3, 4}));
  ASSERT_TRUE(u.meshData);
  EXPECT_EQ(u.meshData->kind, MeshData::Kind::Node);
  ASSERT_EQ(u.meshData->steps.size(), 2u);
  EXPECT_EQ(u.meshData->steps[0].index, 0);
  EXPECT_EQ(u.meshData->steps[0].tags, (std::vector<std::size_t>{1, 2, 3, 4}));
  EXPECT_EQ(u.meshData->steps[0].values, (std::vector<double>{10, 20, 30, 40}));

  const post::View& e = views.at(1);
  ASSERT_EQ(e.lists.size(), 1u);  // only the element that has data
  EXPECT_EQ(e.lists[0].kind, FieldKind::Vector);
  EXPECT_EQ(e.lists[0].coordinates, (std::vector<double>{0, 0, 0, 1, 1, 0, 0, 1, 0}));
  EXPECT_EQ(e.lists[0].values, (std::vector<double>{7, 8, 9, 7, 8, 9, 7, 8, 9}));
  EXPECT_EQ(e.meshData->kind, MeshData::Kind::Element);
  EXPECT_EQ(e.meshData->components, 3);
  EXPECT_EQ(e.meshData->steps[0].tags, std::vector<std::size_t>{2});

  const post::View& en = views.at(2);
  ASSERT_EQ(en.lists.size(), 1u);
  EXPECT_EQ(en.lists[0].values, (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(en.meshData->steps[0].counts, (std::vector<int>{3, 3}));
}

TEST_F(ViewMsh, AsciiDataSectionsBecomeViews) {
  read(file("a41.msh", std::string(kMesh41) + kData));
  expectTheThreeViews(views_);
  read(file("a22.msh", std::string(kMesh22) + kData));
  expectTheThreeViews(views_);
}

template <class T>
void append(std::string& bytes, T v) {
  char raw[sizeof(T)];
  std::memcpy(raw, &v, sizeof(T));
  bytes.append(raw, sizeof(T));
}

// The mesh written as binary MSH (tags 1..4 and 1..2), then "u"'s first step in binary.
std::string binaryFile(const Mesh& mesh, double version, int badTag = 0) {
  std::ostringstream out;
  MshWriteOptions options;
  options.binary = true;
  options.version = version;
  options.saveAll = true;
  writeMsh(out, Model{}, mesh, options);
  std::string s = out.str() + "$NodeData\n1\n\"u\"\n1\n1.0\n3\n0\n1\n4\n";
  for (int tag = 1; tag <= 4; ++tag) {
    append<std::int32_t>(s, tag == 4 && badTag ? badTag : tag);
    append<double>(s, 10.0 * tag);
  }
  return s + "\n$EndNodeData\n";
}

TEST_F(ViewMsh, BinaryDataSectionsBecomeViews) {
  read(file("a41.msh", std::string(kMesh41) + kData));
  const Mesh ascii = mesh_;
  for (double version : {4.1, 2.2}) {
    read(file("b.msh", binaryFile(ascii, version)));
    ASSERT_EQ(views_.size(), 1u);
    EXPECT_EQ(views_.at(0).lists[0].values, (std::vector<double>{10, 20, 30, 10, 30, 40}));
    const std::string bad = binaryFile(ascii, version, 9);
    const std::string path = file("bad.msh", bad);
    const std::size_t at = bad.size() - std::string("\n$EndNodeData\n").size() - 12;
    EXPECT_EQ(readError(path),
              path + ": byte " + std::to_string(at) + ": node 9 is not in the mesh");
  }
}

// Complete second-order elements give order-2 lists with all their nodes, other high-order
// ones their corners; 2 components are padded to vectors, 6 made symmetric tensors.
TEST_F(ViewMsh, HighOrderElementsAndComponentCounts) {
  const std::string text = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$Nodes
6
1 0 0 0
2 2 0 0
3 0 2 0
4 1 0 0
5 1 1 0
6 0 1 0
$EndNodes
$Elements
1
1 9 2 0 1 1 2 3 4 5 6
$EndElements
$NodeData
1
"v"
0
3
0
2
6
1 1 2
2 3 4
3 5 6
4 7 8
5 9 10
6 11 12
$EndNodeData
$ElementData
1
"t"
0
3
0
6
1
1 1 2 3 4 5 6
$EndElementData
)";
  read(file("t6.msh", text));
  ASSERT_EQ(views_.size(), 2u);
  const post::ElementList& v = views_.at(0).lists.at(0);
  EXPECT_EQ(v.order, 2);
  EXPECT_EQ(v.kind, FieldKind::Vector);
  EXPECT_EQ(v.nodesPerElement, 6);
  EXPECT_EQ(v.coordinates[3 * 4], 1);  // node 5 at (1, 1)
  EXPECT_EQ(v.values,
            (std::vector<double>{1, 2, 0, 3, 4, 0, 5, 6, 0, 7, 8, 0, 9, 10, 0, 11, 12, 0}));
  EXPECT_EQ(views_.at(0).meshData->components, 2);  // kept as the file gave it
  const post::ElementList& t = views_.at(1).lists.at(0);
  EXPECT_EQ(t.kind, FieldKind::Tensor);
  EXPECT_EQ(std::vector<double>(t.values.begin(), t.values.begin() + 9),
            (std::vector<double>{1, 2, 3, 2, 4, 5, 3, 5, 6}));
  EXPECT_EQ(t.values.size(), 6u * 9u);
}

// A file of data alone (merged onto a mesh read before) names the mesh's own tags.
TEST_F(ViewMsh, DataWithoutMeshUsesTheMeshTags) {
  read(file("m.msh", kMesh41));
  std::string data =
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
      "$NodeData\n1\n\"d\"\n0\n3\n0\n1\n4\n1 5\n2 6\n3 7\n4 8\n$EndNodeData\n"
      "$ElementData\n1\n\"e\"\n0\n3\n0\n1\n1\n2 9\n$EndElementData\n";
  views_.clear();
  ASSERT_EQ(readMshViews(file("d.msh", data), mesh_, views_), 2);
  EXPECT_EQ(views_.at(0).lists[0].values, (std::vector<double>{5, 6, 7, 5, 7, 8}));
  EXPECT_EQ(views_.at(1).lists[0].values, (std::vector<double>{9, 9, 9}));
  data.replace(data.find("4 8"), 1, "5");
  const std::string bad = file("bad.msh", data);
  views_.clear();
  try {
    readMshViews(bad, mesh_, views_);
    ADD_FAILURE() << "no error";
  } catch (const ViewReadError& e) {
    EXPECT_EQ(std::string(e.what()), bad + ":15:1: node 5 is not in the mesh");
  }
}

// Every cut of a file, and every byte of it changed, reads or fails with ViewReadError.
TEST_F(ViewMsh, DamagedFilesFailCleanly) {
  read(file("a41.msh", std::string(kMesh41) + kData));
  const Mesh mesh = mesh_;
  for (const std::string& whole : {std::string(kMesh41) + kData, std::string(kMesh22) + kData,
                                   binaryFile(mesh, 4.1), binaryFile(mesh, 2.2)}) {
    for (std::size_t cut = 0; cut < whole.size(); cut += 5) {  // a sample keeps it quick
      std::string changed = whole;
      changed[cut] = static_cast<char>(changed[cut] ^ 0x5a);
      for (const std::string& damaged : {whole.substr(0, cut), changed}) {
        post::ViewStore views;
        try {
          readMshViews(file("d.msh", damaged), mesh, views);
        } catch (const ViewReadError&) {
        }
      }
    }
  }
}

TEST_F(ViewMsh, DataOnMissingNodesOrElementsIsLocated) {
  std::string data = kData;
  data.replace(data.find("30 30"), 2, "77");
  const std::string path = file("n.msh", std::string(kMesh41) + data);
  EXPECT_EQ(readError(path), path + ":47:1: node 77 is not in the mesh");
  data = kData;
  data.replace(data.find("6 7 8 9"), 1, "8");
  const std::string element = file("e.msh", std::string(kMesh22) + data);
  EXPECT_EQ(readError(element), element + ":52:1: element 8 is not in the mesh");
  data = kData;
  data.replace(data.find("6 3 4"), 3, "6 2");
  const std::string count = file("c.msh", std::string(kMesh41) + data);
  EXPECT_EQ(readError(count), count + ":69:3: element 2 has 3 nodes, not 2");
  // The mesh must be the file's: a node elsewhere is reported where the file places it.
  std::string moved = std::string(kMesh41) + kData;
  moved.replace(moved.find("1 1 0"), 5, "1 2 0");
  const std::string other = file("o.msh", moved);
  post::ViewStore views;
  try {
    readMshViews(other, mesh_, views);
    ADD_FAILURE() << "no error";
  } catch (const ViewReadError& e) {
    EXPECT_EQ(std::string(e.what()),
              other +
                  ":13:1: node 3 of the file is not where the mesh has it (a mesh of another "
                  "file?)");
  }
}

TEST_F(ViewMsh, MeshViewsAreWrittenBackAsMsh) {
  for (double version : {4.1, 2.2}) {
    read(file("a.msh", std::string(kMesh22) + kData));
    const post::ViewStore original = std::move(views_);
    const Mesh mesh = mesh_;
    for (std::size_t i = 0; i < 3; ++i) {
      const std::string out = (dir_ / "out.msh").string();
      writeView(original.at(i), out, mesh, version);
      read(out);
      ASSERT_EQ(views_.size(), 1u);
      const post::View& back = views_.at(0);
      EXPECT_EQ(back.name, original.at(i).name);
      EXPECT_EQ(back.times, original.at(i).times);
      ASSERT_EQ(back.lists.size(), original.at(i).lists.size());
      EXPECT_EQ(back.lists[0].coordinates, original.at(i).lists[0].coordinates);
      EXPECT_EQ(back.lists[0].values, original.at(i).lists[0].values);
      EXPECT_EQ(back.meshData->steps.back().values, original.at(i).meshData->steps.back().values);
    }
  }
}

TEST_F(ViewMsh, AppendedViewsFollowTheMeshAlreadyWritten) {
  for (double version : {4.1, 2.2}) {
    read(file("a.msh", std::string(kMesh41) + kData));
    const post::ViewStore original = std::move(views_);
    const Mesh mesh = mesh_;
    const std::string out = (dir_ / "all.msh").string();
    for (std::size_t i = 0; i < 3; ++i) writeView(original.at(i), out, mesh, version, i > 0);
    read(out);
    expectTheThreeViews(views_);
  }
}

// The writers number nodes entity by entity, not in the mesh's order: data follows its node.
TEST_F(ViewMsh, NodeDataFollowsNodesRenumberedByTheWriter) {
  Mesh mesh;
  for (Vec3 p : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1, 0}}) mesh.addNode(p);
  mesh.entity({0, 1}).nodes = {3};
  mesh.entity({0, 1}).block(ElementType::Point1).nodes = {3};
  mesh.entity({2, 1}).nodes = {0, 1, 2};
  mesh.entity({2, 1}).block(ElementType::Triangle3).nodes = {0, 1, 2, 0, 2, 3};
  post::View view;
  view.name = "n";
  view.meshData = MeshData{MeshData::Kind::Node, 1, {{0.25, 0, {1, 2, 3, 4}, {}, {5, 6, 7, 8}}}};
  for (double version : {4.1, 2.2}) {
    const std::string out = (dir_ / "n.msh").string();
    writeView(view, out, mesh, version);
    read(out);
    ASSERT_EQ(views_.size(), 1u);
    const post::View& back = views_.at(0);
    EXPECT_EQ(back.times, std::vector<double>{0.25});
    for (const post::ElementList& l : back.lists)
      for (std::size_t k = 0; k < l.values.size(); ++k) {
        const double x = l.coordinates[3 * k], y = l.coordinates[3 * k + 1];
        const double expected = x == 0 ? (y == 0 ? 5 : 8) : (y == 0 ? 6 : 7);
        EXPECT_EQ(l.values[k], expected) << "at " << x << ", " << y;
      }
    ASSERT_EQ(back.lists.size(), 2u);  // the point and the triangles
  }
}

TEST_F(ViewMsh, ListViewsAreWrittenAsTheirOwnMesh) {
  post::View view;
  view.name = "lists";
  view.times = {0.5, 1.5};
  view.list(ElementShape::Triangle, FieldKind::Scalar);
  view.list(ElementShape::Quadrangle, FieldKind::Scalar);
  post::ElementList& st = view.lists[0];
  post::ElementList& sq = view.lists[1];
  st.steps = 2;
  st.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  st.values = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 0.1};
  sq.steps = 2;
  sq.coordinates = {1, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0};
  sq.values = {1, 2, 3, 4, 5, 6, 7, 1.0 / 3};
  for (double version : {4.1, 2.2}) {
    const std::string out = (dir_ / "lists.msh").string();
    writeView(view, out, Mesh{}, version);
    read(out);
    EXPECT_EQ(mesh_.nodeCount(), 6u);  // shared corners written once
    ASSERT_EQ(views_.size(), 1u);
    const post::View& back = views_.at(0);
    EXPECT_EQ(back.times, view.times);
    ASSERT_EQ(back.lists.size(), 2u);
    EXPECT_EQ(back.lists[0].coordinates, st.coordinates);
    EXPECT_EQ(back.lists[0].values, st.values);
    EXPECT_EQ(back.lists[1].coordinates, sq.coordinates);
    EXPECT_EQ(back.lists[1].values, sq.values);
  }
  view.list(ElementShape::Point, FieldKind::Vector).coordinates = {0, 0, 0};
  view.lists.back().values = {1, 2, 3, 4, 5, 6};
  view.lists.back().steps = 2;
  EXPECT_THROW(writeView(view, (dir_ / "mixed.msh").string(), Mesh{}), std::runtime_error);
}

}  // namespace
}  // namespace geomesh
