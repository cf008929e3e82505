// The list-based .pos format (Gmsh's legacy $PostFormat 1.3/1.4 ... $View ... $EndView),
// ASCII and binary, read into views' element lists and text items.
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>

#include "io/view_file_parts.h"
#include "io/view_scanner.h"

namespace geomesh {

using post::ElementShape;
using post::FieldKind;

namespace {

// One list of the header's counts: shape, kind and order, in the order the file gives them.
struct ListSlot {
  ElementShape shape;
  FieldKind kind;
  int order;
};

// The 24 first-order lists (P L T Q S H I Y, each S V T), then for version 1.4 the 21
// second-order ones (L T Q S H I Y).
std::vector<ListSlot> listSlots(bool secondOrder) {
  std::vector<ListSlot> slots;
  for (int order = 1; order <= (secondOrder ? 2 : 1); ++order)
    for (int s = order == 1 ? 0 : 1; s < post::kShapeCount; ++s)
      for (FieldKind kind : {FieldKind::Scalar, FieldKind::Vector, FieldKind::Tensor})
        slots.push_back({static_cast<ElementShape>(s), kind, order});
  return slots;
}

struct PostFormat {
  bool binary = false;
  int realSize = 8;
  bool secondOrder = true;  // version 1.4
};

// Reads numbers as text words or binary reals, as the file is.
struct NumberReader {
  ViewScanner& in;
  const PostFormat& format;
  std::endian order = std::endian::little;

