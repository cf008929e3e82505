// The data sections of MSH files ($NodeData, $ElementData, $ElementNodeData; 4.1 and 2.2, ASCII
// and binary) read into views over the mesh the same file holds.
#include <algorithm>
#include <cstring>
#include <optional>
#include <span>
#include <unordered_map>

#include "io/msh_view_data.h"
#include "io/view_file_parts.h"
#include "io/view_scanner.h"

namespace geomesh {

using post::MeshData;

namespace {

struct MshLayout {
  bool v4 = true;
  bool binary = false;
  std::endian order = std::endian::little;
};

// Values as the file holds them: words in ASCII files, raw values in binary data.
struct MshValues {
  ViewScanner& in;
  MshLayout layout;
  bool binaryData = false;  // inside a binary data block

  std::uint64_t size() {
    return binaryData ? in.raw<std::uint64_t>(layout.order)
                      : in.number<std::uint64_t>("a non-negative integer");
  }
  int integer() {
    return binaryData ? in.raw<std::int32_t>(layout.order) : in.number<int>("an integer");
  }
  double real() { return binaryData ? in.rawReal(layout.order, 8) : in.real(); }
  // Where the next value starts (for messages about it).
  std::size_t here() {
    if (!binaryData) in.skipSpace();
    return in.offset();
  }
  // Starts binary data after the current text line (no-op in ASCII files).
  void beginData() {
    if (!layout.binary) return;
    in.line();
    binaryData = true;
    in.setBinary(true);
  }
  void endData() {
    binaryData = false;
    in.setBinary(false);
  }
  // A count bounded by what the rest of the file can hold.
  std::uint64_t count(std::uint64_t n, std::size_t minBytesEach) {
    if (n > in.remaining() / std::max<std::size_t>(minBytesEach, 1))
      in.fail("count " + std::to_string(n) + " exceeds the size of the file");
    return n;
  }
};

MshLayout readMeshFormat(ViewScanner& in) {
  in.word();  // $MeshFormat
  const std::string_view version = in.word();
  MshLayout layout;
  layout.v4 = version.starts_with("4");
  if (!layout.v4 && !version.starts_with("2") && !version.starts_with("3"))
    in.fail("unsupported MSH version " + std::string(version.substr(0, 20)));
  const int fileType = in.number<int>("a file type");
  const int dataSize = in.number<int>("a data size");
  if (fileType != 0 && fileType != 1) in.fail("invalid file type (0: ASCII, 1: binary)");
  if (dataSize != 8) in.fail("unsupported data size " + std::to_string(dataSize));
  layout.binary = fileType == 1;
  if (layout.binary) {
    in.line();
    in.setBinary(true);
    const auto one = in.raw<std::int32_t>(std::endian::little);
    in.setBinary(false);
    if (one == 0x01000000)
      layout.order = std::endian::big;
    else if (one != 1)
      in.fail("invalid binary check word (expected the integer 1)");
  }
  return layout;
}

void expectEnd(ViewScanner& in) {
  if (in.atEnd() || !in.word().starts_with("$End")) in.fail("expected the end of the section");
}

// The MSH 2.2 count opening $Nodes and $Elements is text in binary files too.
std::uint64_t textCount(MshValues& v) {
  const std::uint64_t n = v.in.number<std::uint64_t>("a count");
  v.beginData();
  return v.count(n, 4);
}

void skipSection(ViewScanner& in);

void readNodes(MshValues& v, const Mesh& mesh, FileMeshTags& tags) {
  if (tags.nodesGiven) return skipSection(v.in);
  v.in.word();  // $Nodes
  tags.nodes.clear();
  tags.hasNodes = true;
  auto addNode = [&](std::uint64_t tag, std::size_t tagAt) {
    if (tags.nodes.size() >= mesh.nodeCount())
      v.in.failAt(tagAt, "the file has more nodes than the mesh");
    if (!tags.nodes.emplace(tag, tags.nodes.size() + 1).second)
      v.in.failAt(tagAt, "node " + std::to_string(tag) + " is defined twice");
  };
  // The mesh read from this file has its nodes in the file's order, at the same places.
  auto checkPlace = [&](std::size_t index, std::size_t at) {
    const Vec3 file{v.real(), v.real(), v.real()};
    const Vec3 own = mesh.node(static_cast<NodeIndex>(index));
    if (file.x != own.x || file.y != own.y || file.z != own.z)
      v.in.failAt(at, "node " + std::to_string(index + 1) +
                          " of the file is not where the mesh has it (a mesh of another file?)");
  };
  if (!v.layout.v4) {
    const std::uint64_t n = textCount(v);
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::size_t at = v.here();
      const std::uint64_t tag = v.binaryData ? std::uint64_t(v.integer()) : v.size();
      addNode(tag, at);
      checkPlace(tags.nodes.size() - 1, v.here());
    }
  } else {
    v.beginData();
    const std::uint64_t blocks = v.count(v.size(), 4);
    v.size();  // total, smallest and largest tags
    v.size();
    v.size();
    for (std::uint64_t b = 0; b < blocks; ++b) {
      const int dim = v.integer();
      v.integer();  // entity tag
      const int parametric = v.integer();
      const std::uint64_t n = v.count(v.size(), 4);
      const std::size_t first = tags.nodes.size();
      for (std::uint64_t i = 0; i < n; ++i) {
        const std::size_t at = v.here();
        addNode(v.size(), at);
      }
      const int uv = parametric ? std::clamp(dim, 0, 3) : 0;
      for (std::uint64_t i = 0; i < n; ++i) {
        checkPlace(first + i, v.here());
        for (int k = 0; k < uv; ++k) v.real();
      }
    }
  }
  v.endData();
  expectEnd(v.in);
}

// The mesh elements in the order that gives them their tags (see FileMeshTags), found by
// their type and nodes.
class MeshElementIndex {
 public:
  explicit MeshElementIndex(const Mesh& mesh) {
    std::uint64_t tag = 0;
    for (const auto& [id, em] : mesh.entities())
      for (const ElementBlock& b : em.blocks)
        for (std::size_t i = 0; i < b.size(); ++i)
          byNodes_.emplace(key(b.type, b.element(i)), ++tag);
  }
  // 0 when the mesh has no such element.
  std::uint64_t find(ElementType type, std::span<const NodeIndex> nodes) const {
    const auto it = byNodes_.find(key(type, nodes));
    return it == byNodes_.end() ? 0 : it->second;
  }

