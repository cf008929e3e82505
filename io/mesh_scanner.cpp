// MeshScanner: words, lines and skips over a file held in memory, with line-numbered errors.
#include "io/mesh_scanner.h"

#include <algorithm>
#include <cmath>

namespace geomesh {

namespace {
bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}
}  // namespace

std::vector<std::string_view> wordsOf(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t at = 0;
  while (at < line.size()) {
    while (at < line.size() && isSpace(line[at])) ++at;
    std::size_t end = at;
    while (end < line.size() && !isSpace(line[end])) ++end;
    if (end > at) words.push_back(line.substr(at, end - at));
    at = end;
  }
  return words;
}

std::string lowercase(std::string_view text) {
  std::string out(text);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

void MeshScanner::fail(const std::string& message, int line) const {
  throw MeshReadError(name_ + ":" + std::to_string(line > 0 ? line : line_) + ": " + message);
}

void MeshScanner::endLine() {
  if (!lineBreakPending_) return;
  lineBreakPending_ = false;
  if (pos_ < data_.size() && data_[pos_] == '\n') {
    ++pos_;
    ++line_;
  }
}

void MeshScanner::skipSpace() {
  lineBreakPending_ = false;
  while (pos_ < data_.size() && isSpace(data_[pos_])) {
    if (data_[pos_] == '\n') ++line_;
    ++pos_;
  }
}

bool MeshScanner::atEnd() {
  skipSpace();
  return pos_ == data_.size();
}

std::string_view MeshScanner::word() {
  skipSpace();
  const std::size_t start = pos_;
  while (pos_ < data_.size() && !isSpace(data_[pos_])) ++pos_;
  if (pos_ == start) fail("unexpected end of file");
  return data_.substr(start, pos_ - start);
}

std::string_view MeshScanner::peekWord() {
  skipSpace();
  std::size_t end = pos_;
  while (end < data_.size() && !isSpace(data_[end])) ++end;
  return data_.substr(pos_, end - pos_);
}

std::string_view MeshScanner::line() {
  endLine();
  if (pos_ >= data_.size()) fail("unexpected end of file");
  const std::size_t end = std::min(data_.find('\n', pos_), data_.size());
  std::string_view out = data_.substr(pos_, end - pos_);
  pos_ = end;
  lineBreakPending_ = true;
  while (!out.empty() && isSpace(out.back())) out.remove_suffix(1);
  return out;
}

double MeshScanner::rawNumber(NumberType type, std::endian order) {
  double v = 0;
  switch (type.kind == 'f' ? type.bytes : type.kind == 'u' ? type.bytes + 100 : type.bytes + 200) {
    case 4: v = raw<float>(order); break;
    case 8: v = raw<double>(order); break;
    case 101: return raw<std::uint8_t>(order);
    case 102: return raw<std::uint16_t>(order);
    case 104: return raw<std::uint32_t>(order);
    case 108: return static_cast<double>(raw<std::uint64_t>(order));
    case 201: return raw<std::int8_t>(order);
    case 202: return raw<std::int16_t>(order);
    case 204: return raw<std::int32_t>(order);
    case 208: return static_cast<double>(raw<std::int64_t>(order));
    default: fail("unsupported binary number of " + std::to_string(type.bytes) + " bytes");
  }
  if (!std::isfinite(v)) fail("non-finite number in binary data");
  return v;
}

bool MeshScanner::hasLine() {
  endLine();
  return pos_ < data_.size();
}

bool MeshScanner::startsWith(std::string_view text) {
  endLine();
  return data_.substr(pos_).starts_with(text);
}

void MeshScanner::skip(std::size_t bytes) {
  endLine();
  if (remaining() < bytes) fail("unexpected end of binary data");
  pos_ += bytes;
}

}  // namespace geomesh
