// Output streams that write to Python's sys.stdout or sys.stderr, so that what a session
// prints appears where Python's own output goes: a terminal, a notebook, pytest's capture.
#pragma once

#include <mutex>
#include <ostream>
#include <streambuf>
#include <string>

namespace geomesh::python {

// Collects characters and hands them to sys.<name>.write at each newline and on flush. It
// takes the GIL to write, so any thread may use it, with the GIL or without (a run releases
// the GIL while it meshes). sys.<name> is looked up at each write: a stream that Python
// replaces (contextlib.redirect_stdout, capture) receives what follows.
class PythonStreamBuf final : public std::streambuf {
 public:
  explicit PythonStreamBuf(const char* name) : name_(name) {}

 protected:
  int_type overflow(int_type c) override;
  std::streamsize xsputn(const char* text, std::streamsize count) override;
  int sync() override;

 private:
  // Appends text; returns the complete lines to write, taken out of what is pending.
  std::string append(const char* text, std::size_t count);
  void write(const std::string& text) const;

  const char* name_;
  std::mutex mutex_;
  std::string pending_;
};

// An std::ostream over a PythonStreamBuf: PythonStream("stdout") or PythonStream("stderr").
class PythonStream final : public std::ostream {
 public:
  explicit PythonStream(const char* name) : std::ostream(nullptr), buffer_(name) {
    rdbuf(&buffer_);
  }

 private:
  PythonStreamBuf buffer_;
};

}  // namespace geomesh::python
