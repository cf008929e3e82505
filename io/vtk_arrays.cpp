// VtkArrayReader: typed values and attribute sections of legacy VTK files.
#include "io/vtk_arrays.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

namespace geomesh {

namespace {

// The keywords that start an array of an attribute section.
bool isAttributeKeyword(std::string_view word) {
  static constexpr std::string_view kWords[] = {
      "SCALARS",  "COLOR_SCALARS", "LOOKUP_TABLE", "VECTORS",      "NORMALS",
      "TENSORS",  "TENSORS6",      "FIELD",        "GLOBAL_IDS",   "PEDIGREE_IDS",
      "METADATA", "TEXTURE_COORDINATES"};
  return std::find(std::begin(kWords), std::end(kWords), word) != std::end(kWords);
}

}  // namespace

NumberType VtkArrayReader::typeNamed(std::string_view name) {
  const std::string type = lowercase(name);
  if (type == "float" || type == "vtktypefloat32") return {4, 'f'};
  if (type == "double" || type == "vtktypefloat64") return {8, 'f'};
  if (type == "char" || type == "signed_char" || type == "vtktypeint8") return {1, 'i'};
  if (type == "unsigned_char" || type == "vtktypeuint8") return {1, 'u'};
  if (type == "short" || type == "vtktypeint16") return {2, 'i'};
  if (type == "unsigned_short" || type == "vtktypeuint16") return {2, 'u'};
  if (type == "int" || type == "vtkidtype" || type == "vtktypeint32") return {4, 'i'};
  if (type == "unsigned_int" || type == "vtktypeuint32") return {4, 'u'};
  if (type == "long" || type == "vtktypeint64") return {8, 'i'};
  if (type == "unsigned_long" || type == "vtktypeuint64") return {8, 'u'};
  in_.fail("unsupported data type '" + std::string(name.substr(0, 40)) + "'");
}

bool VtkArrayReader::nextIs(std::string_view word) {
  return binary_ ? in_.startsWith(word) : in_.peekWord() == word;
}

bool VtkArrayReader::isIntegral(std::string_view type) {
  const std::string t = lowercase(type);
  return t != "float" && t != "double" && t != "vtktypefloat32" && t != "vtktypefloat64";
}

std::uint64_t VtkArrayReader::count(std::string_view what, std::size_t bytesEach) {
  const auto n = in_.number<std::uint64_t>(what);
  // An ASCII value takes at least two characters: a digit and a separator.
  const std::size_t each = binary_ ? std::max<std::size_t>(bytesEach, 1) : 2;
  if (n > (in_.remaining() + 1) / each)
    in_.fail(std::string(what) + " " + std::to_string(n) + " exceeds the size of the file");
  return n;
}

template <class Out>
void VtkArrayReader::readValues(std::string_view typeName, std::uint64_t count,
                                std::vector<Out>& out) {
  const NumberType type = typeNamed(typeName);
  constexpr bool wantsIntegers = std::is_integral_v<Out>;
  if (wantsIntegers && type.kind == 'f')
    in_.fail("expected an integer type, found '" + std::string(typeName.substr(0, 40)) + "'");
  const std::size_t each = binary_ ? type.bytes : 2;
  if (count > (in_.remaining() + 1) / each)
    in_.fail(std::to_string(count) + " values exceed the size of the file");
  out.reserve(out.size() + count);
  for (std::uint64_t i = 0; i < count; ++i) {
    if (binary_) {
      out.push_back(static_cast<Out>(in_.rawNumber(type, std::endian::big)));
    } else if (type.kind == 'f') {
      out.push_back(static_cast<Out>(in_.real()));
    } else {
      out.push_back(static_cast<Out>(in_.number<std::int64_t>("an integer")));
    }
  }
}

void VtkArrayReader::read(std::string_view type, std::uint64_t count, std::vector<double>& out) {
  readValues(type, count, out);
}

void VtkArrayReader::read(std::string_view type, std::uint64_t count,
                          std::vector<std::int64_t>& out) {
  readValues(type, count, out);
}

void VtkArrayReader::skip(std::string_view typeName, std::uint64_t count) {
  const NumberType type = typeNamed(typeName);
  if (binary_) {
    if (count > in_.remaining() / type.bytes)
      in_.fail(std::to_string(count) + " values exceed the size of the file");
    in_.skip(count * type.bytes);
    return;
  }
  for (std::uint64_t i = 0; i < count; ++i) in_.word();
}

void VtkArrayReader::readOrSkip(std::string name, std::string_view type, std::uint64_t count,
                                std::uint64_t components, std::vector<VtkCellArray>* kept) {
  if (components != 1 || !kept) return skip(type, count);
  VtkCellArray array{std::move(name), isIntegral(type), {}, in_.lineNumber()};
  read(type, count, array.values);
  kept->push_back(std::move(array));
}

// Binary files always name the table; ASCII ones may leave it out.
void VtkArrayReader::skipLookupTableLine() {
  if (!binary_ && in_.peekWord() != "LOOKUP_TABLE") return;
  if (in_.word() != "LOOKUP_TABLE") in_.fail("expected LOOKUP_TABLE after SCALARS");
  in_.word();
  in_.line();
}

void VtkArrayReader::skipMetadata() {
  in_.line();
  while (in_.hasLine() && !in_.line().empty()) {
  }
}

void VtkArrayReader::readField(std::vector<VtkCellArray>* kept, std::uint64_t n) {
  in_.word();  // the field's name
  const std::uint64_t arrays = count("array count", 8);
  in_.line();
  for (std::uint64_t a = 0; a < arrays; ++a) {
    std::string name(in_.word());
    const auto components = in_.number<std::uint64_t>("a component count");
    const auto tuples = in_.number<std::uint64_t>("a tuple count");
    const std::string type(in_.word());
    in_.line();
    if (components > 0 && tuples > std::numeric_limits<std::uint64_t>::max() / components)
      in_.fail("array '" + name.substr(0, 40) + "' is too large");
    readOrSkip(std::move(name), type, components * tuples, tuples == n ? components : 0,
               kept);
    if (!in_.atEnd() && in_.peekWord() == "METADATA") {
      in_.word();
      skipMetadata();
    }
  }
}

// "SCALARS name type [components]", whose keyword has been read, and its values.
void VtkArrayReader::readScalars(std::uint64_t n, std::vector<VtkCellArray>* kept) {
  std::string name(in_.word());
  const std::string type(in_.word());
  std::uint64_t components = 1;
  if (const auto rest = wordsOf(in_.line()); !rest.empty())
    components = parseNumber<std::uint64_t>(in_, rest[0], "a component count");
  if (components < 1 || components > 4) in_.fail("SCALARS of 1 to 4 components expected");
  skipLookupTableLine();
  readOrSkip(std::move(name), type, n * components, components, kept);
}

// An array not used, whose keyword has been read.
void VtkArrayReader::skipAttribute(const std::string& keyword, std::uint64_t n) {
  in_.word();  // its name
  if (keyword == "COLOR_SCALARS" || keyword == "LOOKUP_TABLE") {
    const std::uint64_t m = count("a size", 1);
    in_.line();
    // Colours are bytes in binary files, numbers from 0 to 1 in ASCII ones.
    skip(binary_ ? "unsigned_char" : "float", keyword == "LOOKUP_TABLE" ? 4 * m : n * m);
    return;
  }
  std::uint64_t each = 1;
  if (keyword == "TEXTURE_COORDINATES") each = count("a dimension", 1);
  if (keyword == "VECTORS" || keyword == "NORMALS") each = 3;
  if (keyword == "TENSORS6") each = 6;
  if (keyword == "TENSORS") each = 9;
  const std::string type(in_.word());
  in_.line();
  skip(type, n * each);
}

void VtkArrayReader::readAttributes(std::uint64_t n, std::vector<VtkCellArray>* kept) {
  while (!in_.atEnd() && isAttributeKeyword(in_.peekWord())) {
    const std::string keyword(in_.word());
    if (keyword == "METADATA")
      skipMetadata();
    else if (keyword == "FIELD")
      readField(kept, n);
    else if (keyword == "SCALARS")
      readScalars(n, kept);
    else
      skipAttribute(keyword, n);
  }
}

}  // namespace geomesh