 private:
  static std::string key(ElementType type, std::span<const NodeIndex> nodes) {
    std::string k(1 + 4 * nodes.size(), '\0');
    k[0] = static_cast<char>(type);
    std::memcpy(k.data() + 1, nodes.data(), 4 * nodes.size());
    return k;
  }
  std::unordered_map<std::string, std::uint64_t> byNodes_;
};

// One element of the file: its nodes found in the mesh, then the mesh element they make.
void addElement(MshValues& v, const MeshElementIndex& index, FileMeshTags& tags, std::uint64_t tag,
                std::size_t tagAt, ElementType type, std::vector<NodeIndex>& nodes) {
  for (NodeIndex& n : nodes) {
    const std::size_t at = v.here();
    const std::uint64_t nodeTag =
        v.binaryData && !v.layout.v4 ? std::uint64_t(v.integer()) : v.size();
    const auto it = tags.nodes.find(nodeTag);
    if (it == tags.nodes.end())
      v.in.failAt(at, "node " + std::to_string(nodeTag) + " is not defined");
    n = static_cast<NodeIndex>(it->second - 1);
  }
  const std::uint64_t meshTag = index.find(type, nodes);
  if (meshTag == 0) v.in.failAt(tagAt, "element " + std::to_string(tag) + " is not in the mesh");
  tags.elements[tag] = meshTag;
}

ElementType elementType(MshValues& v) {
  const std::size_t at = v.here();
  const int number = v.integer();
  const std::optional<ElementType> type = elementTypeFromNumber(number);
  if (!type) v.in.failAt(at, "unsupported element type " + std::to_string(number));
  return *type;
}

void readElements22(MshValues& v, const MeshElementIndex& index, FileMeshTags& tags) {
  const std::uint64_t n = textCount(v);
  std::vector<NodeIndex> nodes;
  for (std::uint64_t read = 0; read < n;) {
    if (v.binaryData) {
      const ElementType type = elementType(v);
      const int group = v.integer();
      const int tagCount = v.integer();
      if (group <= 0 || std::uint64_t(group) > n - read || tagCount < 0 || tagCount > 1000)
        v.in.fail("invalid element group header");
      for (int i = 0; i < group; ++i, ++read) {
        const std::size_t at = v.here();
        const std::uint64_t tag = std::uint64_t(v.integer());
        for (int k = 0; k < tagCount; ++k) v.integer();
        nodes.resize(std::size_t(nodeCount(type)));
        addElement(v, index, tags, tag, at, type, nodes);
      }
    } else {
      const std::size_t at = v.here();
      const std::uint64_t tag = v.size();
      const ElementType type = elementType(v);
      const int tagCount = v.integer();
      if (tagCount < 0 || tagCount > 1000) v.in.fail("invalid tag count");
      for (int k = 0; k < tagCount; ++k) v.integer();
      nodes.resize(std::size_t(nodeCount(type)));
      addElement(v, index, tags, tag, at, type, nodes);
      ++read;
    }
  }
}

void readElements41(MshValues& v, const MeshElementIndex& index, FileMeshTags& tags) {
  v.beginData();
  const std::uint64_t blocks = v.count(v.size(), 4);
  for (int k = 0; k < 3; ++k) v.size();
  std::vector<NodeIndex> nodes;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    v.integer();  // dimension and entity
    v.integer();
    const ElementType type = elementType(v);
    const std::uint64_t n = v.count(v.size(), 4);
    nodes.resize(std::size_t(nodeCount(type)));
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::size_t at = v.here();
      addElement(v, index, tags, v.size(), at, type, nodes);
    }
  }
}

