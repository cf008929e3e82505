// MshDecoder: checked reads of MSH text tokens and binary values, with line-numbered errors.
#include "io/msh_decoder.h"

#include <charconv>
#include <cmath>
#include <cstring>

#include "io/msh_reader.h"

namespace geomesh {

namespace {
bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}
}  // namespace

void MshDecoder::fail(const std::string& message) const {
  throw MshReadError(name_ + ":" + std::to_string(line_) + ": " + message, line_);
}

void MshDecoder::skipSpace() {
  while (pos_ < data_.size() && isSpace(data_[pos_])) {
    if (data_[pos_] == '\n') ++line_;
    ++pos_;
  }
}

bool MshDecoder::atEnd() {
  skipSpace();
  return pos_ == data_.size();
}

std::string_view MshDecoder::token() {
  skipSpace();
  const std::size_t start = pos_;
  while (pos_ < data_.size() && !isSpace(data_[pos_])) ++pos_;
  if (pos_ == start) fail("unexpected end of file");
  return data_.substr(start, pos_ - start);
}

std::string_view MshDecoder::line() {
  if (pos_ >= data_.size()) fail("unexpected end of file");
  const std::size_t end = std::min(data_.find('\n', pos_), data_.size());
  std::string_view out = data_.substr(pos_, end - pos_);
  pos_ = end < data_.size() ? end + 1 : end;
  ++line_;
  while (!out.empty() && (out.back() == '\r' || out.back() == ' ' || out.back() == '\t'))
    out.remove_suffix(1);
  return out;
}

std::string MshDecoder::quoted() {
  skipSpace();
  if (pos_ >= data_.size() || data_[pos_] != '"') fail("expected a quoted name");
  const std::size_t end = data_.find('"', pos_ + 1);
  const std::size_t lineEnd = data_.find('\n', pos_ + 1);
  if (end == std::string_view::npos || end > lineEnd) fail("unterminated quoted name");
  std::string out(data_.substr(pos_ + 1, end - pos_ - 1));
  pos_ = end + 1;
  return out;
}

void MshDecoder::skipPast(std::string_view marker) {
  while (pos_ < data_.size())
    if (line() == marker) return;
  fail("missing " + std::string(marker));
}

template <class T>
T MshDecoder::raw() {
  if (remaining() < sizeof(T)) fail("unexpected end of binary data");
  T v;
  std::memcpy(&v, data_.data() + pos_, sizeof(T));
  pos_ += sizeof(T);
  return v;
}

template <class T>
T MshDecoder::number(std::string_view what) {
  const std::string_view text = token();
  T v{};
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (error != std::errc() || end != text.data() + text.size())
    fail("expected " + std::string(what) + ", found '" + std::string(text.substr(0, 40)) + "'");
  return v;
}

std::uint64_t MshDecoder::size() {
  return binary_ ? raw<std::uint64_t>() : number<std::uint64_t>("a non-negative integer");
}

int MshDecoder::integer() { return binary_ ? raw<int>() : number<int>("an integer"); }

double MshDecoder::real() {
  const double v = binary_ ? raw<double>() : number<double>("a number");
  if (!std::isfinite(v)) fail("non-finite number");
  return v;
}

}  // namespace geomesh
