// Reading Nastran bulk data: GRID and element cards in free fields (commas), small fixed fields
// (8 columns) or large fixed fields (16 columns, a '*' after the card name), continued on lines
// starting with '+' or '*' or with a blank first field. Other cards are skipped. Elements go to
// one discrete entity per dimension and property id, each id above 0 a physical group too.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <istream>
#include <iterator>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "io/bdf_elements.h"
#include "io/discrete_mesh.h"
#include "io/formats.h"
#include "io/mesh_scanner.h"

namespace geomesh {

namespace {

struct BdfCard {
  int line = 0;
  std::vector<std::string> fields;  // field 1 (the card's name, without '*') first; trimmed
};

std::string trimmed(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return "";
  const std::size_t last = text.find_last_not_of(" \t");
  return std::string(text.substr(first, last - first + 1));
}

bool isCommentOrBlank(std::string_view line) {
  return line.empty() || line.front() == '$' || trimmed(line).empty();
}

// The data fields of a line: after field 1, up to field 10 (a continuation mark, dropped).
void appendFields(std::string_view line, bool large, std::vector<std::string>& fields) {
  if (line.find(',') != std::string_view::npos) {
    std::size_t start = line.find(',') + 1;
    std::vector<std::string> free;
    for (std::size_t end; (end = line.find(',', start)) != std::string_view::npos; start = end + 1)
      free.push_back(trimmed(line.substr(start, end - start)));
    free.push_back(trimmed(line.substr(start)));
    const bool marked =
        free.size() == 9 && (free[8].empty() || free[8][0] == '+' || free[8][0] == '*');
    if (marked) free.pop_back();  // field 10
    fields.insert(fields.end(), free.begin(), free.end());
    return;
  }
  const std::size_t width = large ? 16 : 8;
  for (std::size_t start = 8; start < std::min<std::size_t>(line.size(), 72); start += width)
    fields.push_back(trimmed(line.substr(start, width)));
}

bool continues(std::string_view line) {
  if (line.empty()) return false;
  if (line.front() == '+' || line.front() == '*' || line.front() == ',') return true;
  return line.size() > 8 && trimmed(line.substr(0, 8)).empty();
}

// The cards of the bulk data: after BEGIN BULK when there is one, up to ENDDATA.
std::vector<BdfCard> readCards(const std::string& data, const std::string& name) {
  const bool hasBulkMarker = data.find("BEGIN BULK") != std::string::npos;
  MeshScanner in(data, name);
  bool inBulk = !hasBulkMarker;
  std::vector<BdfCard> cards;
  while (in.hasLine()) {
    const std::string_view line = in.line();
    if (!inBulk) {
      inBulk = trimmed(line).starts_with("BEGIN BULK");
      continue;
    }
    if (isCommentOrBlank(line)) continue;
    if (continues(line) && !cards.empty()) {
      appendFields(line, line.front() == '*', cards.back().fields);
      continue;
    }
    std::string card = trimmed(line.substr(0, std::min(line.find(','), std::size_t{8})));
    std::transform(card.begin(), card.end(), card.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    if (card == "ENDDATA") break;
    const bool large = card.ends_with('*');
    if (large) card.pop_back();
    cards.push_back({in.lineNumber(), {card}});
    appendFields(line, large, cards.back().fields);
  }
  return cards;
}

// `text` as a number of type T; nullopt when malformed. Nastran reals may leave out the 'E' of
// the exponent ("1.5-3") or write it 'D'.
template <class T>
std::optional<T> bdfNumber(std::string text) {
  if constexpr (std::is_floating_point_v<T>) {
    std::replace(text.begin(), text.end(), 'D', 'E');
    std::replace(text.begin(), text.end(), 'd', 'E');
    const std::size_t sign = text.find_first_of("+-", 1);
    if (sign != std::string::npos && text.find_first_of("Ee") == std::string::npos)
      text.insert(sign, "E");
  }
  const char* first = text.data() + (text.starts_with('+') ? 1 : 0);
  const char* last = text.data() + text.size();
  T v{};
  const auto [end, error] = std::from_chars(first, last, v);
  if (error != std::errc() || end != last || first == last) return std::nullopt;
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(v)) return std::nullopt;
  return v;
}

class BdfMeshBuilder {
 public:
  BdfMeshBuilder(std::string name, Mesh& mesh) : name_(std::move(name)), mesh_(mesh) {}

