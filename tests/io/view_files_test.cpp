// Tests of the .pos view files: the parsed format written, the list-based format read (ASCII
// and binary, both byte orders) and its malformed files reported where they fail.
#include "io/view_files.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/io/scratch_files.h"

namespace geomesh {
namespace {

using post::ElementShape;
using post::FieldKind;

class ViewFiles : public ScratchFiles {
 protected:
  ViewFiles() : ScratchFiles("view-files") {}

  static std::string contentOf(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  std::string readError(const std::string& path) {
    post::ViewStore views;
    try {
      readListBasedPos(path, views);
    } catch (const ViewReadError& e) {
      EXPECT_EQ(views.size(), 0u);  // nothing half-read is kept
      return e.what();
    }
    return "no error";
  }

};

post::View smallView() {
  post::View view;
  view.name = "a \"quoted\" name";
  view.times = {0, 0.1};
  post::ElementList& st = view.list(ElementShape::Triangle, FieldKind::Scalar);
  st.steps = 2;
  st.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  st.values = {1, 2, 3, 1.0 / 3, -4.5e-300, 1e21};
  post::ElementList& vp = view.list(ElementShape::Point, FieldKind::Vector);
  vp.steps = 2;
  vp.coordinates = {0.5, 0.25, -1};
  vp.values = {1, 2, 3, 4, 5, 6};
  post::ElementList& sq2 = view.list(ElementShape::Line, FieldKind::Tensor, 2);
  sq2.nodesPerElement = 3;
  sq2.steps = 1;
  sq2.coordinates = {0, 0, 0, 2, 0, 0, 1, 0, 0};
  for (int i = 0; i < 27; ++i) sq2.values.push_back(i);
  view.texts.push_back({2, 10, 20, 0, 15, {"hello", "say \"hi\" \\ ok"}});
  view.texts.push_back({3, 1, 2, 3, 0, {"3d"}});
  return view;
}

TEST_F(ViewFiles, ParsedPosIsWrittenWithEveryListStepAndText) {
  const std::string path = (dir_ / "v.pos").string();
  writeView(smallView(), path, Mesh{});
  EXPECT_EQ(contentOf(path),
            "View \"a \\\"quoted\\\" name\" {\n"
            "TIME{0,0.1};\n"
            "ST(0,0,0,1,0,0,0,1,0){1,2,3,0.3333333333333333,-4.5e-300,1e+21};\n"
            "VP(0.5,0.25,-1){1,2,3,4,5,6};\n"
            "TL2(0,0,0,2,0,0,1,0,0){0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17,18,19,20,21,22,"
            "23,24,25,26};\n"
            "T2(10,20,15){\"hello\",\"say \\\"hi\\\" \\ ok\"};\n"
            "T3(1,2,3,0){\"3d\"};\n"
            "};\n");
}

TEST_F(ViewFiles, ParsedPosAppendsToAnExistingFile) {
  const std::string path = (dir_ / "two.pos").string();
  post::View a;
  a.name = "a";
  post::ElementList& sp = a.list(ElementShape::Point, FieldKind::Scalar);
  sp.coordinates = {1, 2, 3};
  sp.values = {7};
  writeView(a, path, Mesh{});
  a.name = "b";
  writeView(a, path, Mesh{}, 4.1, true);
  EXPECT_EQ(contentOf(path), "View \"a\" {\nSP(1,2,3){7};\n};\nView \"b\" {\nSP(1,2,3){7};\n};\n");
  writeView(a, path, Mesh{});  // without append, replaced
  EXPECT_EQ(contentOf(path), "View \"b\" {\nSP(1,2,3){7};\n};\n");
}

TEST_F(ViewFiles, UnknownExtensionIsRefused) {
  EXPECT_THROW(writeView(smallView(), (dir_ / "v.xyz").string(), Mesh{}), std::runtime_error);
}

// Version 1.4: 24 first-order counts, 21 second-order ones, then the text counts.
const char* kListAscii = R"($PostFormat
1.4 0 8
$EndPostFormat
$View
two^steps 2
1 0 0  0 1 0  1 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0
0 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0  0 0 0
0 0 0 0
0.5 1.5
1 2 3 10 20
0 1 0 0 0 0  1 2 3 4 5 6  7 8 9 10 11 12
0 1 0 0 0 1 0 0 0  1 2 3 4 5 6
$EndView
)";

TEST_F(ViewFiles, ListBasedAsciiIsReadIntoNodeMajorLists) {
  const std::string path = file("list.pos", kListAscii);
  EXPECT_TRUE(isListBasedPosFile(path));
  post::ViewStore views;
  ASSERT_EQ(readListBasedPos(path, views), 1);
  const post::View& v = views.at(0);
  EXPECT_EQ(v.name, "two steps");
  EXPECT_EQ(v.times, (std::vector<double>{0.5, 1.5}));
  ASSERT_EQ(v.lists.size(), 3u);
  EXPECT_EQ(v.lists[0].shape, ElementShape::Point);
  EXPECT_EQ(v.lists[0].coordinates, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(v.lists[0].values, (std::vector<double>{10, 20}));
  const post::ElementList& vl = v.lists[1];
  EXPECT_EQ(vl.kind, FieldKind::Vector);
  EXPECT_EQ(vl.shape, ElementShape::Line);
  EXPECT_EQ(vl.coordinates, (std::vector<double>{0, 0, 0, 1, 0, 0}));
  EXPECT_EQ(vl.value(0, 1, 0, 2), 9);  // step 1, node 0, z
  const post::ElementList& st = v.lists[2];
  EXPECT_EQ(st.coordinates, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
  EXPECT_EQ(st.value(0, 1, 2, 0), 6);
  EXPECT_EQ(v.stepCount(), 2);
  // Files appended one after the other, each with its format header.
  post::ViewStore two;
  EXPECT_EQ(readListBasedPos(file("two.pos", std::string(kListAscii) + kListAscii), two), 2);
  EXPECT_EQ(two.at(1).lists[2].values, st.values);
}

// Version 1.3 (no second-order counts), as the reference writes it: the characters of the
// texts follow the last index directly, each string ended by a NUL.
TEST_F(ViewFiles, ListBasedTextsAreSplitAtTheirIndices) {
  std::string text = "$PostFormat /* comment */\n1.3 0 8\n$EndPostFormat\n$View /* t */\nt 2\n";
  for (int i = 0; i < 24; ++i) text += "0 ";
  text += "2 14 1 4\n0 1\n10 20 15 0 5 6 0 10";
  text += std::string("hello\0w^o\0ab\0\0", 14);
  text += " 1 2 3 0 0";
  text += std::string("03d\0", 4);
  text += "\n$EndView\n";
  post::ViewStore views;
  ASSERT_EQ(readListBasedPos(file("t.pos", text), views), 1);
  const post::View& v = views.at(0);
  ASSERT_EQ(v.texts.size(), 3u);
  EXPECT_EQ(v.texts[0].dimension, 2);
  EXPECT_EQ(v.texts[0].style, 15);
  EXPECT_EQ(v.texts[0].text, (std::vector<std::string>{"hello", "w^o"}));
  EXPECT_EQ(v.texts[1].x, 5);
  EXPECT_EQ(v.texts[1].text, (std::vector<std::string>{"ab", ""}));
  EXPECT_EQ(v.texts[2].dimension, 3);
  EXPECT_EQ(v.texts[2].z, 3);
  EXPECT_EQ(v.texts[2].text, (std::vector<std::string>{"03d"}));
}

template <class T>
void append(std::string& bytes, T v, std::endian order) {
  char raw[sizeof(T)];
  std::memcpy(raw, &v, sizeof(T));
  if (order != std::endian::native)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
  bytes.append(raw, sizeof(T));
}

// A binary file: one scalar triangle over one step and a 2D text.
std::string binaryList(std::endian order, std::size_t keep = std::string::npos) {
  std::string s = "$PostFormat\n1.4 1 8\n$EndPostFormat\n$View\nbin 1\n0 0 0 0 0 0 1";
  for (int i = 0; i < 38; ++i) s += " 0";
  s += " 1 3 0 0\n";
  append<std::int32_t>(s, 1, order);
  for (double d :
       {2.5, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 7.0, 8.0, 9.0, 3.0, 4.0, 0.0, 0.0})
    append(s, d, order);
  s += std::string("ok\0", 3);
  s += "\n$EndView\n";
  return s.substr(0, keep);
}

TEST_F(ViewFiles, ListBasedBinaryIsReadInEitherByteOrder) {
  for (std::endian order : {std::endian::little, std::endian::big}) {
    post::ViewStore views;
    ASSERT_EQ(readListBasedPos(file("b.pos", binaryList(order)), views), 1);
    const post::View& v = views.at(0);
    EXPECT_EQ(v.times, std::vector<double>{2.5});
    ASSERT_EQ(v.lists.size(), 1u);
    EXPECT_EQ(v.lists[0].shape, ElementShape::Triangle);
    EXPECT_EQ(v.lists[0].coordinates, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0}));
    EXPECT_EQ(v.lists[0].values, (std::vector<double>{7, 8, 9}));
    ASSERT_EQ(v.texts.size(), 1u);
    EXPECT_EQ(v.texts[0].x, 3);
    EXPECT_EQ(v.texts[0].text, std::vector<std::string>{"ok"});
  }
}

TEST_F(ViewFiles, MalformedListBasedFilesAreLocated) {
  std::string bad = kListAscii;
  bad.replace(bad.find("1 2 3 10 20"), 1, "x");
  const std::string path = file("bad.pos", bad);
  EXPECT_EQ(readError(path), path + ":10:1: expected a number, found 'x'");
  const std::string header = binaryList(std::endian::little);
  const std::size_t dataStart = header.find("0 0\n") + 4;
  const std::string cut =
      file("cut.pos", binaryList(std::endian::little, dataStart + 4 + 8 * 3 + 5));
  EXPECT_EQ(readError(cut), cut + ": byte " + std::to_string(dataStart + 4 + 8 * 3) +
                                ": unexpected end of binary data");
  std::string wrongCheck = header;
  wrongCheck[dataStart] = 7;
  const std::string check = file("check.pos", wrongCheck);
  EXPECT_EQ(readError(check), check + ": byte " + std::to_string(dataStart) +
                                  ": invalid binary check word (expected the integer 1)");
  const std::string version = file("v.pos", "$PostFormat\n1.2 0 8\n$EndPostFormat\n");
  EXPECT_EQ(readError(version),
            version + ":2:1: unsupported list-based .pos version (1.3 and 1.4 are supported)");
  const std::string noEnd = file("e.pos", std::string(kListAscii).substr(0, bad.find("$EndView")));
  EXPECT_EQ(readError(noEnd), noEnd + ":13:1: expected $EndView");
}

// Every cut of a file, and every byte of it changed, reads or fails with ViewReadError.
TEST_F(ViewFiles, DamagedListBasedFilesFailCleanly) {
  std::string text = kListAscii;
  for (const std::string& whole : {text, binaryList(std::endian::little)}) {
    int failures = 0;
    for (std::size_t cut = 0; cut < whole.size(); cut += 3) {  // a sample keeps it quick
      post::ViewStore views;
      try {
        readListBasedPos(file("cut.pos", whole.substr(0, cut)), views);
      } catch (const ViewReadError&) {
        ++failures;
      }
      std::string changed = whole;
      changed[cut] = static_cast<char>(changed[cut] ^ 0x5a);
      try {
        readListBasedPos(file("changed.pos", changed), views);
      } catch (const ViewReadError&) {
      }
    }
    EXPECT_GT(failures, int(whole.size()) / 6);  // most cuts fail
  }
}

TEST_F(ViewFiles, ParsedPosIsNotListBased) {
  EXPECT_FALSE(isListBasedPosFile(file("p.pos", "// comment\nView \"x\" {\n};\n")));
  EXPECT_TRUE(isListBasedPosFile(file("l.pos", "\n\n  $PostFormat\n1.4 0 8\n")));
  EXPECT_FALSE(isListBasedPosFile((dir_ / "missing.pos").string()));
}

}  // namespace
}  // namespace geomesh
