// MshEncoder: writes each MSH section once for both encodings, text and binary.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>

namespace geomesh {

// Writes the values of an MSH file either as text (separated by spaces, lines ended
// explicitly) or as raw little-endian binary (where line ends vanish), so that each section is
// written once for both encodings. Output is buffered.
class MshEncoder {
 public:
  MshEncoder(std::ostream& out, bool binary) : out_(out), binary_(binary) {}
  ~MshEncoder() { flush(); }
  MshEncoder(const MshEncoder&) = delete;
  MshEncoder& operator=(const MshEncoder&) = delete;

  bool binary() const { return binary_; }
  void size(std::uint64_t v);  // size_t in binary
  void integer(int v);         // int in binary
  void real(double v);         // double in binary; "%.16g" as text
  // Ends a line of values (text only); Gmsh ends some lines with a space.
  void endLine(bool trailingSpace = false);
  // Text written as is in both encodings (section markers, counts in MSH 2.2 headers).
  void text(std::string_view s);
  void flush();

 private:
  void separate();
  template <class T>
  void raw(T v);

  std::ostream& out_;
  bool binary_;
  bool lineStart_ = true;
  std::string buffer_;
};

}  // namespace geomesh
