// The MSH reader: $MeshFormat, $PhysicalNames, dispatch of sections to the 4.1 or 2.2 readers.
#include "io/msh_reader.h"

#include <algorithm>
#include <fstream>
#include <istream>
#include <iterator>

#include "io/msh_read_state.h"

namespace geomesh {

void MshReadState::addToPhysical(int dim, int group, int entity) {
  std::vector<int>& members = physicalMembers[{dim, group}];
  if (std::find(members.begin(), members.end(), entity) == members.end()) members.push_back(entity);
}

NodeIndex MshReadState::node(MshDecoder& in, std::uint64_t tag) const {
  auto it = nodeIndex.find(tag);
  if (it == nodeIndex.end()) in.fail("node " + std::to_string(tag) + " is not defined");
  return it->second;
}

ElementType MshReadState::elementType(MshDecoder& in, int number) {
  const std::optional<ElementType> type = elementTypeFromNumber(number);
  if (!type) in.fail("unsupported element type " + std::to_string(number));
  return *type;
}

void MshReadState::checkDimension(MshDecoder& in, int dim) {
  if (dim < 0 || dim > 3) in.fail("invalid entity dimension " + std::to_string(dim));
}

void expectSectionEnd(MshDecoder& in, const char* marker) {
  if (in.atEnd()) in.fail(std::string("missing ") + marker);
  const std::string_view line = in.line();
  if (line != marker)
    in.fail("expected " + std::string(marker) + ", found '" + std::string(line.substr(0, 40)) +
            "'");
}

namespace {

// The $MeshFormat section, whose first line has been read: returns the major version (2 for
// 2.x and 3.0, whose sections have the same layout, or 4) and sets the encoding.
int readMeshFormat(MshDecoder& in, std::string_view firstLine) {
  if (firstLine != "$MeshFormat") in.fail("not an MSH file: no $MeshFormat");
  const std::string_view version = in.token();
  const int fileType = in.integer();
  const int dataSize = in.integer();
  int major = 0;
  if (version == "4.1")
    major = 4;
  else if (version == "2.2" || version == "2.1" || version == "2" || version == "2.0" ||
           version == "3.0" || version == "3")
    major = 2;
  else
    in.fail("unsupported MSH version " + std::string(version.substr(0, 20)) +
            " (4.1, 3.0, 2.x and 1.0 are supported)");
  if (fileType != 0 && fileType != 1) in.fail("invalid file type " + std::to_string(fileType));
  if (fileType == 1) {
    if (dataSize != 8) in.fail("unsupported data size " + std::to_string(dataSize));
    in.line();  // the rest of the version line
    in.setBinary(true);
    const int one = in.integer();
    in.setBinary(false);
    if (one != 1) in.fail("binary data in a foreign byte order is not supported");
  }
  expectSectionEnd(in, "$EndMeshFormat");
  in.setBinary(fileType == 1);
  return major;
}

void readPhysicalNames(MshDecoder& in, MshReadState& state) {
  const bool binary = in.binary();
  in.setBinary(false);  // names are text in binary files too
  const std::uint64_t count = in.size();
  for (std::uint64_t i = 0; i < count; ++i) {
    const int dim = in.integer();
    MshReadState::checkDimension(in, dim);
    const int tag = in.integer();
    state.physicalNames[{dim, tag}] = in.quoted();
  }
  expectSectionEnd(in, "$EndPhysicalNames");
  in.setBinary(binary);
}

void buildPhysicalGroups(MshReadState& state) {
  std::map<EntityId, PhysicalGroup> groups;
  for (const auto& [id, members] : state.physicalMembers)
    groups[id] = PhysicalGroup{id.dim, id.tag, "", members};
  for (const auto& [id, name] : state.physicalNames) {
    PhysicalGroup& g = groups[id];
    g.dim = id.dim;
    g.tag = id.tag;
    g.name = name;
  }
  for (auto& [id, group] : groups) state.model.addPhysicalGroup(std::move(group));
}

void readSection(MshDecoder& in, MshReadState& state, int major, std::string_view header) {
  if (header.size() < 2 || header.front() != '$')
    in.fail("expected a section, found '" + std::string(header.substr(0, 40)) + "'");
  const std::string name(header.substr(1));
  if (major == 1 && name == "NOD") return readMsh1Nodes(in, state);
  if (major == 1 && name == "ELM") return readMsh1Elements(in, state);
  if (major == 1) in.fail("unexpected section $" + name.substr(0, 40) + " in an MSH 1.0 file");
  if (name == "PhysicalNames") return readPhysicalNames(in, state);
  if (major == 4 && name == "Entities") return readMsh41Entities(in, state);
  if (major == 4 && name == "Nodes") return readMsh41Nodes(in, state);
  if (major == 4 && name == "Elements") return readMsh41Elements(in, state);
  if (major == 2 && name == "Nodes") return readMsh22Nodes(in, state);
  if (major == 2 && name == "Elements") return readMsh22Elements(in, state);
  if (major == 4 && name == "Periodic") return readMsh41Periodic(in, state);
  if (major == 2 && name == "Periodic") return readMsh22Periodic(in, state);
  if (major == 4 && name == "PartitionedEntities") return readMsh41PartitionedEntities(in, state);
  in.skipPast("$End" + name);  // data we do not use: post-processing views...
}

}  // namespace

void readMsh(std::istream& in, Model& model, Mesh& mesh, const std::string& name) {
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  model.clear();
  mesh.clear();
  MshDecoder decoder(data, name);
  MshReadState state{model, mesh, {}, {}, {}, 0, {}};
  try {
    if (decoder.atEnd()) decoder.fail("not an MSH file: no $MeshFormat");
    const std::string_view first = decoder.line();
    // MSH 1.0 has no $MeshFormat: it starts with its nodes.
    const int major = first == "$NOD" ? 1 : readMeshFormat(decoder, first);
    if (major == 1) readSection(decoder, state, major, first);
    while (!decoder.atEnd()) readSection(decoder, state, major, decoder.line());
    attachPartitions(state);
    buildPhysicalGroups(state);
  } catch (const MshReadError&) {
    model.clear();  // no half-read result
    mesh.clear();
    throw;
  }
}

void readMshFile(const std::string& path, Model& model, Mesh& mesh) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw MshReadError("cannot open '" + path + "'", 0);
  readMsh(file, model, mesh, path);
}

}  // namespace geomesh