void readElements(MshValues& v, const Mesh& mesh, FileMeshTags& tags) {
  v.in.word();  // $Elements
  if (!tags.hasNodes) v.in.fail("$Elements before $Nodes");
  tags.elements.clear();
  tags.hasElements = true;
  const MeshElementIndex index(mesh);
  if (v.layout.v4)
    readElements41(v, index, tags);
  else
    readElements22(v, index, tags);
  v.endData();
  expectEnd(v.in);
}

// Skips a section the views do not use, up to its end marker.
void skipSection(ViewScanner& in) {
  const std::string_view header = in.word();
  const std::string end = "$End" + std::string(header.substr(1));
  const std::size_t at = in.data().find(end, in.offset());
  if (at == std::string_view::npos) in.fail("missing " + end);
  in.seek(at + end.size());
}

// The header of a data section: string, real and integer tags, each list after its count.
DataSection readDataHeader(MshValues& v, MeshData::Kind kind) {
  DataSection s;
  s.kind = kind;
  const int strings = v.in.number<int>("a number of string tags");
  if (strings < 0 || std::size_t(strings) > v.in.remaining()) v.in.fail("invalid tag count");
  for (int i = 0; i < strings; ++i) {
    v.in.skipSpace();
    std::string_view text = v.in.line();
    if (text.size() >= 2 && text.front() == '"' && text.back() == '"')
      text = text.substr(1, text.size() - 2);
    if (i == 0) s.name = std::string(text);
  }
  const int reals = v.in.number<int>("a number of real tags");
  if (reals < 0 || std::size_t(reals) > v.in.remaining()) v.in.fail("invalid tag count");
  for (int i = 0; i < reals; ++i) {
    const double r = v.in.real();
    if (i == 0) s.step.time = r;
  }
  const int integers = v.in.number<int>("a number of integer tags");
  if (integers < 3 || std::size_t(integers) > v.in.remaining())
    v.in.fail("a data section needs at least 3 integer tags (time step, components, count)");
  std::int64_t values[3] = {};
  for (int i = 0; i < integers; ++i) {
    const std::size_t at = v.here();
    const auto t = v.in.number<std::int64_t>("an integer tag");
    if (i < 3) values[i] = t;
    if (i == 1 && t != 1 && t != 2 && t != 3 && t != 6 && t != 9)
      v.in.failAt(at,
                  "unsupported number of components " + std::to_string(t) + " (1, 2, 3, 6 or 9)");
    if (i == 2 && (t < 0 || std::uint64_t(t) > v.in.remaining() / 2))
      v.in.failAt(at, "invalid number of entries " + std::to_string(t));
  }
  s.step.index = static_cast<int>(values[0]);
  s.components = static_cast<int>(values[1]);
  s.entries = static_cast<std::size_t>(values[2]);
  return s;
}

