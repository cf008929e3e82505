// The $Periodic section: for each periodic entity, its master, the affine map from the master
// to it and the pairs (node, master node). MSH 4.1 writes the map as a count followed by the
// values, in the file's encoding; MSH 2.2 as "Affine" and the values, always as text.
#include <charconv>
#include <cstdio>
#include <string>
#include <vector>

#include "io/msh_read_state.h"
#include "io/msh_sections.h"

namespace geomesh {

namespace {

struct SavedLink {
  EntityId entity;
  const PeriodicLink* link;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> tags;  // saved pairs, as file tags
};

std::vector<SavedLink> savedLinks(const Mesh& mesh, const MshContent& content) {
  std::vector<SavedLink> links;
  for (EntityId e : content.entities) {
    const EntityMesh* em = mesh.find(e);
    if (!em || !em->periodic) continue;
    SavedLink saved{e, &*em->periodic, {}};
    for (const auto& [node, master] : em->periodic->nodes)
      if (node < content.nodeTag.size() && master < content.nodeTag.size() &&
          content.nodeTag[node] != 0 && content.nodeTag[master] != 0)
        saved.tags.push_back({content.nodeTag[node], content.nodeTag[master]});
    links.push_back(std::move(saved));
  }
  return links;
}

void writeMsh41Link(MshEncoder& out, const SavedLink& s) {
  out.integer(s.entity.dim);
  out.integer(s.entity.tag);
  out.integer(s.link->master);
  out.endLine();
  out.size(s.link->affine.size());
  for (double v : s.link->affine) out.real(v);
  out.endLine();
  out.size(s.tags.size());
  out.endLine();
  for (const auto& [node, master] : s.tags) {
    out.size(node);
    out.size(master);
    out.endLine();
  }
}

std::string msh22Link(const SavedLink& s) {
  std::string text = std::to_string(s.entity.dim) + " " + std::to_string(s.entity.tag) + " " +
                     std::to_string(s.link->master) + "\n";
  if (!s.link->affine.empty()) {
    text += "Affine";
    char number[32];
    for (double v : s.link->affine) {
      std::snprintf(number, sizeof number, " %.16g", v);
      text += number;
    }
    text += "\n";
  }
  text += std::to_string(s.tags.size()) + "\n";
  for (const auto& [node, master] : s.tags)
    text += std::to_string(node) + " " + std::to_string(master) + "\n";
  return text;
}

// An MSH 2.2 count or tag read as a text token, which may also be the word "Affine".
std::uint64_t parseCount(MshDecoder& in, std::string_view token) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size())
    in.fail("expected a count in $Periodic, found '" + std::string(token.substr(0, 40)) + "'");
  return value;
}

// The mesh of the entity a link names (Gmsh also links entities whose mesh is not saved).
EntityMesh& linkedEntity(MshDecoder& in, MshReadState& state, int dim, int tag) {
  MshReadState::checkDimension(in, dim);
  return state.mesh.entity({dim, tag});
}

void readPairs(MshDecoder& in, MshReadState& state, std::uint64_t count, PeriodicLink& link) {
  if (count > in.remaining()) in.fail("too many node pairs in $Periodic");
  for (std::uint64_t k = 0; k < count; ++k) {
    const NodeIndex node = state.node(in, in.size());
    link.nodes.push_back({node, state.node(in, in.size())});
  }
}

}  // namespace

void writePeriodic(MshEncoder& out, const Mesh& mesh, const MshContent& content, bool msh2) {
  const std::vector<SavedLink> links = savedLinks(mesh, content);
  if (links.empty()) return;
  if (msh2) {
    std::string text = "$Periodic\n" + std::to_string(links.size()) + "\n";
    for (const SavedLink& s : links) text += msh22Link(s);
    out.text(text + "$EndPeriodic\n");
    return;
  }
  out.text("$Periodic\n");
  out.size(links.size());
  out.endLine();
  for (const SavedLink& s : links) writeMsh41Link(out, s);
  endSection(out, "$EndPeriodic\n");
}

void readMsh41Periodic(MshDecoder& in, MshReadState& state) {
  const std::uint64_t count = in.size();
  if (count > in.remaining()) in.fail("too many links in $Periodic");
  for (std::uint64_t k = 0; k < count; ++k) {
    const int dim = in.integer();
    const int tag = in.integer();
    PeriodicLink link{in.integer(), {}, {}};
    const std::uint64_t values = in.size();
    if (values != 0 && values != 16) in.fail("an affine map has 16 values, not " +
                                              std::to_string(values));
    for (std::uint64_t v = 0; v < values; ++v) link.affine.push_back(in.real());
    readPairs(in, state, in.size(), link);
    linkedEntity(in, state, dim, tag).periodic = std::move(link);
  }
  expectSectionEnd(in, "$EndPeriodic");
}

void readMsh22Periodic(MshDecoder& in, MshReadState& state) {
  const bool binary = in.binary();
  in.setBinary(false);  // written as text in binary files too
  const std::uint64_t count = parseCount(in, in.token());
  if (count > in.remaining()) in.fail("too many links in $Periodic");
  for (std::uint64_t k = 0; k < count; ++k) {
    const int dim = in.integer();
    const int tag = in.integer();
    PeriodicLink link{in.integer(), {}, {}};
    std::string_view token = in.token();
    if (token == "Affine") {
      for (int v = 0; v < 16; ++v) link.affine.push_back(in.real());
      token = in.token();
    }
    readPairs(in, state, parseCount(in, token), link);
    linkedEntity(in, state, dim, tag).periodic = std::move(link);
  }
  expectSectionEnd(in, "$EndPeriodic");
  in.setBinary(binary);
}

}  // namespace geomesh