  double next() { return format.binary ? in.rawReal(order, format.realSize) : in.real(); }
};

PostFormat readPostFormat(ViewScanner& in) {
  in.skipSpace();
  in.line();  // "$PostFormat", possibly followed by a comment
  PostFormat f;
  const std::size_t versionAt = (in.skipSpace(), in.offset());
  const double version = in.real();
  const int fileType = in.number<int>("a file type");
  f.realSize = in.number<int>("a data size");
  if (version != 1.4 && version != 1.3)
    in.failAt(versionAt, "unsupported list-based .pos version (1.3 and 1.4 are supported)");
  if (fileType != 0 && fileType != 1) in.fail("invalid file type (0: ASCII, 1: binary)");
  if (f.realSize != 8 && f.realSize != 4) in.fail("unsupported data size (4 or 8)");
  f.binary = fileType == 1;
  f.secondOrder = version == 1.4;
  in.line();
  if (in.word() != "$EndPostFormat") in.fail("expected $EndPostFormat");
  return f;
}

// A count from the view header, bounded by what the rest of the file can hold.
std::size_t readCount(ViewScanner& in, std::size_t minBytesEach) {
  const auto n = in.number<std::uint64_t>("a count");
  if (minBytesEach > 0 && n > in.remaining() / minBytesEach)
    in.fail("count " + std::to_string(n) + " exceeds the size of the file");
  return static_cast<std::size_t>(n);
}

// The byte order of binary data, from the integer 1 written before it.
std::endian readCheckWord(ViewScanner& in) {
  const auto one = in.raw<std::int32_t>(std::endian::little);
  if (one == 1) return std::endian::little;
  if (one == 0x01000000) return std::endian::big;
  in.fail("invalid binary check word (expected the integer 1)");
}

void readList(NumberReader& num, post::View& view, const ListSlot& slot, std::size_t count,
              int steps) {
  if (count == 0) return;
  post::ElementList& list = view.list(slot.shape, slot.kind, slot.order);
  const int n = listNodeCount(slot.shape, slot.order);
  list.nodesPerElement = n;
  list.steps = steps;
  const std::size_t valueCount = std::size_t(steps) * std::size_t(n) * list.components();
  std::vector<double> xyz(3 * std::size_t(n));
  for (std::size_t e = 0; e < count; ++e) {
    for (double& c : xyz) c = num.next();  // all x, then all y, then all z
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) list.coordinates.push_back(xyz[std::size_t(c * n + i)]);
    for (std::size_t k = 0; k < valueCount; ++k) list.values.push_back(num.next());
  }
}

// The strings of the text items: item k's start at its index in the block and run to the
// next item's; each ends with a NUL (or a '^' in ASCII files written without NULs).
void splitTexts(ViewScanner& in, std::string_view block, std::vector<post::TextItem>& items,
                const std::vector<double>& indices, std::size_t blockStart) {
  const char end = block.find('\0') == std::string_view::npos ? '^' : '\0';
  for (std::size_t k = 0; k < items.size(); ++k) {
    const double first = indices[k];
    const double last = k + 1 < items.size() ? indices[k + 1] : double(block.size());
    if (first < 0 || first > last || last > double(block.size()) || first != std::floor(first))
      in.failAt(blockStart, "invalid text index " + std::to_string(first));
    std::string_view rest = block.substr(std::size_t(first), std::size_t(last - first));
    while (!rest.empty()) {
      const std::size_t stop = std::min(rest.find(end), rest.size());
      items[k].text.emplace_back(rest.substr(0, stop));
      rest.remove_prefix(std::min(stop + 1, rest.size()));
    }
  }
}

// In ASCII files the characters follow the last index without a separator ("0hello"), so
// that index is read as the longest number whose block of `chars` characters then ends
// with a string terminator.
std::string_view asciiCharsAfterLastIndex(ViewScanner& in, std::size_t chars, double& index) {
  in.skipSpace();
  const std::size_t at = in.offset();
  const std::string_view word = in.peekWord();
  // A number is never longer than a few dozen characters: longer words need not be tried.
  for (std::size_t length = std::min<std::size_t>(word.size(), 64); length > 0; --length) {
    in.seek(at);
    double v = 0;
    try {
      v = in.realPrefix(length);
    } catch (const ViewReadError&) {
      continue;
    }
    for (bool skipBlank : {false, true}) {
      const std::size_t after = in.offset();
      if (skipBlank) in.skipSpace();
      if (in.remaining() >= chars) {
        const std::string_view block = in.data().substr(in.offset(), chars);
        if (chars == 0 || block.back() == '\0' || block.back() == '^') {
          index = v;
          return in.bytes(chars);
        }
      }
      in.seek(after);
    }
  }
  in.failAt(at, "expected a text index followed by " + std::to_string(chars) + " characters");
}

void readTexts(NumberReader& num, post::View& view, int dim, std::size_t count, std::size_t chars) {
  std::vector<post::TextItem> items(count);
  std::vector<double> indices(count);
  for (std::size_t k = 0; k < count; ++k) {
    post::TextItem& t = items[k];
    t.dimension = dim;
    t.x = num.next();
    t.y = num.next();
    if (dim == 3) t.z = num.next();
    t.style = num.next();
    const bool lastAscii = !num.format.binary && k + 1 == count;
    indices[k] = lastAscii ? 0 : num.next();
    if (lastAscii) {
      const std::size_t at = num.in.offset();
      const std::string_view block = asciiCharsAfterLastIndex(num.in, chars, indices[k]);
      splitTexts(num.in, block, items, indices, at);
    }
  }
  if (num.format.binary || count == 0) {
    const std::size_t at = num.in.offset();
    const std::string_view block = num.in.bytes(chars);
    splitTexts(num.in, block, items, indices, at);
  }
  for (post::TextItem& t : items) view.texts.push_back(std::move(t));
}

std::string viewName(std::string_view word) {
  std::string name(word);
  for (char& c : name)
    if (c == '^') c = ' ';
  return name;
}

void readView(ViewScanner& in, const PostFormat& format, post::ViewStore& views) {
  in.skipSpace();
  in.line();  // "$View", possibly followed by a comment
  const std::string name = viewName(in.word());
  const std::size_t stepsAt = (in.skipSpace(), in.offset());
  const auto steps = in.number<int>("a number of time steps");
  if (steps < 1 || std::size_t(steps) > in.remaining())
    in.failAt(stepsAt, "invalid number of time steps " + std::to_string(steps));
  const std::size_t minBytes = format.binary ? std::size_t(format.realSize) : 2;
  const std::vector<ListSlot> slots = listSlots(format.secondOrder);
  std::vector<std::size_t> counts;
  for (std::size_t i = 0; i < slots.size(); ++i) counts.push_back(readCount(in, minBytes));
  std::array<std::size_t, 4> textCounts;
  for (std::size_t& c : textCounts) c = readCount(in, 1);
  if (format.binary) in.line();  // the line break before binary data
  NumberReader num{in, format};
  if (format.binary) {
    in.setBinary(true);
    num.order = readCheckWord(in);
  }
  post::View& view = views.add(name);
  for (int s = 0; s < steps; ++s) view.times.push_back(num.next());
  for (std::size_t i = 0; i < slots.size(); ++i) readList(num, view, slots[i], counts[i], steps);
  readTexts(num, view, 2, textCounts[0], textCounts[1]);
  readTexts(num, view, 3, textCounts[2], textCounts[3]);
  in.setBinary(false);
  if (in.atEnd()) in.failAt(in.offset(), "expected $EndView");
  if (in.word() != "$EndView") in.fail("expected $EndView");
}

}  // namespace

std::string readViewFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw ViewReadError("cannot open '" + path + "'");
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

bool isListBasedPosFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::string word;
  return file >> word && word.starts_with("$PostFormat");
}

int readListBasedPos(const std::string& path, post::ViewStore& views) {
  const std::string data = readViewFile(path);
  ViewScanner in(data, path);
  const std::size_t before = views.size();
  try {
    std::optional<PostFormat> format;
    while (!in.atEnd()) {
      const std::string_view section = in.peekWord();
      if (section.starts_with("$PostFormat"))
        format = readPostFormat(in);
      else if (section.starts_with("$View") && format)
        readView(in, *format, views);
      else {
        in.word();
        in.fail(format ? "expected $View or $PostFormat" : "expected $PostFormat");
      }
    }
  } catch (const ViewReadError&) {
    while (views.size() > before) views.remove(views.size() - 1);  // no half-read view
    throw;
  }
  return static_cast<int>(views.size() - before);
}

}  // namespace geomesh
