// meshPageJson: a MeshPage as the JSON block the viewer script reads (viewer/src/data.js).
#include <charconv>
#include <string>

#include "io/base64.h"
#include "io/mesh_page.h"

namespace geomesh {

namespace {

// A JSON string; '<' escaped too, so that the text never closes the <script> it sits in.
std::string quoted(std::string_view text) {
  std::string out = "\"";
  for (char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || c == '<' || c == '>' || c == '&') {
      static constexpr char kHex[] = "0123456789abcdef";
      out += "\\u00";
      out += kHex[u >> 4];
      out += kHex[u & 15];
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string number(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

// Lowercase family names, those of the first-order types ("tetrahedron").
std::string familyName(ElementFamily f) {
  return elementName(linearType(f));
}

std::string cornerLists(const std::vector<std::vector<int>>& lists) {
  std::string out = "[";
  for (const std::vector<int>& list : lists) {
    out += out.size() > 1 ? ",[" : "[";
    for (std::size_t i = 0; i < list.size(); ++i) out += (i ? "," : "") + std::to_string(list[i]);
    out += "]";
  }
  return out + "]";
}

std::string families() {
  std::string out = "{";
  for (ElementFamily f :
       {ElementFamily::Line, ElementFamily::Triangle, ElementFamily::Quad, ElementFamily::Tet,
        ElementFamily::Hex, ElementFamily::Prism, ElementFamily::Pyramid}) {
    const NodePlaces edges = familyEdges(f);
    out += (out.size() > 1 ? "," : "") + quoted(familyName(f)) +
           ":{\"dim\":" + std::to_string(dimension(f)) +
           ",\"corners\":" + std::to_string(vertexCount(f)) +
           ",\"faces\":" + cornerLists(volumeFaces(f)) + ",\"edges\":" + cornerLists(edges) + "}";
  }
  return out + "}";
}

std::string groups(const MeshPage& page) {
  std::string out = "[";
  for (const PageGroup& g : page.groups)
    out += (out.size() > 1 ? "," : "") + std::string("{\"name\":") + quoted(g.name) +
           ",\"dim\":" + std::to_string(g.dim) + ",\"tag\":" + std::to_string(g.tag) +
           ",\"physical\":" + (g.physical ? "true" : "false") + "}";
  return out + "]";
}

std::string block(const PageBlock& b) {
  std::string out = "{\"entity\":[" + std::to_string(b.entity.dim) + "," +
                    std::to_string(b.entity.tag) + "],\"type\":" + quoted(elementName(b.type)) +
                    ",\"family\":" + quoted(familyName(family(b.type))) +
                    ",\"firstId\":" + std::to_string(b.firstId) +
                    ",\"count\":" + std::to_string(b.size()) + ",\"groups\":[";
  for (std::size_t i = 0; i < b.groups.size(); ++i)
    out += (i ? "," : "") + std::to_string(b.groups[i]);
  out += "],\"nodes\":" + quoted(base64OfUint32s(b.corners));
  if (!b.gamma.empty())
    out += ",\"quality\":{\"gamma\":" + quoted(base64OfFloats(b.gamma)) +
           ",\"sicn\":" + quoted(base64OfFloats(b.sicn)) + "}";
  if (!b.neighbours.empty()) out += ",\"neighbours\":" + quoted(base64OfUint32s(b.neighbours));
  return out + "}";
}

}  // namespace

std::string meshPageJson(const MeshPage& page) {
  std::string out = "{\"version\":1,\"origin\":[" + number(page.origin.x) + "," +
                    number(page.origin.y) + "," + number(page.origin.z) + "]";
  out += ",\"nodes\":" + quoted(base64OfFloats(page.coordinates));
  out += ",\"groups\":" + groups(page);
  out += ",\"measures\":[\"gamma\",\"sicn\"]";
  out += ",\"families\":" + families();
  out += ",\"blocks\":[";
  for (std::size_t i = 0; i < page.blocks.size(); ++i)
    out += (i ? "," : "") + block(page.blocks[i]);
  out += "],\"counts\":[";
  for (std::size_t i = 0; i < page.counts.size(); ++i)
    out += (i ? ",[" : "[") + quoted(page.counts[i].first) + "," +
           std::to_string(page.counts[i].second) + "]";
  return out + "]}";
}

}  // namespace geomesh
