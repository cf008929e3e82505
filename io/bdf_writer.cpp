// Nastran bulk data (.bdf): GRID* cards in large fixed fields (16 columns, for the precision of
// the coordinates), element cards in small fixed fields (8 columns) continued on lines of their
// own; each element's property id is its physical tag (or its entity's tag).
#include <algorithm>
#include <cstdio>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/bdf_elements.h"
#include "io/formats.h"
#include "io/msh_content.h"
#include "io/physical_sets.h"

namespace geomesh {

namespace {

// Small fields hold integers of at most 8 digits.
constexpr long long kLargestId = 99999999;

// A real in at most 16 columns, with the decimal point and exponent Nastran reads, as precise
// as fits.
std::string largeFieldReal(double v) {
  if (v == 0) return "0.0";
  char text[32];
  for (int digits = 10; digits > 0; --digits)
    if (std::snprintf(text, sizeof text, "%.*E", digits, v) <= 16) break;
  return text;
}

// Field 10 of a card that goes on, and field 1 of the line that continues it: the same
// identifier, numbered through the file in base 36.
std::string continuationMark(char lead, unsigned long long count) {
  std::string digits;
  do {
    digits.insert(digits.begin(), "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ"[count % 36]);
    count /= 36;
  } while (count > 0);
  return lead + digits;
}

class BdfCardWriter {
 public:
  explicit BdfCardWriter(std::ostream& out) : out_(out) {}

  void grid(std::uint64_t id, Vec3 p) {
    const std::string mark = continuationMark('*', ++continuations_);
    out_ << field("GRID*", 8) << field(std::to_string(id), 16) << field("", 16)
         << field(largeFieldReal(p.x), 16, true) << field(largeFieldReal(p.y), 16, true) << mark
         << '\n'
         << field(mark, 8) << field(largeFieldReal(p.z), 16, true) << '\n';
  }

  // Fields 2 to 9 of each line hold the values: the element id, the property id, the grid
  // points, eight to a continuation line.
  void element(std::string_view card, const std::vector<long long>& values) {
    out_ << field(std::string(card), 8);
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (i > 0 && i % 8 == 0) {
        const std::string mark = continuationMark('+', ++continuations_);
        out_ << mark << '\n' << field(mark, 8);
      }
      out_ << field(std::to_string(values[i]), 8);
    }
    out_ << '\n';
  }

 private:
  static std::string field(const std::string& text, std::size_t width, bool right = false) {
    const std::string pad(width - std::min(width, text.size()), ' ');
    return right ? pad + text : text + pad;
  }

  std::ostream& out_;
  unsigned long long continuations_ = 0;
};

// Every id must fit a small field, and property ids must be positive.
void checkIds(const Model& model, const MshContent& content) {
  std::size_t elements = 0;
  for (const MshElementBlock& b : content.elementBlocks) {
    if (b.block->type == ElementType::Point1) continue;
    bdfElementForWriting(b.block->type);
    elements += b.block->size();
    const int property = physicalOrEntityTag(model, b.entity);
    if (property <= 0 || property > kLargestId)
      throw std::invalid_argument("Nastran property ids are between 1 and 99999999, not " +
                                  std::to_string(property));
  }
  if (content.nodeCount > kLargestId || elements > kLargestId)
    throw std::invalid_argument(
        "Nastran small fields hold at most 99999999 grid points and "
        "elements");
}

}  // namespace

// Named by the bdf row of io/formats.cpp. Saves what an MSH file would, except point elements
// (their grid points are saved).
void writeBdf(std::ostream& out, const Model& model, const Mesh& mesh,
              const MeshWriteOptions& options) {
  const MshContent content = selectMshContent(model, mesh, options.saveAll);
  checkIds(model, content);
  out << "$ geomesh mesh\nBEGIN BULK\n";
  BdfCardWriter cards(out);
  for (const MshNodeBlock& block : content.nodeBlocks)
    for (NodeIndex n : block.nodes) cards.grid(content.nodeTag[n], mesh.node(n));
  long long id = 0;
  std::vector<long long> values;
  for (const MshElementBlock& b : content.elementBlocks) {
    if (b.block->type == ElementType::Point1) continue;
    const BdfElement& bdf = bdfElementForWriting(b.block->type);
    const int property = physicalOrEntityTag(model, b.entity);
    for (std::size_t i = 0; i < b.block->size(); ++i) {
      const auto nodes = b.block->element(i);
      values.assign({++id, property});
      for (int k : bdf.fromMsh) values.push_back(static_cast<long long>(content.nodeTag[nodes[k]]));
      cards.element(bdf.card, values);
    }
  }
  out << "ENDDATA\n";
}

}  // namespace geomesh
