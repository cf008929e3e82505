// ViewScanner: words, lines, numbers and binary values of view files, with located errors.
#include "io/view_scanner.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace geomesh {

namespace {

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

}  // namespace

template <class T>
bool parseWhole(std::string_view text, T& value) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') ++first;  // from_chars refuses '+'
  if (first == last) return false;
  const auto [end, error] = std::from_chars(first, last, value);
  if (error != std::errc() || end != last) return false;
  if constexpr (std::is_floating_point_v<T>) return std::isfinite(value);
  return true;
}

template bool parseWhole<double>(std::string_view, double&);
template bool parseWhole<int>(std::string_view, int&);
template bool parseWhole<long>(std::string_view, long&);
template bool parseWhole<long long>(std::string_view, long long&);
template bool parseWhole<std::uint64_t>(std::string_view, std::uint64_t&);

void ViewScanner::skipSpace() {
  while (pos_ < data_.size() && isSpace(data_[pos_])) ++pos_;
}

bool ViewScanner::atEnd() {
  skipSpace();
  return pos_ == data_.size();
}

std::string_view ViewScanner::word() {
  skipSpace();
  start_ = pos_;
  while (pos_ < data_.size() && !isSpace(data_[pos_])) ++pos_;
  if (pos_ == start_) fail("unexpected end of file");
  return data_.substr(start_, pos_ - start_);
}

std::string_view ViewScanner::peekWord() {
  const std::size_t keep = pos_;
  skipSpace();
  std::size_t end = pos_;
  while (end < data_.size() && !isSpace(data_[end])) ++end;
  const std::string_view w = data_.substr(pos_, end - pos_);
  pos_ = keep;
  return w;
}

std::string_view ViewScanner::line() {
  start_ = pos_;
  if (pos_ >= data_.size()) fail("unexpected end of file");
  const std::size_t end = std::min(data_.find('\n', pos_), data_.size());
  std::string_view out = data_.substr(pos_, end - pos_);
  pos_ = end < data_.size() ? end + 1 : end;
  while (!out.empty() && isSpace(out.back())) out.remove_suffix(1);
  return out;
}

double ViewScanner::realPrefix(std::size_t maxLength) {
  skipSpace();
  start_ = pos_;
  std::size_t end = pos_;
  while (end < data_.size() && !isSpace(data_[end])) ++end;
  const std::string_view w = data_.substr(pos_, std::min(end - pos_, maxLength));
  const char* first = w.data() + (w.size() > 1 && w[0] == '+' && w[1] != '-' ? 1 : 0);
  double v = 0;
  const auto [stop, error] = std::from_chars(first, w.data() + w.size(), v);
  if (error != std::errc() || !std::isfinite(v))
    fail("expected a number, found '" + std::string(w.substr(0, 40)) + "'");
  pos_ += static_cast<std::size_t>(stop - w.data());
  return v;
}

std::string_view ViewScanner::bytes(std::size_t count) {
  start_ = pos_;
  if (remaining() < count) fail("unexpected end of data");
  pos_ += count;
  return data_.substr(start_, count);
}

double ViewScanner::rawReal(std::endian order, int size) {
  const double v = size == 4 ? double(raw<float>(order)) : raw<double>(order);
  if (!std::isfinite(v)) fail("non-finite number");
  return v;
}

void ViewScanner::fail(const std::string& message) const {
  failAt(start_, message);
}

void ViewScanner::failAt(std::size_t offset, const std::string& message) const {
  offset = std::min(offset, data_.size());
  if (binary_) throw ViewReadError(path_ + ": byte " + std::to_string(offset) + ": " + message);
  const std::string_view before = data_.substr(0, offset);
  const std::size_t line = 1 + std::size_t(std::count(before.begin(), before.end(), '\n'));
  const std::size_t lineStart = before.rfind('\n');
  const std::size_t col = offset - (lineStart == std::string_view::npos ? 0 : lineStart + 1) + 1;
  throw ViewReadError(path_ + ":" + std::to_string(line) + ":" + std::to_string(col) + ": " +
                      message);
}

}  // namespace geomesh