// A tag of the file in a data section, as the mesh tag it names.
std::uint64_t meshTagOf(MshValues& v, const Mesh& mesh, const FileMeshTags& tags,
                        MeshData::Kind kind, std::size_t elementCount) {
  const std::size_t at = v.here();
  const std::uint64_t tag = v.binaryData ? std::uint64_t(std::uint32_t(v.integer())) : v.size();
  const bool node = kind == MeshData::Kind::Node;
  std::uint64_t meshTag = 0;
  if (node ? tags.hasNodes : tags.hasElements) {
    const auto& map = node ? tags.nodes : tags.elements;
    const auto it = map.find(tag);
    if (it != map.end()) meshTag = it->second;
  } else if (tag >= 1 && tag <= (node ? mesh.nodeCount() : elementCount)) {
    meshTag = tag;
  }
  if (meshTag == 0)
    v.in.failAt(
        at, std::string(node ? "node " : "element ") + std::to_string(tag) + " is not in the mesh");
  return meshTag;
}

DataSection readDataSection(MshValues& v, const Mesh& mesh, const FileMeshTags& tags,
                            const std::vector<ElementType>& elementTypes, MeshData::Kind kind) {
  v.in.word();  // the section marker
  v.in.skipSpace();
  DataSection s = readDataHeader(v, kind);
  s.at = v.in.offset();
  v.beginData();
  v.count(s.entries, v.binaryData ? 12 : 4);  // at least a tag and one value each
  for (std::size_t e = 0; e < s.entries; ++e) {
    const std::uint64_t tag = meshTagOf(v, mesh, tags, kind, elementTypes.size());
    s.step.tags.push_back(tag);
    int perEntry = 1;
    if (kind == MeshData::Kind::ElementNode) {
      const std::size_t at = v.here();
      perEntry = v.integer();
      if (perEntry != nodeCount(elementTypes[tag - 1]))
        v.in.failAt(at, "element " + std::to_string(tag) + " has " +
                            std::to_string(nodeCount(elementTypes[tag - 1])) + " nodes, not " +
                            std::to_string(perEntry));
      s.step.counts.push_back(perEntry);
    }
    for (int k = 0; k < perEntry * s.components; ++k) s.step.values.push_back(v.real());
  }
  v.endData();
  expectEnd(v.in);
  return s;
}

std::vector<ElementType> meshElementTypes(const Mesh& mesh) {
  std::vector<ElementType> types;
  for (const auto& [id, em] : mesh.entities())
    for (const ElementBlock& b : em.blocks) types.insert(types.end(), b.size(), b.type);
  return types;
}

}  // namespace

std::vector<DataSection> readMshDataSections(const std::string& data, const std::string& path,
                                             const Mesh& mesh, FileMeshTags* tagsOut) {
  ViewScanner in(data, path);
  MshValues v{in, {}};
  FileMeshTags tags = tagsOut ? std::move(*tagsOut) : FileMeshTags{};
  const std::vector<ElementType> types = meshElementTypes(mesh);
  std::vector<DataSection> sections;
  bool formatSeen = false;
  while (!in.atEnd()) {
    const std::string_view header = in.peekWord();
    if (header == "$MeshFormat") {
      v.layout = readMeshFormat(in);
      formatSeen = true;
      expectEnd(in);
      continue;
    }
    if (!formatSeen) {
      in.word();
      in.fail("not an MSH file: no $MeshFormat");
    }
    if (header == "$Nodes")
      readNodes(v, mesh, tags);
    else if (header == "$Elements")
      readElements(v, mesh, tags);
    else if (header == "$NodeData")
      sections.push_back(readDataSection(v, mesh, tags, types, MeshData::Kind::Node));
    else if (header == "$ElementData")
      sections.push_back(readDataSection(v, mesh, tags, types, MeshData::Kind::Element));
    else if (header == "$ElementNodeData")
      sections.push_back(readDataSection(v, mesh, tags, types, MeshData::Kind::ElementNode));
    else if (header.starts_with("$"))
      skipSection(in);
    else {
      in.word();
      in.fail("expected a section, found '" + std::string(header.substr(0, 40)) + "'");
    }
  }
  if (tagsOut) *tagsOut = std::move(tags);
  return sections;
}

}  // namespace geomesh
