// Reading I-DEAS universal files: nodes (2411), elements (2412) and groups (2477, 2467); other
// datasets are skipped. Elements go to discrete entities by physical property table number,
// split where groups take part of them, and groups become physical groups.
#include <algorithm>
#include <istream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "io/discrete_mesh.h"
#include "io/formats.h"
#include "io/mesh_scanner.h"
#include "io/physical_sets.h"
#include "io/unv_elements.h"

namespace geomesh {

namespace {

struct UnvElementRecord {
  ElementType type;
  int property = 0;
  std::size_t firstNode = 0;  // in UnvContent::elementNodes, in MSH order
  std::vector<int> groups;    // indices in UnvContent::groups
};

struct UnvGroup {
  int line = 0;  // where its record starts
  int number = 0;
  std::string name;
  std::vector<long long> elements;  // labels
};

struct UnvContent {
  std::unordered_map<long long, NodeIndex> nodes;  // label -> mesh node
  std::vector<UnvElementRecord> elements;
  std::unordered_map<long long, std::size_t> elementIndex;  // label -> index in elements
  std::vector<NodeIndex> elementNodes;
  std::vector<UnvGroup> groups;
};

// A FORTRAN real: D or E exponent.
double unvReal(MeshScanner& in) {
  std::string text(in.word());
  std::replace(text.begin(), text.end(), 'D', 'E');
  std::replace(text.begin(), text.end(), 'd', 'e');
  return parseNumber<double>(in, text, "a coordinate");
}

// Reads the first field of a record; false at the delimiter that ends the dataset.
bool recordStart(MeshScanner& in, long long& value) {
  const std::string_view word = in.word();
  if (word == "-1") return false;
  value = parseNumber<long long>(in, word, "an integer");
  return true;
}

void readNodes(MeshScanner& in, Mesh& mesh, UnvContent& content) {
  long long label = 0;
  while (recordStart(in, label)) {
    for (int i = 0; i < 3; ++i) in.number<int>("an integer");
    const Vec3 p{unvReal(in), unvReal(in), unvReal(in)};
    if (!content.nodes.emplace(label, static_cast<NodeIndex>(mesh.nodeCount())).second)
      in.fail("node " + std::to_string(label) + " is defined twice");
    mesh.addNode(p);
  }
}

void readElement(MeshScanner& in, UnvContent& content, long long label) {
  const int descriptor = in.number<int>("an FE descriptor id");
  const UnvElement* unv = unvElementForReading(descriptor);
  if (!unv) in.fail("unsupported FE descriptor id " + std::to_string(descriptor));
  const int property = in.number<int>("a physical property table number");
  in.number<int>("a material property table number");
  in.number<int>("a colour");
  const int count = in.number<int>("a node count");
  if (count != nodeCount(unv->type))
    in.fail("FE descriptor " + std::to_string(descriptor) + " has " +
            std::to_string(nodeCount(unv->type)) + " nodes, not " + std::to_string(count));
  if (unvHasBeamRecord(descriptor))
    for (int i = 0; i < 3; ++i) in.number<int>("a beam record value");
  const std::size_t first = content.elementNodes.size();
  content.elementNodes.resize(first + count);
  for (int k : unv->fromMsh) {
    const long long node = in.number<long long>("a node label");
    const auto it = content.nodes.find(node);
    if (it == content.nodes.end()) in.fail("node " + std::to_string(node) + " is not defined");
    content.elementNodes[first + k] = it->second;
  }
  if (!content.elementIndex.emplace(label, content.elements.size()).second)
    in.fail("element " + std::to_string(label) + " is defined twice");
  content.elements.push_back({unv->type, property, first, {}});
}

void readElements(MeshScanner& in, UnvContent& content) {
  long long label = 0;
  while (recordStart(in, label)) readElement(in, content, label);
}

// 2477 and 2467: per group, its number, six set numbers, its size, its name on a line of its
// own, then (entity type, label, 0, 0) per member: 7 a node, 8 an element.
void readGroups(MeshScanner& in, UnvContent& content) {
  long long number = 0;
  while (recordStart(in, number)) {
    const int line = in.lineNumber();
    for (int i = 0; i < 6; ++i) in.number<int>("an integer");
    const auto size = in.number<std::uint64_t>("a group size");
    if (size > in.remaining() / 8) in.fail("group size " + std::to_string(size) + " too large");
    in.line();  // the end of the record
    std::string_view name = in.line();
    name.remove_prefix(std::min(name.find_first_not_of(' '), name.size()));
    UnvGroup group{line, static_cast<int>(number), std::string(name), {}};
    for (std::uint64_t i = 0; i < size; ++i) {
      const int type = in.number<int>("an entity type code");
      const long long label = in.number<long long>("an entity label");
      in.number<long long>("an integer");
      in.number<long long>("an integer");
      if (type == 8) group.elements.push_back(label);
    }
    content.groups.push_back(std::move(group));
  }
}

bool isDelimiter(std::string_view line) {
  const std::size_t start = line.find_first_not_of(' ');
  return start != std::string_view::npos && line.substr(start) == "-1";
}

void skipDataset(MeshScanner& in) {
  while (!isDelimiter(in.line())) {
  }
}

void readDataset(MeshScanner& in, Mesh& mesh, UnvContent& content) {
  if (in.word() != "-1") in.fail("expected -1, the start of a dataset");
  const int id = in.number<int>("a dataset number");
  switch (id) {
    case 2411:
      return readNodes(in, mesh, content);
    case 2412:
      return readElements(in, content);
    case 2467:
    case 2477:
      return readGroups(in, content);
    default:
      in.line();
      return skipDataset(in);
  }
}

// Builds the entities and physical groups once the whole file is read (groups come last).
// Elements of one dimension and property table number that groups split apart get entities
// of their own, tagged after the largest table number.
class UnvModelBuilder {
 public:
  UnvModelBuilder(MeshScanner& in, Mesh& mesh, UnvContent& content)
      : in_(in), mesh_(mesh), content_(content) {}