  void card(const BdfCard& c) {
    line_ = c.line;
    if (c.fields[0] == "GRID") return grid(c.fields);
    const std::size_t nodeFields = bdfNodeFields(c.fields[0]);
    if (nodeFields > 0) element(c.fields, nodeFields);
  }

  std::vector<PhysicalGroup> finish() {
    for (const PendingElement& e : pending_) {
      line_ = e.line;
      ElementBlock& block = mesh_.entity({dimension(e.type), e.property}).block(e.type);
      for (long long id : e.grids) block.nodes.push_back(node(id));
    }
    std::vector<PhysicalGroup> groups;
    for (const EntityId& id : entities_)
      if (id.tag > 0) groups.push_back({id.dim, id.tag, "", {id.tag}});
    return groups;
  }

 private:
  struct PendingElement {
    int line;
    ElementType type;
    int property;
    std::vector<long long> grids;  // in MSH order
  };

  [[noreturn]] void fail(const std::string& message) const {
    throw MeshReadError(name_ + ":" + std::to_string(line_) + ": " + message);
  }

  long long integer(const std::vector<std::string>& fields, std::size_t i, const char* what) {
    if (i >= fields.size() || fields[i].empty()) fail(std::string("missing ") + what);
    const std::optional<long long> v = bdfNumber<long long>(fields[i]);
    if (!v) fail(std::string("expected ") + what + ", found '" + fields[i] + "'");
    return *v;
  }

  double real(const std::vector<std::string>& fields, std::size_t i) const {
    if (i >= fields.size() || fields[i].empty()) return 0;  // blank: 0.0
    const std::optional<double> v = bdfNumber<double>(fields[i]);
    if (!v) fail("expected a real, found '" + fields[i] + "'");
    return *v;
  }

  void grid(const std::vector<std::string>& fields) {
    const long long id = integer(fields, 1, "grid point id");
    if (fields.size() > 2 && !fields[2].empty() && fields[2] != "0")
      fail("grid point " + std::to_string(id) + " is given in coordinate system " + fields[2] +
           ": coordinate systems are not supported");
    const Vec3 p{real(fields, 3), real(fields, 4), real(fields, 5)};
    if (!nodes_.emplace(id, static_cast<NodeIndex>(mesh_.nodeCount())).second)
      fail("grid point " + std::to_string(id) + " is defined twice");
    mesh_.addNode(p);
  }

  void element(const std::vector<std::string>& fields, std::size_t nodeFields) {
    integer(fields, 1, "element id");
    const long long property = integer(fields, 2, "property id");
    if (property < 0 || property > std::numeric_limits<int>::max())
      fail("invalid property id " + std::to_string(property));
    std::vector<long long> grids;
    for (std::size_t i = 3; i < std::min(fields.size(), 3 + nodeFields); ++i)
      if (!fields[i].empty()) grids.push_back(integer(fields, i, "grid point id"));
    const BdfElement* bdf = bdfElementForReading(fields[0], grids.size());
    if (!bdf)
      fail(fields[0] + " with " + std::to_string(grids.size()) + " grid points is not supported");
    PendingElement e{line_, bdf->type, static_cast<int>(property), {}};
    e.grids.resize(grids.size());
    for (std::size_t k = 0; k < grids.size(); ++k) e.grids[bdf->fromMsh[k]] = grids[k];
    entities_.insert({dimension(bdf->type), e.property});
    pending_.push_back(std::move(e));
  }

  NodeIndex node(long long id) const {
    const auto it = nodes_.find(id);
    if (it == nodes_.end()) fail("grid point " + std::to_string(id) + " is not defined");
    return it->second;
  }

  std::string name_;
  Mesh& mesh_;
  int line_ = 0;
  std::unordered_map<long long, NodeIndex> nodes_;
  std::vector<PendingElement> pending_;  // elements may come before their grid points
  std::set<EntityId> entities_;
};

}  // namespace

// Named by the bdf row of io/formats.cpp.
void readBdf(std::istream& in, Model& model, Mesh& mesh, const std::string& name) {
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  readReplacing(model, mesh, [&] {
    const std::vector<BdfCard> cards = readCards(data, name);
    if (cards.empty()) throw MeshReadError(name + ":1: no bulk data cards");
    BdfMeshBuilder builder(name, mesh);
    for (const BdfCard& card : cards) builder.card(card);
    addDiscreteEntities(model, mesh, builder.finish());
  });
}

}  // namespace geomesh