  std::vector<PhysicalGroup> build() {
    markGroupMembers();
    for (UnvElementRecord& e : content_.elements) {
      const int tag = entityTag(e);
      ElementBlock& block = mesh_.entity({dimension(e.type), tag}).block(e.type);
      const auto first = content_.elementNodes.begin() + static_cast<std::ptrdiff_t>(e.firstNode);
      block.nodes.insert(block.nodes.end(), first, first + nodeCount(e.type));
      for (int g : e.groups) addMember(g, dimension(e.type), tag);
    }
    std::vector<PhysicalGroup> groups;
    for (auto& [key, group] : physical_) groups.push_back(std::move(group));
    return groups;
  }

 private:
  void markGroupMembers() {
    for (std::size_t g = 0; g < content_.groups.size(); ++g)
      for (long long label : content_.groups[g].elements) {
        const auto it = content_.elementIndex.find(label);
        if (it == content_.elementIndex.end())
          in_.fail("group '" + content_.groups[g].name + "' names element " +
                       std::to_string(label) + ", which is not defined",
                   content_.groups[g].line);
        std::vector<int>& groups = content_.elements[it->second].groups;
        if (std::find(groups.begin(), groups.end(), g) == groups.end())
          groups.push_back(static_cast<int>(g));
      }
  }

  int entityTag(UnvElementRecord& e) {
    std::sort(e.groups.begin(), e.groups.end());
    const int dim = dimension(e.type);
    const auto key = std::make_tuple(dim, e.property, e.groups);
    if (const auto it = tags_.find(key); it != tags_.end()) return it->second;
    int& next = nextTag_[dim];
    if (next == 0) next = maxProperty(dim) + 1;
    const bool propertyTaken = usedTags_.contains({dim, e.property});
    const int tag = propertyTaken ? next++ : e.property;
    usedTags_.insert({dim, tag});
    return tags_[key] = tag;
  }

  int maxProperty(int dim) const {
    int most = 0;
    for (const UnvElementRecord& e : content_.elements)
      if (dimension(e.type) == dim) most = std::max(most, e.property);
    return most;
  }

  void addMember(int g, int dim, int entity) {
    const UnvGroup& source = content_.groups[g];
    PhysicalGroup& group = physical_[{dim, source.number}];
    if (group.entities.empty()) {
      group.dim = dim;
      group.tag = source.number;
      const bool defaultName = source.name == physicalGroupName({dim, source.number, "", {}});
      group.name = defaultName ? "" : source.name;
    }
    if (std::find(group.entities.begin(), group.entities.end(), entity) == group.entities.end())
      group.entities.push_back(entity);
  }

  MeshScanner& in_;
  Mesh& mesh_;
  UnvContent& content_;
  std::map<std::tuple<int, int, std::vector<int>>, int> tags_;
  std::set<EntityId> usedTags_;
  std::map<int, int> nextTag_;
  std::map<EntityId, PhysicalGroup> physical_;
};

}  // namespace

// Named by the unv row of io/formats.cpp.
void readUnv(std::istream& in, Model& model, Mesh& mesh, const std::string& name) {
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  readReplacing(model, mesh, [&] {
    MeshScanner scanner(data, name);
    UnvContent content;
    if (scanner.atEnd()) scanner.fail("empty file");
    while (!scanner.atEnd()) readDataset(scanner, mesh, content);
    addDiscreteEntities(model, mesh, UnvModelBuilder(scanner, mesh, content).build());
  });
}

}  // namespace geomesh
